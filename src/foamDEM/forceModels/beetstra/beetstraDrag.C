#include "beetstraDrag.H"
#include "dragCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(beetstraDrag, 0);
    addToRunTimeSelectionTable(forceModel, beetstraDrag, dictionary);
}
}


Foam::scalar Foam::foamDEM::beetstraDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip
) const
{
    return ::foamDEM::correlations::beetstraForceCoeff(d, rho, mu, eps, slip);
}
