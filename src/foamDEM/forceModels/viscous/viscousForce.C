#include "viscousForce.H"
#include "demCoupling.H"
#include "fvcDiv.H"
#include "fvcGrad.H"
#include "fvcLaplacian.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(viscousForce, 0);
    addToRunTimeSelectionTable(forceModel, viscousForce, dictionary);
}
}


void Foam::foamDEM::viscousForce::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::viscousForce::addForce(particleData& p) const
{
    const volVectorField& U = coupling_.U();
    const dimensionedScalar nu("nu", dimViscosity, coupling_.nuFluid());

    // div(nu (grad(u) + grad(u)^T)), kinematic
    const volVectorField divTau
    (
        fvc::laplacian(nu, U) + fvc::div(nu*T(fvc::grad(U)))
    );
    const scalar rho = coupling_.rhoFluid();

    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            p.uncoupledForce[i] += p.volume(i)*rho*divTau[p.cell[i]];
        }
    }
}
