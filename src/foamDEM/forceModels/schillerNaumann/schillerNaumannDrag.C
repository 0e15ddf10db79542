#include "schillerNaumannDrag.H"
#include "dragCorrelations.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(schillerNaumannDrag, 0);
    addToRunTimeSelectionTable(forceModel, schillerNaumannDrag, dictionary);
}
}


Foam::scalar Foam::foamDEM::schillerNaumannDrag::forceCoeff
(
    scalar d,
    scalar rho,
    scalar mu,
    scalar eps,
    scalar slip
) const
{
    return ::foamDEM::correlations::schillerNaumannForceCoeff(d, rho, mu, slip);
}
