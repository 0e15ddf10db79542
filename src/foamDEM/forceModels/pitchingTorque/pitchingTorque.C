#include "pitchingTorque.H"
#include "demCoupling.H"
#include "liftTorqueCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(pitchingTorque, 0);
    addToRunTimeSelectionTable(forceModel, pitchingTorque, dictionary);
}
}


Foam::foamDEM::pitchingTorque::pitchingTorque
(
    const dictionary& dict,
    const demCoupling& coupling
)
:
    forceModel(coupling)
{
    namespace corr = ::foamDEM::correlations;

    const word set(dict.getOrDefault<word>("coefficients", "zastawnyProlate52"));
    if (set == "zastawnyProlate52" || set == "zastawnyProlate54")
    {
        const double* c = set == "zastawnyProlate52"
            ? corr::zastawnyProlate52 : corr::zastawnyProlate54;
        forAll(c_, k) c_[k] = c[k];
    }
    else if (set == "user")
    {
        c_ = dict.get<FixedList<scalar, 10>>("c");
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown coefficients " << set << nl << nl
            << "Valid coefficients types :" << nl
            << "3(user zastawnyProlate52 zastawnyProlate54)"
            << exit(FatalIOError);
    }

    const dictionary& axes = dict.subDict("axes");
    for (const entry& e : axes)
    {
        const label type = typeOfEntry(axes, e);
        const word axis(e.stream());
        if (axis != "length" && axis != "thickness")
        {
            FatalIOErrorInFunction(axes)
                << "Unknown axis " << axis << " for body type " << type
                << nl << nl << "Valid axis types :" << nl
                << "2(length thickness)" << exit(FatalIOError);
        }
        flat_.set(type, axis == "thickness");
    }
    if (flat_.empty())
    {
        FatalIOErrorInFunction(axes)
            << "'axes' lists no body type: the model would do nothing"
            << exit(FatalIOError);
    }
}


void Foam::foamDEM::pitchingTorque::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::velocity, typeName);
    plan.need(quantity::radius, typeName);
    plan.need(quantity::orientation, typeName);
    plan.need(quantity::type, typeName);
    plan.need(quantity::torque, typeName);
}


void Foam::foamDEM::pitchingTorque::addForce(particleData& p) const
{
    namespace corr = ::foamDEM::correlations;
    auto v3 = [](const vector& v) { return corr::vec3{v.x(), v.y(), v.z()}; };

    const scalar rho = coupling_.rhoFluid();
    const scalar mu = rho*coupling_.nuFluid();
    const double* c = c_.cdata();

    forAll(p.cell, i)
    {
        if (p.cell[i] < 0) continue;
        const auto iter = flat_.cfind(p.type[i]);
        if (!iter.found()) continue;

        // orientation columns: length, width, thickness axes
        const bool flat = *iter;
        const vector axis(p.orientation[i].col(flat ? 2 : 0));
        const corr::vec3 T = corr::pitchingTorque
        (
            c, p.diameter(i), rho, mu,
            v3(p.fluidVelocity[i] - p.velocity[i]), v3(axis), flat
        );
        p.torque[i] += vector(T.x, T.y, T.z);
    }
}
