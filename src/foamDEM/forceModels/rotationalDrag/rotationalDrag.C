#include "rotationalDrag.H"
#include "demCoupling.H"
#include "liftTorqueCorrelations.H"
#include "fvcCurl.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(rotationalDrag, 0);
    addToRunTimeSelectionTable(forceModel, rotationalDrag, dictionary);
}
}


Foam::foamDEM::rotationalDrag::rotationalDrag
(
    const dictionary& dict,
    const demCoupling& coupling
)
:
    forceModel(coupling)
{
    const dictionary& factors = dict.subDict("factors");
    for (const entry& e : factors)
    {
        const label type = typeOfEntry(factors, e);
        const scalar f = readScalar(e.stream());
        if (!(f > 0))
        {
            FatalIOErrorInFunction(factors)
                << "The factor of body type " << type << " must be > 0,"
                << " got " << f << exit(FatalIOError);
        }
        factor_.set(type, f);
    }
    if (factor_.empty())
    {
        FatalIOErrorInFunction(factors)
            << "'factors' lists no body type: the model would do nothing"
            << exit(FatalIOError);
    }
}


void Foam::foamDEM::rotationalDrag::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::radius, typeName);
    plan.need(quantity::angularVelocity, typeName);
    plan.need(quantity::type, typeName);
    plan.need(quantity::torque, typeName);
}


void Foam::foamDEM::rotationalDrag::addForce(particleData& p) const
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
        const auto iter = factor_.cfind(p.type[i]);
        if (!iter.found()) continue;

        const corr::vec3 T = corr::rotationalTorque
        (
            p.diameter(i), rho, mu,
            v3(vorticity[c]), v3(p.angularVelocity[i])
        );
        p.torque[i] += (*iter)*vector(T.x, T.y, T.z);
    }
}
