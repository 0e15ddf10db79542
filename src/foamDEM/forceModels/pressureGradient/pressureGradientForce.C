#include "pressureGradientForce.H"
#include "demCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(pressureGradientForce, 0);
    addToRunTimeSelectionTable(forceModel, pressureGradientForce, dictionary);
}
}


void Foam::foamDEM::pressureGradientForce::addRequirements
(
    exchangePlan& plan
) const
{
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::pressureGradientForce::addForce(particleData& p) const
{
    const volVectorField& gradP = coupling_.pressureGradient();
    const scalar rho = coupling_.rhoFluid();
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            p.uncoupledForce[i] -= p.volume(i)*rho*gradP[p.cell[i]];
        }
    }
}
