#include "archimedesForce.H"
#include "demCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(archimedesForce, 0);
    addToRunTimeSelectionTable(forceModel, archimedesForce, dictionary);
}
}


void Foam::foamDEM::archimedesForce::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::archimedesForce::addForce(particleData& p) const
{
    const vector rhoG = coupling_.rhoFluid()*coupling_.gravity();
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            p.uncoupledForce[i] -= p.volume(i)*rhoG;
        }
    }
}
