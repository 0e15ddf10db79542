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

// Set result = combine(D_P, D_N, w) on every internal and coupled face;
// other boundary faces keep their values
template<class Combine>
void setFaceValues
(
    const Foam::volScalarField& D,
    Foam::surfaceScalarField& result,
    const Combine& combine
)
{
    using namespace Foam;
    const fvMesh& mesh = D.mesh();
    const surfaceScalarField& weights = mesh.weights();
    const labelUList& owner = mesh.owner();
    const labelUList& neighbour = mesh.neighbour();

    scalarField& internal = result.primitiveFieldRef();
    forAll(owner, facei)
    {
        internal[facei] =
            combine(D[owner[facei]], D[neighbour[facei]], weights[facei]);
    }

    auto& boundary = result.boundaryFieldRef();
    forAll(boundary, patchi)
    {
        const fvPatchScalarField& Dp = D.boundaryField()[patchi];
        if (Dp.coupled())
        {
            const scalarField DP(Dp.patchInternalField());
            const scalarField DN(Dp.patchNeighbourField());
            const scalarField& w = weights.boundaryField()[patchi];
            forAll(DP, i)
            {
                boundary[patchi][i] = combine(DP[i], DN[i], w[i]);
            }
        }
    }
}

// The owner weights of every internal and coupled face
Foam::tmp<Foam::surfaceScalarField> ownerWeights
(
    const Foam::volScalarField& D,
    bool ownSide
)
{
    Foam::tmp<Foam::surfaceScalarField> tlambda
    (
        new Foam::surfaceScalarField
        (
            "conductanceWeights",
            D.mesh().weights()
        )
    );
    setFaceValues
    (
        D,
        tlambda.ref(),
        [ownSide](scalar DP, scalar DN, scalar w)
        {
            return ownerWeight(DP, DN, w, ownSide);
        }
    );
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
    tDf.ref().rename("pressureConductance");
    setFaceValues(D, tDf.ref(), seriesConductance);
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
