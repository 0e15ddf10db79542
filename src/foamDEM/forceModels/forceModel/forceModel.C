#include "forceModel.H"
#include "particleShapes.H"
#include "selectModel.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(forceModel, 0);
    defineRunTimeSelectionTable(forceModel, dictionary);
}
}


Foam::autoPtr<Foam::foamDEM::forceModel> Foam::foamDEM::forceModel::New
(
    const word& modelName,
    const dictionary& couplingDict,
    const demCoupling& coupling
)
{
    auto cstrIter = selectModel
    (
        couplingDict, "forceModels", modelName, typeName,
        dictionaryConstructorTablePtr_
    );

    return cstrIter()
    (
        couplingDict.optionalSubDict(modelName + "Coeffs"),
        coupling
    );
}


Foam::label Foam::foamDEM::forceModel::typeOfEntry
(
    const dictionary& dict,
    const entry& e
)
{
    return particleTypeOfEntry(dict, e);
}
