#include "voidFractionModel.H"
#include "selectModel.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(voidFractionModel, 0);
    defineRunTimeSelectionTable(voidFractionModel, dictionary);
}
}


Foam::foamDEM::voidFractionModel::voidFractionModel
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mesh_(mesh),
    alphaMin_(dict.getOrDefault<scalar>("alphaMin", 0.3)),
    nClipped_(0)
{
    if (alphaMin_ <= 0 || alphaMin_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "alphaMin must lie in (0, 1), got " << alphaMin_
            << exit(FatalIOError);
    }
}


Foam::autoPtr<Foam::foamDEM::voidFractionModel>
Foam::foamDEM::voidFractionModel::New
(
    const dictionary& couplingDict,
    const fvMesh& mesh
)
{
    const word modelType(couplingDict.get<word>("voidFraction"));

    auto cstrIter = selectModel
    (
        couplingDict, "voidFraction", modelType, typeName,
        dictionaryConstructorTablePtr_
    );

    return cstrIter()
    (
        couplingDict.optionalSubDict(modelType + "Coeffs"),
        mesh
    );
}


void Foam::foamDEM::voidFractionModel::setFromSolidVolume
(
    const scalarField& solidVolume,
    volScalarField& alpha
) const
{
    const scalarField& V = mesh_.V();
    scalarField& a = alpha.primitiveFieldRef();
    nClipped_ = 0;
    forAll(a, celli)
    {
        a[celli] = 1 - solidVolume[celli]/V[celli];
        if (a[celli] < alphaMin_)
        {
            a[celli] = alphaMin_;
            ++nClipped_;
        }
    }
    alpha.correctBoundaryConditions();
}
