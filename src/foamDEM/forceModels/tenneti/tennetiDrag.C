#include "tennetiDrag.H"
#include "dragCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(tennetiDrag, 0);
    addToRunTimeSelectionTable(forceModel, tennetiDrag, dictionary);
}
}


Foam::scalar Foam::foamDEM::tennetiDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip
) const
{
    return ::foamDEM::correlations::tennetiForceCoeff(d, rho, mu, eps, slip);
}
