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

    // Each connected group of clipped cells (face neighbours) gives its
    // excess to the layers of cells around it, nearest layer first: a
    // layer with room for what is left takes it in proportion to each
    // cell's room; one without is filled and the rest goes on to the next
    // layer, up to maxRedistributionSweeps layers. What is left after that
    // (or when no layer is left) stays in the group's cells and is lost
    // at the bound below. A cell is visited once per group, so the excess
    // never flows back. Groups go in cell order, an earlier one taking the
    // room nearest to it; each walk costs the cells within its layers, so
    // many groups in a region already filled to the bound cost more.
    if (redistributeClipped_ && maxRedistributionSweeps_ > 0 && full.size())
    {
        const labelListList& cellCells = mesh_.cellCells();
        labelList visited(mesh_.nCells(), -1);
        boolList grouped(mesh_.nCells(), false);
        DynamicList<label> group;
        DynamicList<label> front;
        DynamicList<label> next;
        label groupi = 0;
        for (const label seed : full)
        {
            if (grouped[seed])
            {
                continue;
            }

            // The group: clipped cells connected to the seed
            group.clear();
            group.append(seed);
            visited[seed] = groupi;
            grouped[seed] = true;
            for (label k = 0; k < group.size(); ++k)
            {
                for (const label n : cellCells[group[k]])
                {
                    if (!grouped[n] && s[n] > solidMax)
                    {
                        visited[n] = groupi;
                        grouped[n] = true;
                        group.append(n);
                    }
                }
            }
            scalar excess = 0;
            for (const label celli : group)
            {
                excess += (s[celli] - solidMax)*V[celli];
            }

            // Layers around it
            front = group;
            for
            (
                label layer = 0;
                layer < maxRedistributionSweeps_ && excess > 0
             && front.size();
                ++layer
            )
            {
                next.clear();
                scalar room = 0;
                for (const label celli : front)
                {
                    for (const label n : cellCells[celli])
                    {
                        if (visited[n] != groupi)
                        {
                            visited[n] = groupi;
                            next.append(n);
                            room += max(solidMax - s[n], scalar(0))*V[n];
                        }
                    }
                }
                const scalar given = min(room, excess);
                if (given > 0)
                {
                    for (const label n : next)
                    {
                        const scalar roomn =
                            max(solidMax - s[n], scalar(0))*V[n];
                        s[n] += roomn/room*given/V[n];
                    }
                }
                excess -= given;
                front.swap(next);
            }

            // The group keeps at the bound what it gave away; the rest, if
            // any, stays on its cells in proportion to their excess
            scalar groupExcess = 0;
            for (const label celli : group)
            {
                groupExcess += (s[celli] - solidMax)*V[celli];
            }
            const scalar kept = groupExcess > 0 ? excess/groupExcess : 0;
            for (const label celli : group)
            {
                s[celli] = solidMax + kept*(s[celli] - solidMax);
            }
            ++groupi;
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
