#include "undisturbedVelocity.H"
#include "selfInducedVelocity.H"
#include "mathematicalConstants.H"
#include "interpolationCellPoint.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::foamDEM::undisturbedVelocity::kernels>
Foam::foamDEM::undisturbedVelocity::kernelNames
({
    { kernels::cell, "cell" },
    { kernels::voidFraction, "voidFraction" },
    { kernels::cellPoint, "cellPoint" },
});

const Foam::Enum<Foam::foamDEM::undisturbedVelocity::methods>
Foam::foamDEM::undisturbedVelocity::methodNames
({
    { methods::none, "none" },
    { methods::selfInducedCorrection, "selfInducedCorrection" },
});


// * * * * * * * * * * * * * * * Private functions  * * * * * * * * * * * * //

template<class EnumType>
EnumType Foam::foamDEM::undisturbedVelocity::readChoice
(
    const dictionary& dict,
    const word& key,
    const Enum<EnumType>& names,
    const EnumType deflt
)
{
    if (!dict.found(key, keyType::LITERAL))
    {
        return deflt;
    }
    const word name(dict.get<word>(key, keyType::LITERAL));
    if (!names.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown " << key << " '" << name << "' in "
            << dict.name() << nl << nl
            << "Valid " << key << " types :" << nl << names.sortedToc()
            << exit(FatalIOError);
    }
    return names.get(name);
}


void Foam::foamDEM::undisturbedVelocity::evaluateForces
(
    particleData& p,
    const PtrList<forceModel>& forces
)
{
    p.dragCoeff = 0;
    p.coupledForce = Zero;
    p.uncoupledForce = Zero;
    for (const forceModel& f : forces)
    {
        f.addForce(p);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::foamDEM::undisturbedVelocity::undisturbedVelocity
(
    const dictionary& couplingDict,
    const fvMesh& mesh,
    const voidFractionModel& voidFraction,
    const scalar rho,
    const scalar nu,
    const bool correctPressureGradient
)
:
    mesh_(mesh),
    voidFraction_(voidFraction),
    rho_(rho),
    mu_(rho*nu),
    kernel_
    (
        readChoice(couplingDict, "couplingKernel", kernelNames, kernels::cell)
    ),
    method_
    (
        readChoice
        (
            couplingDict, "undisturbedVelocity", methodNames, methods::none
        )
    ),
    correctPressureGradient_(correctPressureGradient),
    maxRelativeCorrection_(0)
{
    if (interpolates() && corrects())
    {
        FatalIOErrorInFunction(couplingDict)
            << "undisturbedVelocity "
            << methodNames[methods::selfInducedCorrection]
            << " with couplingKernel " << kernelNames[kernels::cellPoint]
            << " in " << couplingDict.name() << nl << nl
            << "Valid undisturbedVelocity types with couplingKernel "
            << kernelNames[kernels::cellPoint] << " :" << nl
            << wordList({methodNames[methods::none]}) << nl
            << "(the correction's mobility is that of the cell and"
            << " voidFraction kernels' read)" << exit(FatalIOError);
    }
    Info<< "    coupling kernel " << kernelNames[kernel_]
        << (spreads() && !voidFraction_.smooths()
          && voidFraction_.subCellVariance(1) == 0
          ? " (the void fraction model puts a particle in one cell: the"
            " same as cell)" : "")
        << ", undisturbed velocity " << methodNames[method_]
        << (corrects() && correctPressureGradient_
          ? " (and the pressure-gradient force)" : "") << endl;
}


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * * //

void Foam::foamDEM::undisturbedVelocity::read
(
    const volVectorField& U,
    const volScalarField& alpha,
    particleData& p
)
{
    if (interpolates())
    {
        // Point values by volPointInterpolation (its weights are cached
        // on the mesh), then the cell's tetrahedra
        const interpolationCellPoint<vector> Ui(U);
        const interpolationCellPoint<scalar> alphai(alpha);
        cellU_.setSize(p.size());
        forAll(p.cell, i)
        {
            const label c = p.cell[i];
            if (c < 0)
            {
                p.fluidVelocity[i] = Zero;
                cellU_[i] = Zero;
                continue;
            }
            cellU_[i] = U[c];
            p.fluidVelocity[i] = Ui.interpolate(p.position[i], c);
            // In [alphaMin, 1]: the tetrahedron search falls back to the
            // nearest one (weights may be negative) for a position the
            // locate's face-plane test put in a warped or snapped cell
            p.voidFraction[i] = min
            (
                max
                (
                    alphai.interpolate(p.position[i], c),
                    voidFraction_.alphaMin()
                ),
                scalar(1)
            );
        }
        return;
    }

    if (!spreads())
    {
        forAll(p.cell, i)
        {
            const label c = p.cell[i];
            p.fluidVelocity[i] = c >= 0 ? U[c] : vector::zero;
        }
        return;
    }

    // The filter of the source, applied to U (its matrix is symmetric, so
    // reading the filtered U at the weights is the source's kernel)
    vectorField Uf(U.primitiveField());
    if (voidFraction_.smooths())
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            scalarField comp(Uf.component(d));
            voidFraction_.smooth(comp);
            Uf.replace(d, comp);
        }
    }
    const particleCellWeights& w = voidFraction_.cellWeights();
    forAll(p.cell, i)
    {
        vector u(Zero);
        if (p.cell[i] >= 0)
        {
            for (label k = w.start(i); k < w.end(i); ++k)
            {
                u += w.weight(k)*Uf[w.cell(k)];
            }
        }
        p.fluidVelocity[i] = u;
    }
}


