#include "smoothedVoidFraction.H"
#include "selectModel.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "gaussLaplacianScheme.H"
#include "snGradScheme.H"
#include "fvcSurfaceIntegrate.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(smoothedVoidFraction, 0);
    addToRunTimeSelectionTable(voidFractionModel, smoothedVoidFraction, dictionary);
}
}


// * * * * * * * * * * * * * * * Private functions  * * * * * * * * * * * * //

Foam::autoPtr<Foam::foamDEM::voidFractionModel>
Foam::foamDEM::smoothedVoidFraction::newBase
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word baseType(dict.getOrDefault<word>("base", "divided"));
    if (baseType == typeName)
    {
        FatalIOErrorInFunction(dict)
            << "base " << baseType << ": the base must be a distribution"
            << " (centre or divided)" << exit(FatalIOError);
    }
    auto cstrIter = selectModel
    (
        dict, "base", baseType, voidFractionModel::typeName,
        dictionaryConstructorTablePtr_
    );
    return cstrIter()(dict, mesh);
}


Foam::dictionary Foam::foamDEM::smoothedVoidFraction::solverControls
(
    const dictionary& dict
)
{
    dictionary controls;
    controls.add("solver", word("PCG"));
    controls.add("preconditioner", word("DIC"));
    controls.add("tolerance", 1e-12);
    controls.add("relTol", 0.0);
    controls.merge(dict.subOrEmptyDict("solver"));
    return controls;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::foamDEM::smoothedVoidFraction::smoothedVoidFraction
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(dict, mesh),
    base_(newBase(dict, mesh)),
    smoothingLength_(dict.getOrDefault<scalar>("smoothingLength", 0)),
    lengthInDiameters_
    (
        dict.getOrDefault<scalar>("smoothingLengthInDiameters", 0)
    ),
    solverDict_(solverControls(dict)),
    L_(0)
{
    const bool hasLength = dict.found("smoothingLength");
    const bool hasDiameters = dict.found("smoothingLengthInDiameters");
    if (hasLength == hasDiameters)
    {
        FatalIOErrorInFunction(dict)
            << "Give exactly one of smoothingLength (m) and"
            << " smoothingLengthInDiameters (L/d_max); "
            << (hasLength ? "both are" : "neither is") << " given."
            << exit(FatalIOError);
    }
    if (hasLength && smoothingLength_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "smoothingLength must be positive, got " << smoothingLength_
            << exit(FatalIOError);
    }
    if (hasDiameters && lengthInDiameters_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "smoothingLengthInDiameters must be positive, got "
            << lengthInDiameters_ << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * * //

void Foam::foamDEM::smoothedVoidFraction::addRequirements
(
    exchangePlan& plan
) const
{
    base_->addRequirements(plan);
    plan.need(quantity::radius, typeName);
}


void Foam::foamDEM::smoothedVoidFraction::distribute
(
    const particleData& p,
    particleCellWeights& w
) const
{
    base_->distribute(p, w);
}


void Foam::foamDEM::smoothedVoidFraction::compute
(
    particleData& p,
    volScalarField& alpha
) const
{
    if (lengthInDiameters_ > 0)
    {
        const scalar dMax = returnReduce
        (
            p.radius.size() ? 2*max(p.radius) : scalar(0),
            maxOp<scalar>()
        );
        L_ = lengthInDiameters_*dMax;
    }
    else
    {
        L_ = smoothingLength_;
    }

    voidFractionModel::compute(p, alpha);
}


void Foam::foamDEM::smoothedVoidFraction::smooth(scalarField& perVolume) const
{
    if (L_ <= 0)
    {
        return;
    }

    volScalarField s
    (
        IOobject
        (
            "voidFractionSmoothing",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar("zero", dimless, Zero),
        patchTypes(mesh_)
    );
    s.primitiveFieldRef() = perVolume;
    s.correctBoundaryConditions();

    const surfaceScalarField L2MagSf
    (
        "L2MagSf",
        dimensionedScalar("L2", dimArea, sqr(L_))*mesh_.magSf()
    );

    fvScalarMatrix eqn
    (
        fvm::Sp(dimensionedScalar("one", dimless, 1.0), s)
      - fv::gaussLaplacianScheme<scalar, scalar>::fvmLaplacianUncorrected
        (
            L2MagSf,
            mesh_.nonOrthDeltaCoeffs(),
            s
        )
    );
    eqn.source() += perVolume*mesh_.V();
    eqn.solve(solverDict_);

    // Conservative form: s = s0 + L^2 laplacian(s), the laplacian as a sum
    // of face fluxes that cancel pairwise, so the integral of s0 is kept to
    // round-off whatever the solver tolerance
    const surfaceScalarField flux
    (
        L2MagSf
       *fv::snGradScheme<scalar>::snGrad
        (
            s,
            tmp<surfaceScalarField>(mesh_.nonOrthDeltaCoeffs())
        )
    );
    perVolume += fvc::surfaceIntegrate(flux)().primitiveField();
}
