#include "hoelzerSommerfeldDrag.H"
#include "demCoupling.H"
#include "dragCorrelations.H"
#include "shapeDescriptors.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(hoelzerSommerfeldDrag, 0);
    addToRunTimeSelectionTable(forceModel, hoelzerSommerfeldDrag, dictionary);
}
}


Foam::foamDEM::hoelzerSommerfeldDrag::hoelzerSommerfeldDrag
(
    const dictionary& dict,
    const demCoupling& coupling
)
:
    forceModel(coupling),
    simplified_(false),
    diFeliceVoidage_(true)
{
    const word form(dict.getOrDefault<word>("form", "full"));
    if (form != "full" && form != "simplified")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown form " << form << nl << nl << "Valid form types :"
            << nl << "2(full simplified)" << exit(FatalIOError);
    }
    simplified_ = (form == "simplified");

    const word voidage(dict.getOrDefault<word>("voidage", "diFelice"));
    if (voidage != "diFelice" && voidage != "none")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown voidage " << voidage << nl << nl
            << "Valid voidage types :" << nl << "2(diFelice none)"
            << exit(FatalIOError);
    }
    diFeliceVoidage_ = (voidage == "diFelice");

    shapes_ = readParticleShapes(dict.subOrEmptyDict("shapes"));
}


void Foam::foamDEM::hoelzerSommerfeldDrag::sphericities
(
    const shapeSpec& shape,
    const vector& dirBody,
    scalar& phi,
    scalar& phiPerp,
    scalar& phiPar
)
{
    namespace corr = ::foamDEM::correlations;
    const double dir[3] = {dirBody.x(), dirBody.y(), dirBody.z()};
    switch (shape.kind)
    {
        case shapeSpec::kinds::spherocylinder:
        {
            const corr::spherocylinder s{shape.dim[0], shape.dim[1]};
            phi = corr::sphericity(s);
            phiPerp = corr::crosswiseSphericity(s, dir);
            phiPar = corr::lengthwiseSphericity(s, dir);
            break;
        }
        case shapeSpec::kinds::plate:
        {
            const corr::cuboid s{shape.dim[0], shape.dim[1], shape.dim[2]};
            phi = corr::sphericity(s);
            phiPerp = corr::crosswiseSphericity(s, dir);
            phiPar = corr::lengthwiseSphericity(s, dir);
            break;
        }
        default:
            phi = phiPerp = phiPar = 1;
    }
}


Foam::scalar Foam::foamDEM::hoelzerSommerfeldDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip,
    scalar phi,
    scalar phiPerp,
    scalar phiPar
) const
{
    namespace corr = ::foamDEM::correlations;
    eps = corr::clampVoidFraction(eps);

    // K = |F|/|w| stays finite as Re -> 0: evaluate at a floor Re with the
    // matching slip
    const scalar ReMin = 1e-10;
    scalar Re = eps*rho*slip*d/mu;
    if (Re < ReMin)
    {
        Re = ReMin;
        slip = Re*mu/(eps*rho*d);
    }
    const scalar Cd = simplified_
        ? corr::hoelzerSommerfeldSimplifiedCd(Re, phi, phiPerp)
        : corr::hoelzerSommerfeldCd(Re, phi, phiPerp, phiPar);
    scalar K = constant::mathematical::pi/8*Cd*rho*d*d*slip;
    if (diFeliceVoidage_)
    {
        K *= pow(eps, 2 - corr::diFeliceChi(Re));
    }
    return K;
}


void Foam::foamDEM::hoelzerSommerfeldDrag::addRequirements
(
    exchangePlan& plan
) const
{
    plan.need(quantity::velocity, typeName);
    plan.need(quantity::radius, typeName);
    if (shapes_.size())
    {
        plan.need(quantity::orientation, typeName);
        plan.need(quantity::type, typeName);
    }
}


void Foam::foamDEM::hoelzerSommerfeldDrag::addForce(particleData& p) const
{
    const scalar rho = coupling_.rhoFluid();
    const scalar mu = rho*coupling_.nuFluid();
    const bool modelB = coupling_.modelType() == demCoupling::modelTypes::B;
    const shapeSpec sphere{shapeSpec::kinds::sphere, {0, 0, 0}};

    forAll(p.cell, i)
    {
        if (p.cell[i] < 0) continue;

        const vector w(p.fluidVelocity[i] - p.velocity[i]);
        const scalar slip = mag(w);
        const shapeSpec& shape =
            p.type.size() ? shapes_.lookup(p.type[i], sphere) : sphere;

        scalar phi = 1, phiPerp = 1, phiPar = 1;
        if (shape.kind != shapeSpec::kinds::sphere)
        {
            // Flow direction in the body frame (x length, y width,
            // z thickness); any direction at zero slip
            const vector dir(slip > VSMALL ? w/slip : vector(1, 0, 0));
            sphericities(shape, p.orientation[i].T() & dir, phi, phiPerp, phiPar);
        }

        scalar K = forceCoeff
        (
            p.diameter(i), rho, mu, p.voidFraction[i], slip,
            phi, phiPerp, phiPar
        );
        if (modelB)
        {
            K /= p.voidFraction[i];
        }
        p.dragCoeff[i] += K;
    }
}