void Foam::foamDEM::undisturbedVelocity::evaluate
(
    particleData& p,
    const PtrList<forceModel>& forces
)
{
    evaluateForces(p, forces);
    if (!corrects())
    {
        return;
    }

    seen_ = p.fluidVelocity;
    const scalarField& V = mesh_.V();
    const scalar L = spreads() ? voidFraction_.filterLength() : scalar(0);
    const label nIter = 5;
    for (label iter = 0; iter < nIter; ++iter)
    {
        forAll(p.cell, i)
        {
            const label c = p.cell[i];
            if (c < 0)
            {
                continue;
            }
            const vector slipSeen = seen_[i] - p.velocity[i];
            const scalar slip = mag(p.fluidVelocity[i] - p.velocity[i]);
            const scalar h = cbrt(V[c]);
            scalar a2 = sqr(h)/12;
            if (spreads())
            {
                a2 += voidFraction_.subCellVariance(2*p.radius[i]);
            }
            const scalar m = ::foamDEM::correlations::selfInducedMobility
            (
                rho_, mu_, slip, Foam::sqrt(a2), L
            );
            const scalar factor =
                ::foamDEM::correlations::undisturbedSlipFactor
                (
                    m, p.dragCoeff[i]
                );
            p.fluidVelocity[i] = p.velocity[i] + factor*slipSeen;
        }
        evaluateForces(p, forces);
    }

    if (correctPressureGradient_)
    {
        // The particle's own pressure gradient out of its pressure-gradient
        // force: -V_p rho grad p_self = V_p (g*g)(0)/3 F_p was added by the
        // pressureGradient model; the coupled force takes it off (and its
        // reaction off the fluid)
        forAll(p.cell, i)
        {
            const label c = p.cell[i];
            if (c < 0)
            {
                continue;
            }
            const scalar h = cbrt(V[c]);
            scalar a2 = sqr(h)/12;
            if (spreads())
            {
                a2 += voidFraction_.subCellVariance(2*p.radius[i]);
            }
            const scalar g0 =
                ::foamDEM::correlations::kernelCentreValue(Foam::sqrt(a2), L);
            const scalar Vp = constant::mathematical::pi/6*pow3(2*p.radius[i]);
            p.coupledForce[i] -= Vp*g0/3
               *p.dragCoeff[i]*(p.fluidVelocity[i] - p.velocity[i]);
        }
    }

    maxRelativeCorrection_ = 0;
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            const scalar s = mag(seen_[i] - p.velocity[i]);
            if (s > VSMALL)
            {
                maxRelativeCorrection_ = max
                (
                    maxRelativeCorrection_,
                    mag(p.fluidVelocity[i] - seen_[i])/s
                );
            }
        }
    }
}


void Foam::foamDEM::undisturbedVelocity::addCorrectionSource
(
    const particleData& p,
    vectorField& forceOnFluid
) const
{
    if (interpolates())
    {
        forAll(p.cell, i)
        {
            const label c = p.cell[i];
            if (c >= 0)
            {
                forceOnFluid[c] -=
                    p.dragCoeff[i]*(p.fluidVelocity[i] - cellU_[i]);
            }
        }
        return;
    }
    if (!corrects())
    {
        return;
    }
    const particleCellWeights& w = voidFraction_.cellWeights();
    forAll(p.cell, i)
    {
        const label c = p.cell[i];
        if (c < 0)
        {
            continue;
        }
        const vector extra = p.dragCoeff[i]*(p.fluidVelocity[i] - seen_[i]);
        if (spreads())
        {
            for (label k = w.start(i); k < w.end(i); ++k)
            {
                forceOnFluid[w.cell(k)] -= w.weight(k)*extra;
            }
        }
        else
        {
            forceOnFluid[c] -= extra;
        }
    }
}


void Foam::foamDEM::undisturbedVelocity::smooth
(
    scalarField& sumK,
    vectorField& sumKv,
    vectorField& forceOnFluid
) const
{
    if (!spreads() || !voidFraction_.smooths())
    {
        return;
    }
    const scalarField& V = mesh_.V();

    scalarField s(sumK/V);
    voidFraction_.smooth(s);
    sumK = s*V;

    for (vectorField* f : {&sumKv, &forceOnFluid})
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            scalarField comp(f->component(d)/V);
            voidFraction_.smooth(comp);
            f->replace(d, comp*V);
        }
    }
}


Foam::scalar
Foam::foamDEM::undisturbedVelocity::maxRelativeCorrection() const
{
    return returnReduce(maxRelativeCorrection_, maxOp<scalar>());
}
