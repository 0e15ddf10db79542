#include "particleOutput.H"
#include "selectModel.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(particleOutput, 0);
    defineRunTimeSelectionTable(particleOutput, dictionary);
}
}


Foam::PtrList<Foam::foamDEM::particleOutput>
Foam::foamDEM::particleOutput::New
(
    const fvMesh& mesh,
    const dictionary& couplingDict
)
{
    const wordList names
    (
        couplingDict.getOrDefault<wordList>("particleOutput", wordList{"cloud"})
    );
    const word cloudName
    (
        couplingDict.getOrDefault<word>("cloudName", "particles")
    );

    PtrList<particleOutput> outputs(names.size());
    forAll(names, i)
    {
        auto cstrIter = selectModel
        (
            couplingDict, "particleOutput", names[i], typeName,
            dictionaryConstructorTablePtr_
        );
        for (label j = 0; j < i; ++j)
        {
            if (names[j] == names[i])
            {
                FatalIOErrorInFunction(couplingDict)
                    << "particleOutput lists " << names[i] << " twice: "
                    << names << nl << "Valid particleOutput types :" << nl
                    << dictionaryConstructorTablePtr_->sortedToc()
                    << exit(FatalIOError);
            }
        }
        outputs.set
        (
            i,
            cstrIter()
            (
                mesh,
                cloudName,
                couplingDict.optionalSubDict(names[i] + "Coeffs")
            )
        );
    }
    return outputs;
}
