#include "demEngine.H"
#include "selectModel.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(demEngine, 0);
    defineRunTimeSelectionTable(demEngine, dictionary);
}
}


Foam::autoPtr<Foam::foamDEM::demEngine> Foam::foamDEM::demEngine::New
(
    const Time& runTime,
    const dictionary& couplingDict
)
{
    const word engineType(couplingDict.getOrDefault<word>("demEngine", "liggghts"));

    auto cstrIter = selectModel
    (
        couplingDict, "demEngine", engineType, typeName,
        dictionaryConstructorTablePtr_
    );

    return cstrIter()(runTime, couplingDict);
}
