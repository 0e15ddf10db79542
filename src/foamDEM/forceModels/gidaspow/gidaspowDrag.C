#include "gidaspowDrag.H"
#include "dragCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(gidaspowDrag, 0);
    addToRunTimeSelectionTable(forceModel, gidaspowDrag, dictionary);
}
}


Foam::scalar Foam::foamDEM::gidaspowDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip
) const
{
    return ::foamDEM::correlations::gidaspowForceCoeff(d, rho, mu, eps, slip);
}
