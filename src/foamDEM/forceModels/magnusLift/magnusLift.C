#include "magnusLift.H"
#include "demCoupling.H"
#include "liftTorqueCorrelations.H"
#include "fvcCurl.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(magnusLift, 0);
    addToRunTimeSelectionTable(forceModel, magnusLift, dictionary);
}
}


void Foam::foamDEM::magnusLift::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::velocity, typeName);
    plan.need(quantity::radius, typeName);
    plan.need(quantity::angularVelocity, typeName);
}


void Foam::foamDEM::magnusLift::addForce(particleData& p) const
{
    namespace corr = ::foamDEM::correlations;
    auto v3 = [](const vector& v) { return corr::vec3{v.x(), v.y(), v.z()}; };

    const volVectorField vorticity(fvc::curl(coupling_.U()));
    const scalar rho = coupling_.rhoFluid();
    const scalar mu = rho*coupling_.nuFluid();

    forAll(p.cell, i)
    {
        const label c = p.cell[i];
        if (c < 0) continue;

        const corr::vec3 F = corr::magnusLift
        (
            p.diameter(i), rho, mu,
            v3(p.fluidVelocity[i] - p.velocity[i]),
            v3(vorticity[c]),
            v3(p.angularVelocity[i])
        );
        p.coupledForce[i] += vector(F.x, F.y, F.z);
    }
}
