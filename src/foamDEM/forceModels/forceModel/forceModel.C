#include "forceModel.H"
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
    label type = -1;
    if (!readLabel(e.keyword(), type) || type < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entries of '" << dict.dictName() << "' are named by the"
            << " particle type (\"1\", \"2\", ...), got '" << e.keyword()
            << "'" << exit(FatalIOError);
    }
    return type;
}
