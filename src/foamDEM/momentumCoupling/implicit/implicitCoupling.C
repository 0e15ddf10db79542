#include "implicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(implicitCoupling, 0);
    addToRunTimeSelectionTable(momentumCouplingModel, implicitCoupling, dictionary);
}
}


void Foam::foamDEM::implicitCoupling::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::velocity, typeName);
    plan.need(quantity::implicitCoeff, typeName);
    plan.need(quantity::fluidVelocity, typeName);
    plan.need(quantity::explicitForce, typeName);
}


void Foam::foamDEM::implicitCoupling::distribute
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
            p.implicitCoeff[i] = 0;
            p.explicitForce[i] = Zero;
            p.fluidForce[i] = Zero;
            continue;
        }
        const scalar K = p.dragCoeff[i];
        p.implicitCoeff[i] = K;
        p.explicitForce[i] = p.coupledForce[i] + p.uncoupledForce[i];
        p.fluidForce[i] =
            K*(p.fluidVelocity[i] - p.velocity[i]) + p.explicitForce[i];

        if (weights)
        {
            for (label k = weights->start(i); k < weights->end(i); ++k)
            {
                const label cw = weights->cell(k);
                const scalar w = weights->weight(k);
                sumK[cw] += w*K;
                sumKv[cw] += w*K*p.velocity[i];
                forceOnFluid[cw] -= w*p.coupledForce[i];
            }
        }
        else
        {
            sumK[c] += K;
            sumKv[c] += K*p.velocity[i];
            forceOnFluid[c] -= p.coupledForce[i];
        }
    }
}
