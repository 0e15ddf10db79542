#include "dragModel.H"
#include "demCoupling.H"

void Foam::foamDEM::dragModel::addRequirements(exchangePlan& plan) const
{
    const word who(type());
    plan.need(quantity::velocity, who);
    plan.need(quantity::radius, who);
}


void Foam::foamDEM::dragModel::addForce(particleData& p) const
{
    const scalar rho = coupling_.rhoFluid();
    const scalar mu = rho*coupling_.nuFluid();
    const bool modelB = coupling_.modelType() == demCoupling::modelTypes::B;

    forAll(p.cell, i)
    {
        if (p.cell[i] < 0) continue;

        const scalar eps = p.voidFraction[i];
        const scalar slip = mag(p.fluidVelocity[i] - p.velocity[i]);
        scalar K = forceCoeff(p.diameter(i), rho, mu, eps, slip);
        if (modelB)
        {
            K /= eps;
        }
        p.dragCoeff[i] += K;
    }
}
