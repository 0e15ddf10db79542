#include "particleAveraging.H"

const Foam::word Foam::foamDEM::particleAveraging::typeName
(
    "particleAveraging"
);


Foam::foamDEM::particleAveraging::particleAveraging
(
    const fvMesh& mesh,
    scalar relCutoff
)
:
    mesh_(mesh),
    relCutoff_(relCutoff)
{}


void Foam::foamDEM::particleAveraging::addRequirements
(
    exchangePlan& plan
) const
{
    plan.need(quantity::velocity, typeName);
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::particleAveraging::checkWeights
(
    const particleData& p,
    const voidFractionModel& model
) const
{
    const particleCellWeights& w = model.cellWeights();
    if
    (
        w.nParticles() != p.size()
     || model.solidFraction().size() != mesh_.nCells()
    )
    {
        FatalErrorInFunction
            << "The void fraction model's cell weights are for "
            << w.nParticles() << " particles, not " << p.size()
            << ": call voidFractionModel::compute() first"
            << abort(FatalError);
    }
}


Foam::tmp<Foam::vectorField> Foam::foamDEM::particleAveraging::average
(
    const particleData& p,
    const vectorField& q,
    const voidFractionModel& model
) const
{
    checkWeights(p, model);
    const particleCellWeights& w = model.cellWeights();
    const scalarField& V = mesh_.V();

    const scalarField& solid = model.solidFraction();
    const bool smoothing = model.smooths();

    // Smoothing: filter the deviation from the mean q_m of all particles,
    // S(n - q_m s0) = S(n) - q_m S(s0) as S is linear; then a uniform q
    // gives q back to round-off, not to the solver's tolerance
    vector qMean = Zero;
    if (smoothing)
    {
        scalar sumV = 0;
        for (label i = 0; i < p.size(); ++i)
        {
            if (w.start(i) < w.end(i))
            {
                sumV += p.volume(i);
                qMean += p.volume(i)*q[i];
            }
        }
        reduce(sumV, sumOp<scalar>());
        reduce(qMean, sumOp<vector>());
        qMean = sumV > 0 ? qMean/sumV : vector::zero;
    }

    // Numerator per unit volume: sum_i w_ic V_i (q_i - q_m) / V_c
    vectorField sumVq(mesh_.nCells(), Zero);
    for (label i = 0; i < p.size(); ++i)
    {
        const vector Vq = p.volume(i)*(q[i] - qMean);
        for (label k = w.start(i); k < w.end(i); ++k)
        {
            sumVq[w.cell(k)] += w.weight(k)*Vq;
        }
    }
    sumVq /= V;

    scalar cutoff = 0;
    if (smoothing)
    {
        for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
        {
            scalarField qc(sumVq.component(cmpt));
            model.smooth(qc);
            sumVq.replace(cmpt, qc);
        }
        cutoff = relCutoff_*gMax(solid);
    }

    auto tavg = tmp<vectorField>::New(mesh_.nCells(), Zero);
    vectorField& avg = tavg.ref();
    forAll(avg, celli)
    {
        if (solid[celli] > cutoff)
        {
            avg[celli] = qMean + sumVq[celli]/solid[celli];
        }
    }
    return tavg;
}


void Foam::foamDEM::particleAveraging::average
(
    const particleData& p,
    const voidFractionModel& model,
    volVectorField& Us
) const
{
    Us.primitiveFieldRef() = average(p, p.velocity, model);
    Us.correctBoundaryConditions();
}
