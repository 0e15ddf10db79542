#include "saffmanMeiLift.H"
#include "demCoupling.H"
#include "fvcCurl.H"
#include "liftTorqueCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(saffmanMeiLift, 0);
    addToRunTimeSelectionTable(forceModel, saffmanMeiLift, dictionary);
}
}


namespace
{
    ::foamDEM::correlations::vec3 toVec3(const Foam::vector& v)
    {
        return {v.x(), v.y(), v.z()};
    }
}


Foam::foamDEM::saffmanMeiLift::saffmanMeiLift
(
    const dictionary& dict,
    const demCoupling& coupling
)
:
    forceModel(coupling),
    mei_(true)
{
    const word correction = dict.getOrDefault<word>("correction", "mei");
    if (correction != "mei" && correction != "none")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown correction '" << correction << "' for saffmanMeiLift"
            << " (keyword correction of " << dict.name() << ");"
            << " valid: mei (Mei 1992, the default), none (Saffman 1965)"
            << exit(FatalIOError);
    }
    mei_ = (correction == "mei");
    Info<< "saffmanMeiLift: correction " << correction << endl;
}


void Foam::foamDEM::saffmanMeiLift::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::velocity, typeName);
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::saffmanMeiLift::addForce(particleData& p) const
{
    const volVectorField vorticity(fvc::curl(coupling_.U()));
    const scalar rho = coupling_.rhoFluid();
    const scalar mu = rho*coupling_.nuFluid();

    forAll(p.cell, i)
    {
        const label c = p.cell[i];
        if (c < 0)
        {
            continue;
        }
        const ::foamDEM::correlations::vec3 F =
            ::foamDEM::correlations::saffmanMeiLift
            (
                p.diameter(i),
                rho,
                mu,
                toVec3(p.fluidVelocity[i] - p.velocity[i]),
                toVec3(vorticity[c]),
                mei_
            );
        p.coupledForce[i] += vector(F.x, F.y, F.z);
    }
}
