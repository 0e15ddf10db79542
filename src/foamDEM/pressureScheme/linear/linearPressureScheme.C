#include "linearPressureScheme.H"
#include "fvcGrad.H"
#include "surfaceInterpolate.H"
#include "fvcFlux.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(linearPressureScheme, 0);
    addToRunTimeSelectionTable(pressureScheme, linearPressureScheme, dictionary);
}
}


Foam::tmp<Foam::surfaceScalarField>
Foam::foamDEM::linearPressureScheme::faceConductance
(
    const volScalarField& D
) const
{
    return fvc::interpolate(D);
}


Foam::tmp<Foam::surfaceScalarField>
Foam::foamDEM::linearPressureScheme::flux
(
    const volVectorField& v,
    const volScalarField&
) const
{
    return fvc::flux(v);
}


Foam::tmp<Foam::surfaceScalarField>
Foam::foamDEM::linearPressureScheme::interpolate
(
    const volScalarField& f,
    const volScalarField&
) const
{
    return fvc::interpolate(f);
}


Foam::tmp<Foam::volVectorField>
Foam::foamDEM::linearPressureScheme::grad
(
    const volScalarField& p,
    const volScalarField&
) const
{
    return fvc::grad(p);
}
