#include "diFeliceDrag.H"
#include "dragCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(diFeliceDrag, 0);
    addToRunTimeSelectionTable(forceModel, diFeliceDrag, dictionary);
}
}


Foam::scalar Foam::foamDEM::diFeliceDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip
) const
{
    return ::foamDEM::correlations::diFeliceForceCoeff(d, rho, mu, eps, slip);
}
