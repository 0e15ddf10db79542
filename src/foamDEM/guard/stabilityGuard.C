#include "stabilityGuard.H"
#include "demCoupling.H"
#include "timeStepCriteria.H"
#include "mathematicalConstants.H"
#include "wallFvPatch.H"
#include "locateModel.H"
#include "particleTransfer.H"

namespace
{
    using namespace Foam;

    string fmt(scalar x)
    {
        OStringStream os;
        os.precision(3);
        os << x;
        return os.str();
    }

    string pct(scalar x)
    {
        return fmt(100*x) + " %";
    }

    //- The dictionary of the coupling and of the guard's keys
    const string couplingFile("constant/couplingProperties");

    //- Smallest value and where it was, reduced over ranks
    struct worst
    {
        scalar value = GREAT;
        scalar d = 0;
        void take(scalar v, scalar diameter)
        {
            if (v < value) { value = v; d = diameter; }
        }
        void reduceMin()
        {
            const scalar vMin = returnReduce(value, minOp<scalar>());
            scalar dAt = (value == vMin) ? d : GREAT;
            reduce(dAt, minOp<scalar>());
            value = vMin;
            d = dAt;
        }
    };
}


Foam::foamDEM::stabilityGuard::stabilityGuard
(
    const demCoupling& coupling,
    const dictionary& dict
)
:
    coupling_(coupling),
    dict_(dict)
{}


void Foam::foamDEM::stabilityGuard::checkRanges
(
    scalar dMin, scalar dMax, scalar rhoMin, scalar rhoMax,
    const scalarList& E, const scalarList& nu
)
{
    auto inRange = [&](const string& what, scalar v, scalar lo, scalar hi,
                       const string& unit, const string& where)
    {
        if (!(v >= lo && v <= hi))
        {
            refuse
            (
                what + " = " + fmt(v) + ' ' + unit + " (" + where
              + ") is outside the physical range [" + fmt(lo) + ", "
              + fmt(hi) + "] " + unit + ": check its value and units (SI)."
            );
        }
    };

    inRange("fluid density rho", coupling_.rhoFluid(), 1e-3, 3e4,
        "kg/m^3", "constant/transportProperties");
    inRange("fluid kinematic viscosity nu", coupling_.nuFluid(), 1e-8, 1,
        "m^2/s", "constant/transportProperties");
    inRange("gravity |g|", mag(coupling_.gravity()), 0, 100,
        "m/s^2", "constant/g");
    if (dMax > 0)
    {
        inRange("smallest particle diameter", dMin, 1e-7, 1, "m", "DEM");
        inRange("largest particle diameter", dMax, 1e-7, 1, "m", "DEM");
        inRange("smallest particle density", rhoMin, 10, 3e4, "kg/m^3", "DEM");
        inRange("largest particle density", rhoMax, 10, 3e4, "kg/m^3", "DEM");
    }
    forAll(E, t)
    {
        inRange("Young's modulus of type " + Foam::name(t + 1), E[t],
            1e3, 1e13, "Pa", "DEM youngsModulus");
    }
    forAll(nu, t)
    {
        inRange("Poisson's ratio of type " + Foam::name(t + 1), nu[t],
            0, 0.4999, "", "DEM poissonsRatio");
    }
}


