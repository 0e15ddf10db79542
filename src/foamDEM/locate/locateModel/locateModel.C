#include "locateModel.H"
#include "selectModel.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(locateModel, 0);
    defineRunTimeSelectionTable(locateModel, dictionary);
}
}


Foam::autoPtr<Foam::foamDEM::locateModel> Foam::foamDEM::locateModel::New
(
    const dictionary& couplingDict,
    const fvMesh& mesh
)
{
    const word modelType(couplingDict.get<word>("locate"));

    auto cstrIter = selectModel
    (
        couplingDict, "locate", modelType, typeName,
        dictionaryConstructorTablePtr_
    );

    return cstrIter()
    (
        couplingDict.optionalSubDict(modelType + "Coeffs"),
        mesh
    );
}
