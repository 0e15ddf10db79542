#include "exchangePlan.H"

const Foam::Enum<Foam::foamDEM::quantity> Foam::foamDEM::exchangePlan::names
({
    { quantity::position, "position" },
    { quantity::velocity, "velocity" },
    { quantity::radius, "radius" },
    { quantity::density, "density" },
    { quantity::angularVelocity, "angularVelocity" },
    { quantity::orientation, "orientation" },
    { quantity::type, "type" },
    { quantity::id, "id" },
    { quantity::implicitCoeff, "implicitCoeff" },
    { quantity::fluidVelocity, "fluidVelocity" },
    { quantity::explicitForce, "explicitForce" },
    { quantity::torque, "torque" },
});


void Foam::foamDEM::exchangePlan::need(quantity q, const word& who)
{
    const word& key = names[q];
    if (!requests_.found(key))
    {
        requests_.insert(key, wordList());
        order_.append(key);
        mask_ |= 1u << unsigned(q);
    }
    wordList& models = requests_[key];
    if (!models.found(who))
    {
        models.append(who);
    }
}


Foam::stringList Foam::foamDEM::exchangePlan::describe() const
{
    stringList lines;
    for (const bool pulled : {true, false})
    {
        for (const word& key : order_)
        {
            if (isPulled(names[key]) != pulled) continue;
            string line(key + (pulled ? " (from DEM): " : " (to DEM): "));
            for (const word& who : requests_[key])
            {
                line += who + ' ';
            }
            lines.append(line);
        }
    }
    return lines;
}


void Foam::foamDEM::exchangePlan::print() const
{
    Info<< "foamDEM exchange plan (quantity: models that need it)" << nl;
    for (const string& line : describe())
    {
        Info<< "    " << line.c_str() << nl;
    }
    Info<< endl;
}