void Foam::foamDEM::stabilityGuard::checkRelaxationTime
(
    scalar dMin,
    scalar rhoMin
)
{
    using ::foamDEM::correlations::particleRelaxationTime;

    const scalar mu = coupling_.rhoFluid()*coupling_.nuFluid();
    const scalar tauP = particleRelaxationTime(dMin, rhoMin, mu);
    const scalar dtCFD = coupling_.mesh().time().deltaTValue();
    const scalar dtDEM = coupling_.engine().timeStep();

    note
    (
        "particle relaxation time tau_p = " + fmt(tauP) + " s (d = "
      + fmt(dMin) + " m): CFD step / tau_p = " + fmt(dtCFD/tauP)
      + ", DEM step / tau_p = " + fmt(dtDEM/tauP)
    );

    if (coupling_.momentumCouplingType() == "explicit" && dtCFD > tauP)
    {
        refuse
        (
            "explicit momentum coupling with a CFD step " + fmt(dtCFD)
          + " s larger than the particle relaxation time " + fmt(tauP)
          + " s is unstable. Use 'momentumCoupling implicit;' or a CFD step"
            " below " + fmt(tauP) + " s."
        );
    }
    if (coupling_.engine().holdsBodyDrag() && dtCFD > tauP)
    {
        refuse
        (
            "multisphere bodies hold their drag over the coupling interval "
          + fmt(dtCFD) + " s, larger than the particle relaxation time "
          + fmt(tauP) + " s: unstable. Use a CFD step (couplingInterval x"
            " DEM step) below " + fmt(tauP) + " s."
        );
    }
    if (!coupling_.engine().implicitDrag() && dtDEM > tauP)
    {
        refuse
        (
            "the DEM integrates the drag explicitly with a DEM step "
          + fmt(dtDEM) + " s larger than the particle relaxation time "
          + fmt(tauP) + " s: unstable. Set 'dragIntegration implicit;' in "
            "liggghtsCoeffs or a DEM step below " + fmt(tauP) + " s."
        );
    }
}


void Foam::foamDEM::stabilityGuard::checkCellSize(scalar dMax)
{
    // d/h up to which a model is meant to be used (warn above), and the
    // d/h above which it cannot hold a particle at all (refuse): centre
    // puts a particle's whole volume into the one cell of its centre
    const word vfType(coupling_.voidFractionType());
    const scalar handles =
        vfType == "centre" ? 1.0/3.0 : vfType == "divided" ? 1.0 : GREAT;
    const scalar holds = vfType == "centre" ? 1.0 : GREAT;

    // Each particle in the cell that holds it: located in this rank's mesh,
    // and in parallel moved to the rank whose mesh holds it (the DEM and
    // the CFD decompose the domain independently), as in a coupling step
    const fvMesh& mesh = coupling_.mesh();
    exchangePlan plan;
    for (const quantity q :
        {quantity::position, quantity::radius, quantity::id})
    {
        plan.need(q, "stabilityGuard");
    }
    particleData p;
    coupling_.engine().pull(plan, p);
    autoPtr<locateModel> locate
    (
        locateModel::New
        (
            mesh.lookupObject<IOdictionary>("couplingProperties"), mesh
        )
    );
    locate->locate(p);
    if (Pstream::parRun())
    {
        particleTransfer(mesh, coupling_.engine().reach())
            .gather(p, locate(), plan);
    }

    const scalarField& V = mesh.V();
    scalar worstRatio = 0;
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0 && p.radius.size())
        {
            worstRatio =
                max(worstRatio, 2*p.radius[i]/cbrt(V[p.cell[i]]));
        }
    }
    reduce(worstRatio, maxOp<scalar>());

    if (worstRatio > 0)
    {
        note
        (
            "largest particle diameter / local cell size = "
          + fmt(worstRatio) + " (void fraction model " + vfType + ')'
        );
    }
    if (worstRatio > holds*(1 + 1e-6))
    {
        refuse
        (
            "particles up to " + fmt(worstRatio) + " cell sizes across"
            " (d/h, h the cube root of the cell volume) with 'voidFraction "
          + vfType + ";' in " + couplingFile + ": this model puts a"
            " particle's whole volume into the one cell of its centre,"
            " smaller than the particle. Set the keyword voidFraction to a"
            " model that spreads"
            " a particle over the cells it covers: 'divided' (meant for d/h"
            " up to 1) or 'smoothed' (any d/h; smoothedCoeffs {"
            " smoothingLengthInDiameters 1; }), or use cells at least "
          + fmt(dMax) + " m across."
        );
    }
    else if (worstRatio > handles*(1 + 1e-6))
    {
        warn
        (
            "particles up to " + fmt(worstRatio) + " cell sizes across, but"
            " the void fraction model '" + vfType + "' is meant for up to "
          + fmt(handles) + ". Use 'voidFraction smoothed;' (or coarser"
            " cells) so the solid volume spreads over neighbouring cells."
        );
    }
}


