#include "centreVoidFraction.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(centreVoidFraction, 0);
    addToRunTimeSelectionTable(voidFractionModel, centreVoidFraction, dictionary);
}
}


Foam::foamDEM::centreVoidFraction::centreVoidFraction
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(dict, mesh)
{}


void Foam::foamDEM::centreVoidFraction::addRequirements
(
    exchangePlan& plan
) const
{
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::centreVoidFraction::compute
(
    particleData& p,
    volScalarField& alpha
) const
{
    scalarField solidVolume(mesh_.nCells(), Zero);
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            solidVolume[p.cell[i]] += p.volume(i);
        }
    }

    setFromSolidVolume(solidVolume, alpha);

    forAll(p.cell, i)
    {
        p.voidFraction[i] = p.cell[i] >= 0 ? alpha[p.cell[i]] : 1.0;
    }
}
