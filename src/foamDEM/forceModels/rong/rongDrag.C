#include "rongDrag.H"
#include "dragCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(rongDrag, 0);
    addToRunTimeSelectionTable(forceModel, rongDrag, dictionary);
}
}


Foam::scalar Foam::foamDEM::rongDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip
) const
{
    return ::foamDEM::correlations::rongForceCoeff(d, rho, mu, eps, slip);
}
