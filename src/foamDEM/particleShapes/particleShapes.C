#include "particleShapes.H"

Foam::label Foam::foamDEM::particleTypeOfEntry
(
    const dictionary& dict,
    const entry& e
)
{
    label type = -1;
    if (!readLabel(e.keyword(), type) || type < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entries of '" << dict.dictName() << "' are named by the"
            << " particle type (\"1\", \"2\", ...), got '" << e.keyword()
            << "'" << exit(FatalIOError);
    }
    return type;
}


Foam::Map<Foam::foamDEM::particleShape>
Foam::foamDEM::readParticleShapes(const dictionary& shapesDict)
{
    Map<particleShape> shapes;
    for (const entry& e : shapesDict)
    {
        const dictionary& sd = e.dict();
        const label type = particleTypeOfEntry(shapesDict, e);
        const word shape(sd.get<word>("shape"));
        particleShape spec;
        if (shape == "spherocylinder")
        {
            spec.kind = particleShape::kinds::spherocylinder;
            spec.dim[0] = sd.get<scalar>("diameter");
            spec.dim[1] = sd.get<scalar>("length");
            spec.dim[2] = 0;
            if (spec.dim[1] < spec.dim[0] || spec.dim[0] <= 0)
            {
                FatalIOErrorInFunction(sd)
                    << "A spherocylinder needs 0 < diameter <= length (the"
                    << " total length, caps included)" << exit(FatalIOError);
            }
        }
        else if (shape == "plate")
        {
            spec.kind = particleShape::kinds::plate;
            spec.dim[0] = sd.get<scalar>("length");
            spec.dim[1] = sd.get<scalar>("width");
            spec.dim[2] = sd.get<scalar>("thickness");
            if (min(spec.dim[0], min(spec.dim[1], spec.dim[2])) <= 0)
            {
                FatalIOErrorInFunction(sd)
                    << "A plate needs positive length, width and thickness"
                    << exit(FatalIOError);
            }
        }
        else
        {
            FatalIOErrorInFunction(sd)
                << "Unknown shape " << shape << nl << nl
                << "Valid shape types :" << nl << "2(plate spherocylinder)"
                << exit(FatalIOError);
        }
        shapes.set(type, spec);
    }
    return shapes;
}
