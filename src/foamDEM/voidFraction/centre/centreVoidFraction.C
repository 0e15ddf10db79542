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


void Foam::foamDEM::centreVoidFraction::distribute
(
    const particleData& p,
    particleCellWeights& w
) const
{
    w.reset(p.size());
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            w.append(p.cell[i], 1);
        }
        w.endParticle();
    }
}
