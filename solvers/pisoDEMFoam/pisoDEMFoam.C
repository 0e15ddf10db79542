/*---------------------------------------------------------------------------*\
Application
    pisoDEMFoam

Group
    foamDEM solvers

Description
    Transient incompressible solver for unresolved CFD-DEM: the fluid, with
    void fraction eps, coupled to a DEM (LIGGGHTS) that runs in the same
    process through the foamDEM library. PISO pressure-velocity coupling.

    Zhou et al. (2010), J. Fluid Mech. 661:482, sets I (model A) and
    II (model B), with w = eps for model A and w = 1 for model B:
        d(eps)/dt + div(eps u) = 0
        d(eps u)/dt + div(eps u u) - div(eps tau)/rho
            = -w grad(p) - K_pf/rho (u - U_s) + f_explicit/rho
    with kinematic pressure p (hydrostatic part excluded; the particles get
    buoyancy from the 'archimedes' force model) and K_pf, U_s, f_explicit
    from constant/couplingProperties' models. modelType selects A or B.

    Laminar or turbulent (constant/turbulenceProperties, void-fraction
    weighted), fvOptions supported.

    Inlet semantics: U is the interstitial velocity u, and the flux through
    a face is eps_f u_f . S_f (alphaPhi). A fixedValue U_in on an inlet
    brings the superficial inflow eps_inlet U_in. The void fraction's
    boundary conditions are read from <startTime>/voidfraction when the
    case has one; without it eps = 1 (fixedValue) on non-wall patches with
    a prescribed U and zeroGradient on walls and outlets, so an inlet
    velocity is the superficial velocity, also under a bed resting on the
    inlet. For an interstitial inflow give the inlet zeroGradient in
    0/voidfraction (the stability guard reports the superficial flow).

    Signals: SIGUSR1 writes the coming time step (fields and DEM
    restart), SIGUSR2 writes it and stops, e.g. before a wall-time limit;
    one rank is enough (foamDEM::stopSignals).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "pisoControl.H"
#include "fvOptions.H"
#include "demCoupling.H"
#include "cellReconstruct.H"
#include "writeAtEndTime.H"
#include "stopSignals.H"
#include "sigFpe.H"

typedef Foam::PhaseIncompressibleTurbulenceModel
<
    Foam::singlePhaseTransportModel
> phaseTurbulenceModel;

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Incompressible PISO solver with void fraction, coupled in-process"
        " to the DEM through foamDEM."
    );

    // SIGUSR1: write the coming step; SIGUSR2: write it and stop (a
    // wall-time limit). Before MPI starts its threads (stopSignals.H)
    foamDEM::stopSignals stopSignals;

    #include "setRootCase.H"

    // foamDEM checks particles and fields for NaN/Inf itself and stops
    // with the particle or cell and the last good state written; a
    // floating-point trap would kill the run first, without either
    sigFpe::unset(true);

    #include "createTime.H"
    #include "createMesh.H"

    pisoControl piso(mesh);

    #include "createFields.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        // the last step is written, also off the write grid (continuable)
        foamDEM::writeAtEndTime(runTime);
        stopSignals.check(runTime);
        ++runTime;
        Info<< "Time = " << runTime.timeName() << nl << endl;

        coupling.evolve();

        // Optionally, the time derivative's old velocity rebuilt from the
        // superficial face fluxes, so that cell and face velocities cannot
        // drift apart next to a packed bed (doc/models.md, pressure scheme)
        if (reconstructOldVelocity)
        {
            volVectorField& U0 = U.oldTime();
            U0.primitiveFieldRef() =
                foamDEM::cellReconstruct(alphaPhi)().primitiveField()
               /alpha.oldTime().primitiveField();
            U0.correctBoundaryConditions();
        }

        alphaf = fvc::interpolate(alpha);
        alphaPhi = alphaf*phi;
        const volScalarField pWeight(coupling.pressureWeight());

        #include "UEqn.H"

        while (piso.correct())
        {
            #include "pEqn.H"
        }

        laminarTransport.correct();
        turbulence->correct();

        // Stop on NaN/Inf, writing the last good step
        coupling.checkFluidFinite(U, p);
        coupling.measureFluidImpulse(U);

        #include "reportFlow.H"

        runTime.write();
        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;
    return 0;
}
