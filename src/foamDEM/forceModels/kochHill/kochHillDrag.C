#include "kochHillDrag.H"
#include "dragCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(kochHillDrag, 0);
    addToRunTimeSelectionTable(forceModel, kochHillDrag, dictionary);
}
}


Foam::scalar Foam::foamDEM::kochHillDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip
) const
{
    return ::foamDEM::correlations::kochHillForceCoeff(d, rho, mu, eps, slip);
}
