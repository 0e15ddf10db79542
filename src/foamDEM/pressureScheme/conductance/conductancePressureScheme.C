#include "conductancePressureScheme.H"
#include "fvcSurfaceIntegrate.H"
#include "surfaceInterpolate.H"
#include "surfaceInterpolationScheme.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(conductancePressureScheme, 0);
    addToRunTimeSelectionTable
    (
        pressureScheme,
        conductancePressureScheme,
        dictionary
    );
}
}


namespace
{

using Foam::scalar;

// Conductance of the half-cells P and N in series; w is P's linear weight
inline scalar seriesConductance(scalar DP, scalar DN, scalar w)
{
    const scalar denominator = (1 - w)*DN + w*DP;
    return denominator > Foam::VSMALL ? DP*DN/denominator : 0;
}

// Owner weight of the face pressure (ownSide) or of a flux quantity
inline scalar ownerWeight(scalar DP, scalar DN, scalar w, bool ownSide)
{
    const scalar aP = ownSide ? w*DP : w*DN;
    const scalar aN = ownSide ? (1 - w)*DN : (1 - w)*DP;
    const scalar sum = aP + aN;
    return sum > Foam::VSMALL ? aP/sum : w;
}

// The owner weights of every internal and coupled face
Foam::tmp<Foam::surfaceScalarField> ownerWeights
(
    const Foam::volScalarField& D,
    bool ownSide
)
{
    using namespace Foam;
    const fvMesh& mesh = D.mesh();
    const surfaceScalarField& weights = mesh.weights();

    tmp<surfaceScalarField> tlambda
    (
        new surfaceScalarField("conductanceWeights", weights)
    );
    surfaceScalarField& lambda = tlambda.ref();

    const labelUList& owner = mesh.owner();
    const labelUList& neighbour = mesh.neighbour();
    scalarField& lambdaIn = lambda.primitiveFieldRef();
    forAll(owner, facei)
    {
        lambdaIn[facei] = ownerWeight
        (
            D[owner[facei]], D[neighbour[facei]], weights[facei], ownSide
        );
    }

    auto& lambdaBf = lambda.boundaryFieldRef();
    forAll(lambdaBf, patchi)
    {
        const fvPatchScalarField& Dp = D.boundaryField()[patchi];
        if (Dp.coupled())
        {
            const scalarField DP(Dp.patchInternalField());
            const scalarField DN(Dp.patchNeighbourField());
            const scalarField& w = weights.boundaryField()[patchi];
            forAll(DP, i)
            {
                lambdaBf[patchi][i] = ownerWeight(DP[i], DN[i], w[i], ownSide);
            }
        }
    }
    return tlambda;
}

} // End anonymous namespace


Foam::tmp<Foam::surfaceScalarField>
Foam::foamDEM::conductancePressureScheme::faceConductance
(
    const volScalarField& D
) const
{
    // Boundary faces: the linear scheme's values (the cell's own D on
    // walls and inlets); internal and coupled faces: halves in series
    tmp<surfaceScalarField> tDf(fvc::interpolate(D));
    surfaceScalarField& Df = tDf.ref();
    Df.rename("pressureConductance");

    const surfaceScalarField& weights = mesh_.weights();
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();

    scalarField& DfIn = Df.primitiveFieldRef();
    forAll(owner, facei)
    {
        DfIn[facei] = seriesConductance
        (
            D[owner[facei]], D[neighbour[facei]], weights[facei]
        );
    }

    auto& DfBf = Df.boundaryFieldRef();
    forAll(DfBf, patchi)
    {
        const fvPatchScalarField& Dp = D.boundaryField()[patchi];
        if (Dp.coupled())
        {
            const scalarField DP(Dp.patchInternalField());
            const scalarField DN(Dp.patchNeighbourField());
            const scalarField& w = weights.boundaryField()[patchi];
            forAll(DP, i)
            {
                DfBf[patchi][i] = seriesConductance(DP[i], DN[i], w[i]);
            }
        }
    }
    return tDf;
}


Foam::tmp<Foam::surfaceScalarField>
Foam::foamDEM::conductancePressureScheme::flux
(
    const volVectorField& v,
    const volScalarField& D
) const
{
    return surfaceInterpolationScheme<vector>::dotInterpolate
    (
        mesh_.Sf(), v, ownerWeights(D, false)
    );
}


Foam::tmp<Foam::surfaceScalarField>
Foam::foamDEM::conductancePressureScheme::interpolate
(
    const volScalarField& f,
    const volScalarField& D
) const
{
    return surfaceInterpolationScheme<scalar>::interpolate
    (
        f, ownerWeights(D, false)
    );
}


Foam::tmp<Foam::volVectorField>
Foam::foamDEM::conductancePressureScheme::grad
(
    const volScalarField& p,
    const volScalarField& D
) const
{
    // Face pressures: continuous flux on internal and coupled faces, the
    // boundary condition's value elsewhere
    const surfaceScalarField pf
    (
        surfaceInterpolationScheme<scalar>::interpolate
        (
            p, ownerWeights(D, true)
        )
    );

    tmp<volVectorField> tgrad(fvc::surfaceIntegrate(mesh_.Sf()*pf));
    tgrad.ref().rename("grad(" + p.name() + ')');
    tgrad.ref().correctBoundaryConditions();
    return tgrad;
}
