#include "cloudOutput.H"
#include "addToRunTimeSelectionTable.H"
#include "passiveParticleCloud.H"
#include "IOField.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(cloudOutput, 0);
    addToRunTimeSelectionTable(particleOutput, cloudOutput, dictionary);
}
}


void Foam::foamDEM::cloudOutput::addRequirements(exchangePlan& plan) const
{
    needParticles(plan, "particleOutput");
}


void Foam::foamDEM::cloudOutput::write
(
    const particleData& p,
    const exchangePlan&
)
{
    passiveParticleCloud cloud(mesh_, cloudName_, IDLList<passiveParticle>());

    DynamicList<label> written(p.size());
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            cloud.addParticle
            (
                new passiveParticle(mesh_, p.position[i], p.cell[i])
            );
            written.append(i);
        }
    }

    auto makeField = [&](const word& name, auto value)
    {
        using Type = decltype(value(label(0)));
        IOField<Type> f
        (
            cloud.fieldIOobject(name, IOobject::NO_READ),
            written.size()
        );
        forAll(written, k)
        {
            f[k] = value(written[k]);
        }
        f.write(written.size() > 0);
    };

    makeField("U", [&](label i) { return p.velocity[i]; });
    makeField("d", [&](label i) { return p.diameter(i); });
    // Not "origId": the cloud writes its own particle counter under that name
    makeField("demId", [&](label i) { return p.id[i]; });
    makeField("f", [&](label i) { return p.fluidForce[i]; });

    cloud.write();
}