void Foam::foamDEM::stabilityGuard::checkDomainSize(scalar dMax)
{
    // The mesh's extent in each direction of the solution (not across an
    // empty or wedge direction), over all ranks
    const fvMesh& mesh = coupling_.mesh();
    const boundBox bounds(mesh.points(), true);
    const vector span(bounds.span());
    const Vector<label>& solutionD = mesh.solutionD();
    scalar smallest = GREAT;
    direction across = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD[d] == 1 && span[d] < smallest)
        {
            smallest = span[d];
            across = d;
        }
    }

    if (dMax > smallest*(1 + 1e-6))
    {
        refuse
        (
            "the largest particle, d = " + fmt(dMax) + " m, is larger than"
            " the CFD domain, which is " + fmt(smallest) + " m across in "
          + vector::componentNames[across] + " (mesh bounds "
          + fmt(bounds.min().x()) + ' ' + fmt(bounds.min().y()) + ' '
          + fmt(bounds.min().z()) + " to " + fmt(bounds.max().x()) + ' '
          + fmt(bounds.max().y()) + ' ' + fmt(bounds.max().z()) + " m): no"
            " void fraction model can hold it. Check the particle diameter"
            " and its units (SI) in the DEM script (or the keyword"
            " particleDiameter of stabilityGuard in " + couplingFile
          + "), and the mesh's size and scale (system/blockMeshDict)."
        );
    }
}


void Foam::foamDEM::stabilityGuard::checkCourant(scalar vMax)
{
    const fvMesh& mesh = coupling_.mesh();
    const scalar dt = mesh.time().deltaTValue();
    const scalar hMin = returnReduce(cbrt(min(mesh.V().field())), minOp<scalar>());
    const scalar uMax = returnReduce(max(mag(coupling_.U().primitiveField())), maxOp<scalar>());

    note
    (
        "Courant numbers at start (velocity x CFD step / smallest cell): fluid "
      + fmt(uMax*dt/hMin) + ", particles " + fmt(vMax*dt/hMin)
    );
    if (vMax*dt/hMin > 1)
    {
        warn
        (
            "the fastest particle crosses " + fmt(vMax*dt/hMin) + " cells per"
            " coupling step: the void fraction jumps between steps. Consider"
            " a smaller CFD step (and couplingInterval)."
        );
    }
}


void Foam::foamDEM::stabilityGuard::checkBoundaryVoidFraction()
{
    // An inflow or outflow patch next to particles whose own void fraction
    // is not 1: a velocity U prescribed there brings eps_f U, not U
    const volScalarField& alpha = coupling_.voidFraction();
    const volVectorField& U = coupling_.U();
    forAll(alpha.boundaryField(), patchi)
    {
        const fvPatchScalarField& ap = alpha.boundaryField()[patchi];
        const fvPatch& patch = ap.patch();
        if (patch.coupled() || isA<wallFvPatch>(patch))
        {
            continue;
        }
        const scalarField aIn(ap.patchInternalField());
        const scalarField& magSf = patch.magSf();
        scalar area = 0, aArea = 0, aInMin = 1;
        forAll(ap, facei)
        {
            if (aIn[facei] < 0.99 && ap[facei] < 1 - 1e-9)
            {
                area += magSf[facei];
                aArea += ap[facei]*magSf[facei];
                aInMin = min(aInMin, aIn[facei]);
            }
        }
        const scalar flux = gSum(U.boundaryField()[patchi] & patch.Sf());
        reduce(area, sumOp<scalar>());
        reduce(aArea, sumOp<scalar>());
        reduce(aInMin, minOp<scalar>());
        if (area > 0)
        {
            const word kind =
                flux < 0 ? "inflow" : flux > 0 ? "outflow" : "flow";
            warn
            (
                patch.name() + ": superficial " + kind + " = "
              + fmt(aArea/area) + " x U on " + pct(area/gSum(magSf))
              + " of the patch (its void fraction is " + ap.type()
              + ", eps down to " + fmt(aInMin) + " in the cells next to"
                " it). For a superficial velocity U give the patch"
                " fixedValue 1 in 0/voidfraction."
            );
        }
    }
}


