#include "explicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(explicitCoupling, 0);
    addToRunTimeSelectionTable(momentumCouplingModel, explicitCoupling, dictionary);
}
}


void Foam::foamDEM::explicitCoupling::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::velocity, typeName);
    plan.need(quantity::explicitForce, typeName);
}


void Foam::foamDEM::explicitCoupling::distribute
(
    particleData& p,
    scalarField& sumK,
    vectorField& sumKv,
    vectorField& forceOnFluid,
    const particleCellWeights* weights
) const
{
    forAll(p.cell, i)
    {
        const label c = p.cell[i];
        if (c < 0)
        {
            p.explicitForce[i] = Zero;
            p.fluidForce[i] = Zero;
            continue;
        }
        const vector drag =
            p.dragCoeff[i]*(p.fluidVelocity[i] - p.velocity[i]);
        p.explicitForce[i] = drag + p.coupledForce[i] + p.uncoupledForce[i];
        p.fluidForce[i] = p.explicitForce[i];

        if (weights)
        {
            for (label k = weights->start(i); k < weights->end(i); ++k)
            {
                forceOnFluid[weights->cell(k)] -=
                    weights->weight(k)*(drag + p.coupledForce[i]);
            }
        }
        else
        {
            forceOnFluid[c] -= drag + p.coupledForce[i];
        }
    }
}
