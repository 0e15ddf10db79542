#include "momentumCouplingModel.H"
#include "selectModel.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(momentumCouplingModel, 0);
    defineRunTimeSelectionTable(momentumCouplingModel, dictionary);
}
}


Foam::autoPtr<Foam::foamDEM::momentumCouplingModel>
Foam::foamDEM::momentumCouplingModel::New(const dictionary& couplingDict)
{
    const word modelType(couplingDict.get<word>("momentumCoupling"));

    auto cstrIter = selectModel
    (
        couplingDict, "momentumCoupling", modelType, typeName,
        dictionaryConstructorTablePtr_
    );

    return cstrIter()(couplingDict.optionalSubDict(modelType + "Coeffs"));
}
