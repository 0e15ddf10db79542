#include "drivingForce.H"
#include "demCoupling.H"
#include "uniformDimensionedFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(drivingForce, 0);
    addToRunTimeSelectionTable(forceModel, drivingForce, dictionary);
}
}


namespace
{
    const Foam::word publishedName("foamDEM:drivingForce");
}


Foam::foamDEM::drivingForce::drivingForce
(
    const dictionary& dict,
    const demCoupling& coupling
)
:
    forceModel(coupling),
    startIndex_(coupling.mesh().time().timeIndex())
{}


Foam::vector Foam::foamDEM::drivingForce::forcePerVolume() const
{
    const fvMesh& mesh = coupling_.mesh();
    const auto* f =
        mesh.findObject<uniformDimensionedVectorField>(publishedName);
    if (f)
    {
        return f->value();
    }
    if (mesh.time().timeIndex() == startIndex_)
    {
        // The coupling's first update runs before the fvOptions exist
        return Zero;
    }
    FatalErrorInFunction
        << "The force model " << typeName << " needs the driving force"
        << " per unit volume '" << publishedName << "', which no fvOption"
        << " publishes." << nl
        << "    Add a flowController with 'applyToParticles yes' to"
        << " system/fvOptions (or constant/fvOptions), or remove "
        << typeName << " from forceModels." << exit(FatalError);
    return Zero;
}


void Foam::foamDEM::drivingForce::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::drivingForce::addForce(particleData& p) const
{
    const vector f = forcePerVolume();
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            p.uncoupledForce[i] += p.volume(i)*f;
        }
    }
}