void Foam::foamDEM::stabilityGuard::check()
{
    using namespace ::foamDEM::correlations;

    const demEngine& engine = coupling_.engine();
    const scalar dtDEM = engine.timeStep();

    // The particles at start-up: diameter, density, type, speed
    exchangePlan plan;
    for (const quantity q : {quantity::position, quantity::velocity,
                             quantity::radius, quantity::density})
    {
        plan.need(q, "stabilityGuard");
    }
    particleData p;
    engine.pull(plan, p);
    const labelList types(engine.particleTypes());
    scalarList E, nu;
    engine.materialProperties(E, nu);

    scalar dMin = GREAT, dMax = 0, rhoMin = GREAT, rhoMax = 0, vMax = 0;
    forAll(p.radius, i)
    {
        dMin = min(dMin, 2*p.radius[i]);
        dMax = max(dMax, 2*p.radius[i]);
        rhoMin = min(rhoMin, p.density[i]);
        rhoMax = max(rhoMax, p.density[i]);
        vMax = max(vMax, mag(p.velocity[i]));
    }
    reduce(dMin, minOp<scalar>());
    reduce(dMax, maxOp<scalar>());
    reduce(rhoMin, minOp<scalar>());
    reduce(rhoMax, maxOp<scalar>());
    reduce(vMax, maxOp<scalar>());

    if (dMax == 0)
    {
        if (dict_.found("particleDiameter") && dict_.found("particleDensity"))
        {
            dMin = dMax = dict_.get<scalar>("particleDiameter");
            rhoMin = rhoMax = dict_.get<scalar>("particleDensity");
            note("no particles at start: checking particleDiameter "
                + fmt(dMin) + " m, particleDensity " + fmt(rhoMin) + " kg/m^3");
        }
        else
        {
            note("no particles at start: particle checks skipped (give"
                " particleDiameter and particleDensity in stabilityGuard)");
        }
    }

    checkRanges(dMin, dMax, rhoMin, rhoMax, E, nu);

    if (dMax > 0 && refusals_.empty() && !engine.movesParticles())
    {
        note("the DEM integrates no particles (frozen bed): contact and"
            " relaxation-time checks skipped");
        checkCellSize(dMax);
        checkDomainSize(dMax);
    }
    else if (dMax > 0 && refusals_.empty())
    {
        // Rayleigh time and Hertz contact time, smallest over particles
        const scalar vImpact = dict_.getOrDefault<scalar>("impactVelocity", 1);
        worst rayleigh, hertz;
        auto material = [&](const scalarList& list, label t, scalar fallback)
        {
            return list.size() ? list[min(t, list.size() - 1)] : fallback;
        };
        const bool perParticle = p.radius.size() > 0 && E.size() && nu.size();
        if (perParticle)
        {
            // A multisphere body touches with its spheres: the radius is
            // that of its smallest sphere, the mass the body's
            const scalarList rc(engine.contactRadii());
            forAll(p.radius, i)
            {
                const scalar Ei = material(E, types[i], 0);
                const scalar nui = material(nu, types[i], 0);
                const scalar m = p.density[i]*p.volume(i);
                rayleigh.take
                (
                    rayleighTimeStep(rc[i], p.density[i], Ei, nui),
                    2*rc[i]
                );
                hertz.take
                (
                    hertzContactTime
                    (
                        m/2, rc[i]/2,
                        effectiveYoungsModulus(Ei, nui, Ei, nui), vImpact
                    ),
                    2*rc[i]
                );
            }
        }
        rayleigh.reduceMin();
        hertz.reduceMin();

        if (rayleigh.value < GREAT)
        {
            const scalar ratio = dtDEM/rayleigh.value;
            const scalar warnAt = dict_.getOrDefault<scalar>("rayleighWarn", 0.2);
            const scalar maxAt = dict_.getOrDefault<scalar>("rayleighMax", 0.3);
            note
            (
                "DEM step " + fmt(dtDEM) + " s = " + pct(ratio)
              + " of the Rayleigh time " + fmt(rayleigh.value) + " s (d = "
              + fmt(rayleigh.d) + " m)"
            );
            const string advice =
                " The largest step within " + pct(warnAt) + " is "
              + fmt(warnAt*rayleigh.value) + " s (set 'timestep' in the DEM"
                " script and couplingInterval so that their product stays"
                " the CFD deltaT), or use a softer Young's modulus.";
            if (ratio > maxAt)
            {
                refuse
                (
                    "DEM step " + fmt(dtDEM) + " s is " + pct(ratio)
                  + " of the Rayleigh time " + fmt(rayleigh.value)
                  + " s, above the limit " + pct(maxAt) + '.' + advice
                );
            }
            else if (ratio > warnAt)
            {
                warn
                (
                    "DEM step " + fmt(dtDEM) + " s is " + pct(ratio)
                  + " of the Rayleigh time." + advice
                );
            }
        }
        if (hertz.value < GREAT)
        {
            const scalar steps = hertz.value/dtDEM;
            const scalar warnAt =
                dict_.getOrDefault<scalar>("hertzStepsWarn", 20);
            const scalar minAt = dict_.getOrDefault<scalar>("hertzStepsMin", 10);
            note
            (
                "Hertz contact time at " + fmt(vImpact) + " m/s: "
              + fmt(hertz.value) + " s = " + fmt(steps) + " DEM steps"
            );
            if (steps < minAt)
            {
                refuse
                (
                    "a contact at the impact velocity " + fmt(vImpact)
                  + " m/s lasts " + fmt(hertz.value) + " s, only "
                  + fmt(steps) + " DEM steps (at least " + fmt(minAt)
                  + " needed). Use a DEM step of at most "
                  + fmt(hertz.value/warnAt) + " s."
                );
            }
            else if (steps < warnAt)
            {
                warn
                (
                    "a contact lasts only " + fmt(steps) + " DEM steps at "
                  + fmt(vImpact) + " m/s (" + fmt(warnAt) + " recommended)."
                );
            }
        }
        if (!perParticle && p.radius.size())
        {
            note("DEM has no youngsModulus/poissonsRatio: contact time"
                " checks skipped");
        }

        checkRelaxationTime(dMin, rhoMin);
        checkCellSize(dMax);
        checkDomainSize(dMax);
    }
    checkCourant(vMax);
    checkBoundaryVoidFraction();

    // Report
    const bool overridden = dict_.getOrDefault("override", false);
    Info<< "foamDEM stability guard:" << nl;
    for (const string& s : report_)
    {
        Info<< "    " << s.c_str() << nl;
    }
    for (const string& s : warnings_)
    {
        WarningInFunction << s.c_str() << endl;
    }
    if (refusals_.size())
    {
        if (overridden)
        {
            Info<< nl
                << "*** STABILITY GUARD OVERRIDDEN (stabilityGuard { override"
                << " true; }): running despite " << refusals_.size()
                << " refusal(s):" << nl;
            for (const string& s : refusals_)
            {
                Info<< "***   " << s.c_str() << nl;
            }
            Info<< endl;
        }
        else
        {
            FatalIOErrorInFunction(dict_)
                << "The stability guard refuses this case:" << nl;
            for (const string& s : refusals_)
            {
                FatalIOError << "  - " << s.c_str() << nl;
            }
            FatalIOError
                << "Experts can run anyway with the keyword override:"
                << " stabilityGuard { override true; } in "
                << couplingFile.c_str() << '.' << exit(FatalIOError);
        }
    }
    Info<< endl;
}
