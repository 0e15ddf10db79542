#include "voidFractionModel.H"
#include "selectModel.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(voidFractionModel, 0);
    defineRunTimeSelectionTable(voidFractionModel, dictionary);
}
}


Foam::foamDEM::voidFractionModel::voidFractionModel
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    alphaMin_(dict.getOrDefault<scalar>("alphaMin", 0.3)),
    redistributeClipped_(dict.getOrDefault("redistributeClipped", true)),
    maxRedistributionSweeps_
    (
        dict.getOrDefault<label>("maxRedistributionSweeps", 50)
    ),
    nClipped_(0),
    clippedVolume_(0),
    lostVolume_(0)
{
    if (alphaMin_ <= 0 || alphaMin_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "alphaMin must lie in (0, 1), got " << alphaMin_
            << exit(FatalIOError);
    }
    if (maxRedistributionSweeps_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "maxRedistributionSweeps must be >= 0, got "
            << maxRedistributionSweeps_ << exit(FatalIOError);
    }
}


Foam::autoPtr<Foam::foamDEM::voidFractionModel>
Foam::foamDEM::voidFractionModel::New
(
    const dictionary& couplingDict,
    const fvMesh& mesh
)
{
    const word modelType(couplingDict.get<word>("voidFraction"));

    auto cstrIter = selectModel
    (
        couplingDict, "voidFraction", modelType, typeName,
        dictionaryConstructorTablePtr_
    );

    return cstrIter()
    (
        couplingDict.optionalSubDict(modelType + "Coeffs"),
        mesh
    );
}


Foam::wordList Foam::foamDEM::voidFractionModel::patchTypes(const fvMesh& mesh)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    wordList types(patches.size(), zeroGradientFvPatchScalarField::typeName);
    forAll(patches, patchi)
    {
        if (polyPatch::constraintType(patches[patchi].type()))
        {
            types[patchi] = patches[patchi].type();
        }
    }
    return types;
}


void Foam::foamDEM::voidFractionModel::compute
(
    particleData& p,
    volScalarField& alpha
) const
{
    distribute(p, weights_);
    if (!weights_.complete() || weights_.nParticles() != p.size())
    {
        FatalErrorInFunction
            << type() << "::distribute() filled the weights of "
            << weights_.nParticles() << " particles, expected " << p.size()
            << abort(FatalError);
    }

    const scalarField& V = mesh_.V();
    solidFraction_.setSize(mesh_.nCells());
    solidFraction_ = Zero;
    for (label i = 0; i < p.size(); ++i)
    {
        const scalar Vi = p.cell[i] >= 0 ? p.volume(i) : 0;
        for (label k = weights_.start(i); k < weights_.end(i); ++k)
        {
            solidFraction_[weights_.cell(k)] += weights_.weight(k)*Vi;
        }
    }
    solidFraction_ /= V;

    smooth(solidFraction_);

    setFromSolidFraction(solidFraction_, alpha);

    for (label i = 0; i < p.size(); ++i)
    {
        if (weights_.start(i) == weights_.end(i))
        {
            p.voidFraction[i] = 1;
            continue;
        }
        scalar eps = 0;
        for (label k = weights_.start(i); k < weights_.end(i); ++k)
        {
            eps += weights_.weight(k)*alpha[weights_.cell(k)];
        }
        p.voidFraction[i] = eps;
    }
}


void Foam::foamDEM::voidFractionModel::setFromSolidFraction
(
    const scalarField& solidFraction,
    volScalarField& alpha
) const
{
    const scalarField& V = mesh_.V();
    const scalar solidMax = 1 - alphaMin_;

    // Clipped cells and their excess solid volume
    scalarField s(solidFraction);
    DynamicList<label> full;
    nClipped_ = 0;
    clippedVolume_ = 0;
    forAll(s, celli)
    {
        if (s[celli] > solidMax)
        {
            full.append(celli);
            ++nClipped_;
            clippedVolume_ += (s[celli] - solidMax)*V[celli];
        }
    }

    // Pass the excess volume to face neighbours in proportion to their
    // room. What does not fit overfills the neighbours further out (by
    // layer from the clipped cells, so nothing flows back) and moves on in
    // the next sweep: one layer per sweep.
    if (redistributeClipped_ && full.size())
    {
        const labelListList& cellCells = mesh_.cellCells();
        labelList layer(mesh_.nCells(), -1);
        for (const label celli : full)
        {
            layer[celli] = 0;
        }
        boolList queued(mesh_.nCells(), false);
        DynamicList<label> next;
        DynamicList<label> targets;
        for
        (
            label sweep = 0;
            sweep < maxRedistributionSweeps_ && full.size();
            ++sweep
        )
        {
            next.clear();
            for (const label celli : full)
            {
                const labelList& nbrs = cellCells[celli];
                if (s[celli] <= solidMax || nbrs.empty())
                {
                    continue;
                }
                const scalar excess = (s[celli] - solidMax)*V[celli];
                scalar room = 0;
                for (const label n : nbrs)
                {
                    room += max(solidMax - s[n], scalar(0))*V[n];
                }

                s[celli] = solidMax;
                if (room >= excess)
                {
                    for (const label n : nbrs)
                    {
                        const scalar roomn =
                            max(solidMax - s[n], scalar(0))*V[n];
                        s[n] += roomn/room*excess/V[n];
                    }
                    continue;
                }

                // Fill all neighbours, overfill the outer ones
                targets.clear();
                for (const label n : nbrs)
                {
                    s[n] = max(s[n], solidMax);
                    if (layer[n] < 0 || layer[n] > layer[celli])
                    {
                        targets.append(n);
                    }
                }
                if (targets.empty())
                {
                    targets = nbrs;
                }
                const scalar overflow = (excess - room)/targets.size();
                for (const label n : targets)
                {
                    s[n] += overflow/V[n];
                    if (layer[n] < 0)
                    {
                        layer[n] = layer[celli] + 1;
                    }
                    if (!queued[n])
                    {
                        queued[n] = true;
                        next.append(n);
                    }
                }
            }
            for (const label n : next)
            {
                queued[n] = false;
            }
            full.transfer(next);
        }
    }

    // Bound; whatever is still above the bound is lost
    scalarField& a = alpha.primitiveFieldRef();
    lostVolume_ = 0;
    forAll(a, celli)
    {
        a[celli] = 1 - s[celli];
        if (a[celli] < alphaMin_)
        {
            lostVolume_ += (alphaMin_ - a[celli])*V[celli];
            a[celli] = alphaMin_;
        }
        else if (a[celli] > 1)
        {
            // Round-off negative solid fraction (smoothing solver)
            lostVolume_ -= (a[celli] - 1)*V[celli];
            a[celli] = 1;
        }
    }
    alpha.correctBoundaryConditions();

    reduce(nClipped_, sumOp<label>());
    reduce(clippedVolume_, sumOp<scalar>());
    reduce(lostVolume_, sumOp<scalar>());

    if (debug && nClipped_)
    {
        Info<< type() << ": " << nClipped_ << " cell(s) above solid fraction "
            << solidMax << ", excess " << clippedVolume_ << " m^3, lost "
            << lostVolume_ << " m^3" << endl;
    }
}
