#include "pressureScheme.H"
#include "selectModel.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(pressureScheme, 0);
    defineRunTimeSelectionTable(pressureScheme, dictionary);
}
}


Foam::autoPtr<Foam::foamDEM::pressureScheme>
Foam::foamDEM::pressureScheme::New
(
    const fvMesh& mesh,
    const dictionary& couplingDict
)
{
    const word name
    (
        couplingDict.lookupOrDefault<word>("pressureScheme", "conductance")
    );
    auto cstrIter = selectModel
    (
        couplingDict, "pressureScheme", name, "pressureScheme",
        dictionaryConstructorTablePtr_
    );
    return autoPtr<pressureScheme>(cstrIter()(mesh, couplingDict));
}
