#include "demCoupling.H"
#include "uniformDimensionedFields.H"
#include "zeroGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"
#include "wallPolyPatch.H"
#include "processorFvPatch.H"
#include "fvmSup.H"
#include "fvc.H"
#include "stabilityGuard.H"

#include <chrono>

const Foam::Enum<Foam::foamDEM::demCoupling::modelTypes>
Foam::foamDEM::demCoupling::modelTypeNames
({
    { modelTypes::A, "A" },
    { modelTypes::B, "B" },
});


namespace
{
    //- Adds the wall time of its scope to a timer
    class scopedTimer
    {
        Foam::scalar& total_;
        std::chrono::steady_clock::time_point start_;
    public:
        scopedTimer(Foam::scalar& total)
        :
            total_(total),
            start_(std::chrono::steady_clock::now())
        {}
        ~scopedTimer()
        {
            total_ += std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - start_
            ).count();
        }
    };

    //- The lowest rank's non-empty message, on every rank (collective)
    Foam::string firstMessageOverRanks(const Foam::string& local)
    {
        Foam::List<Foam::string> all(Foam::Pstream::nProcs());
        all[Foam::Pstream::myProcNo()] = local;
        Foam::Pstream::gatherList(all);
        Foam::Pstream::scatterList(all);
        for (const Foam::string& s : all)
        {
            if (s.size()) return s;
        }
        return Foam::string();
    }

    Foam::scalar readFluidProperty
    (
        const Foam::dictionary& dict,
        const Foam::word& name,
        const Foam::dimensionSet& dims
    )
    {
        const Foam::scalar value =
            Foam::dimensionedScalar(name, dims, dict).value();
        if (value <= 0)
        {
            FatalIOErrorInFunction(dict)
                << name << " must be positive, got " << value
                << Foam::exit(Foam::FatalIOError);
        }
        return value;
    }
}


// * * * * * * * * * * * * * * * Private functions  * * * * * * * * * * * * //

Foam::foamDEM::demCoupling::modelTypes
Foam::foamDEM::demCoupling::readModelType(const dictionary& dict)
{
    const word name(dict.get<word>("modelType"));
    if (!modelTypeNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown modelType " << name << nl << nl
            << "Valid modelType types :" << nl << modelTypeNames.sortedToc()
            << exit(FatalIOError);
    }
    return modelTypeNames[name];
}


Foam::wordList Foam::foamDEM::demCoupling::alphaPatchTypes
(
    const volVectorField& U
)
{
    const polyBoundaryMesh& patches = U.mesh().boundaryMesh();
    wordList types(patches.size(), zeroGradientFvPatchScalarField::typeName);
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const fvPatchVectorField& Up = U.boundaryField()[patchi];
        if (polyPatch::constraintType(pp.type()))
        {
            types[patchi] = pp.type();
        }
        else if
        (
            !isA<wallPolyPatch>(pp)
         && Up.fixesValue()
         && Up.type() != "noSlip"
        )
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
    }
    return types;
}


Foam::tmp<Foam::volScalarField>
Foam::foamDEM::demCoupling::createVoidFraction(const volVectorField& U)
{
    const fvMesh& mesh = U.mesh();
    // Not registered: the coupling's own field (alpha_) takes the name
    IOobject io
    (
        "voidfraction",
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );

    tmp<volScalarField> talpha;
    if (io.typeHeaderOk<volScalarField>(true))
    {
        Info<< "    Void fraction boundary conditions from "
            << mesh.time().timeName()/io.name() << ":" << nl;
        talpha = tmp<volScalarField>::New(io, mesh);
        if (talpha().dimensions() != dimless)
        {
            FatalErrorInFunction
                << talpha().objectPath() << ": the void fraction must be"
                << " dimensionless ([0 0 0 0 0 0 0]), got "
                << talpha().dimensions() << exit(FatalError);
        }
    }
    else
    {
        Info<< "    Void fraction boundary conditions: no "
            << mesh.time().timeName()/io.name() << ", default (fixedValue 1"
            << " where U is prescribed, zeroGradient on walls and outlets):"
            << nl;
        io.readOpt() = IOobject::NO_READ;
        talpha = tmp<volScalarField>::New
        (
            io,
            mesh,
            dimensionedScalar("one", dimless, 1),
            alphaPatchTypes(U)
        );
    }

    // Processor patches are not the user's; the others exist on every rank
    for (const fvPatchScalarField& pf : talpha().boundaryField())
    {
        if (isA<processorFvPatch>(pf.patch()))
        {
            continue;
        }
        Info<< "        " << pf.patch().name() << ": " << pf.type();
        const label n = returnReduce(pf.size(), sumOp<label>());
        if (pf.fixesValue() && n > 0)
        {
            Info<< " (mean " << gSum(pf)/n << ")";
        }
        Info<< nl;
    }
    return talpha;
}


void Foam::foamDEM::demCoupling::checkTimeSteps() const
{
    const scalar dtCFD = mesh_.time().deltaTValue();
    const scalar dtDEM = engine_->timeStep();
    const scalar dtCoupled = dtDEM*couplingInterval_;

    if (mag(dtCoupled - dtCFD) > 1e-9*dtCFD)
    {
        FatalIOErrorInFunction(dict_)
            << "Inconsistent time steps: DEM time step " << dtDEM
            << " s x couplingInterval " << couplingInterval_ << " = "
            << dtCoupled << " s, but the CFD deltaT (system/controlDict) is "
            << dtCFD << " s." << nl
            << "    Set couplingInterval to " << dtCFD/dtDEM
            << " (if a whole number), or change deltaT or the DEM timestep."
            << exit(FatalIOError);
    }
    if (mesh_.time().controlDict().getOrDefault("adjustTimeStep", false))
    {
        FatalIOErrorInFunction(mesh_.time().controlDict())
            << "adjustTimeStep yes is not supported: the CFD step must stay"
            << " couplingInterval DEM steps long." << exit(FatalIOError);
    }
}


void Foam::foamDEM::demCoupling::checkGravity() const
{
    const vector gDEM = engine_->gravity();
    if (mag(gDEM - g_) > 1e-6*max(mag(g_), scalar(1)))
    {
        FatalIOErrorInFunction(dict_)
            << "Gravity differs between the CFD and the DEM: constant/g is "
            << g_ << " m/s^2, the DEM's fix gravity gives " << gDEM
            << " m/s^2. Make them equal." << exit(FatalIOError);
    }
}


void Foam::foamDEM::demCoupling::checkForceModels() const
{
    using kinds = forceModel::forceKind;
    wordList drags;
    bool hasPressureGradient = false, hasBuoyancy = false;
    wordList refusedInB;
    for (const forceModel& f : forces_)
    {
        switch (f.kind())
        {
            case kinds::drag: drags.append(f.type()); break;
            case kinds::pressureGradient:
                hasPressureGradient = true;
                refusedInB.append(f.type());
                break;
            case kinds::viscous: refusedInB.append(f.type()); break;
            case kinds::buoyancy: hasBuoyancy = true; break;
            default: break;
        }
    }

    if (drags.size() > 1)
    {
        FatalIOErrorInFunction(dict_)
            << "forceModels lists more than one drag law: " << drags << nl
            << "    Keep one of them." << exit(FatalIOError);
    }
    if (modelType_ == modelTypes::A && !hasPressureGradient)
    {
        FatalIOErrorInFunction(dict_)
            << "modelType A: the fluid sees -eps grad(p), so the particles"
            << " need the pressure-gradient force." << nl
            << "    Add pressureGradient to forceModels, or use modelType B."
            << exit(FatalIOError);
    }
    if (modelType_ == modelTypes::B && refusedInB.size())
    {
        FatalIOErrorInFunction(dict_)
            << "modelType B: the drag (divided by eps) already carries the"
            << " pressure-gradient and viscous forces, but forceModels also"
            << " lists " << refusedInB << '.' << nl
            << "    Remove them from forceModels, or use modelType A."
            << exit(FatalIOError);
    }
    if (drags.empty())
    {
        WarningInFunction
            << "No drag law in forceModels " << dict_.get<wordList>("forceModels")
            << ": the particles feel no drag." << endl;
    }
    if (!hasBuoyancy)
    {
        WarningInFunction
            << "No buoyancy force (archimedes) in forceModels: the pressure"
            << " excludes the hydrostatic part, so the particles feel no"
            << " buoyancy. Fine for gas-solid flows where rho_f << rho_p."
            << endl;
    }
}


void Foam::foamDEM::demCoupling::reportMomentumBalance() const
{
    // What the particles get through the coupled terms ...
    const particleData& p = particles_;
    vector onParticles(Zero);
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            onParticles += p.dragCoeff[i]*(p.fluidVelocity[i] - p.velocity[i])
                + p.coupledForce[i];
        }
    }
    reduce(onParticles, sumOp<vector>());

    // ... and what the fluid gets, at the same instant
    const vector onFluid = totalFluidSource(U_);
    const scalar scale = max(mag(onParticles), max(mag(onFluid), VSMALL));

    Info<< "foamDEM momentum balance: on particles " << onParticles
        << " N, on fluid " << onFluid << " N, relative mismatch "
        << mag(onParticles + onFluid)/scale << endl;
}


void Foam::foamDEM::demCoupling::checkParticlesFinite()
{
    const particleData& p = particles_;
    // Component by component (no square root per particle and quantity)
    struct finiteCheck
    {
        bool operator()(const scalar x) const { return !std::isfinite(x); }
        bool operator()(const vector& x) const
        {
            return
                !std::isfinite(x.x()) || !std::isfinite(x.y())
             || !std::isfinite(x.z());
        }
    } bad;

    string found;
    forAll(p.cell, i)
    {
        const char* what = nullptr;
        if (bad(p.position[i])) what = "position";
        else if (p.velocity.size() && bad(p.velocity[i])) what = "velocity";
        else if (p.radius.size() && bad(p.radius[i])) what = "radius";
        else if (p.cell[i] < 0) continue;
        else if (bad(p.fluidVelocity[i])) what = "fluid velocity at the particle";
        else if (bad(p.voidFraction[i])) what = "void fraction at the particle";
        else if (bad(p.dragCoeff[i])) what = "drag coefficient K_p";
        else if (bad(p.coupledForce[i]) || bad(p.uncoupledForce[i]))
        {
            what = "explicit fluid force";
        }
        if (what)
        {
            found = string("particle id ")
              + Foam::name(p.id.size() ? p.id[i] : i) + " in cell "
              + Foam::name(p.cell[i]) + " of rank "
              + Foam::name(Pstream::myProcNo()) + ": " + what + " is not finite";
            break;
        }
    }

    // The first rank with a bad particle reports it; all ranks stop
    if (!returnReduce(found.size() > 0, orOp<bool>())) return;

    stopWithLastGoodState
    (
        "NaN/Inf at t = " + mesh_.time().timeName() + " s: "
      + firstMessageOverRanks(found) + '.'
    );
}


void Foam::foamDEM::demCoupling::checkFluidFinite
(
    volVectorField& U,
    volScalarField& p
)
{
    label badCell = -1;
    word what;
    forAll(U, celli)
    {
        if (!std::isfinite(mag(U[celli]))) { badCell = celli; what = "U"; break; }
        if (!std::isfinite(p[celli])) { badCell = celli; what = "p"; break; }
    }
    if (!returnReduce(badCell >= 0, orOp<bool>())) return;

    string where;
    if (badCell >= 0)
    {
        where =
            what + " in cell " + Foam::name(badCell) + " (centre "
          + Foam::name(mesh_.C()[badCell].x()) + ' '
          + Foam::name(mesh_.C()[badCell].y()) + ' '
          + Foam::name(mesh_.C()[badCell].z()) + ") of rank "
          + Foam::name(Pstream::myProcNo());
    }
    where = firstMessageOverRanks(where);

    // Back to the last good step
    U == U.oldTime();
    p == p.oldTime();
    stopWithLastGoodState
    (
        "NaN/Inf in the fluid solution at t = " + mesh_.time().timeName()
      + " s: " + where + '.'
    );
}


void Foam::foamDEM::demCoupling::stopWithLastGoodState(const string& message)
{
    Time& runTime = const_cast<Time&>(mesh_.time());
    const scalar tFailed = runTime.value();
    const scalar dt = runTime.deltaTValue();
    const fileName restart
    (
        runTime.globalPath()/"DEM/post/restart.atFailure_" + runTime.timeName()
    );
    engine_->writeRestart(restart);

    // U and p hold the last completed step (the fluid check restores them
    // first); the void fraction goes back to that step too. Written under
    // that step's time; the other coupling fields are not written.
    alpha_ == alpha_.oldTime();
    runTime.setTime(tFailed - dt, runTime.timeIndex() - 1);
    U_.write();
    p_.write();
    alpha_.write();

    // The DEM restart of the same step (failureDEMRestart lastGoodStep),
    // where a write time's restart goes, so that the fluid fields and the
    // DEM state of that time are found together
    string paired;
    if (restartEveryStep_)
    {
        const fileName target
        (
            demEngine::restartFile(runTime, runTime.timeName())
        );
        label slot = -1;
        for (label k = 0; k < 2; ++k)
        {
            if (mag(stepRestartTime_[k] - runTime.value()) < 1e-6*dt)
            {
                slot = k;
            }
        }
        bool found = false;
        if (slot >= 0)
        {
            // A step's own file is moved there, over whatever an earlier
            // run left; a write time's is the target itself (gone if
            // purgeWrite removed it)
            bool there = false;
            if (Pstream::master())
            {
                const fileName from(stepRestart_[slot]);
                there = from == target ? isFile(target) : mv(from, target);
                if (from != target)
                {
                    // Each file beside it goes too; one the step has not
                    // (bodies) is not left from an earlier run
                    const List<fileName> a(engine_->restartCompanions(from));
                    const List<fileName> b(engine_->restartCompanions(target));
                    forAll(a, i)
                    {
                        if (!isFile(a[i]) || !mv(a[i], b[i]))
                        {
                            rm(b[i]);
                        }
                    }
                }
            }
            // The other ranks wait for the move before the exit
            found = returnReduce(there, orOp<bool>());
        }
        paired =
            found
          ? ", the DEM state of that step to " + target
          : string
            (
                slot < 0
              ? " (no DEM restart of that step: it was the run's start)"
              : " (no DEM restart of that step: its file is gone)"
            );
    }

    // The particles of the same step: a failure in the particles at t is
    // found before this step's copy (the newest is t - dt), a failure in
    // the fluid after it (the older one is t - dt). The same on all ranks.
    const scalar tGood = runTime.value();
    const particleData* good = nullptr;
    if (mag(goodNowTime_ - tGood) < 1e-6*dt) good = &goodNow_;
    else if (mag(goodBeforeTime_ - tGood) < 1e-6*dt) good = &goodBefore_;
    string particles;
    if (good)
    {
        for (particleOutput& o : outputs_)
        {
            o.write(*good, plan_);
        }
        particles = " and the particles (particle outputs)";
    }
    else
    {
        particles =
            keepLastGood_
          ? " (no particles: the failed step was the run's first)"
          : " (no particles: writeParticlesAtFailure is false)";
    }

    FatalErrorInFunction
        << message.c_str() << nl
        << "    The fluid fields" << particles.c_str()
        << " of the last good step were written to time "
        << runTime.timeName() << paired.c_str()
        << "; the DEM state at the failure to " << restart << '.' << nl
        << "    Check the stability guard's report at start-up, and consider"
        << " a smaller time step or implicit coupling." << exit(FatalError);
}


Foam::tmp<Foam::volScalarField>
Foam::foamDEM::demCoupling::pressureWeight() const
{
    if (modelType_ == modelTypes::A)
    {
        return tmp<volScalarField>::New("pressureWeight", alpha_);
    }
    return tmp<volScalarField>::New
    (
        IOobject("pressureWeight", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar("one", dimless, 1)
    );
}


Foam::tmp<Foam::volScalarField>
Foam::foamDEM::demCoupling::pressureConductance
(
    const volScalarField& rAU
) const
{
    return alpha_*pressureWeight()*rAU;
}


const Foam::volVectorField&
Foam::foamDEM::demCoupling::updatePressureGradient(const volScalarField& D)
{
    gradp_ = pressureScheme_->grad(p_, D);
    return gradp_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::foamDEM::demCoupling::demCoupling
(
    const volVectorField& U,
    const volScalarField& p
)
:
    mesh_(U.mesh()),
    U_(U),
    p_(p),
    dict_
    (
        IOobject
        (
            "couplingProperties",
            mesh_.time().constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    modelType_(readModelType(dict_)),
    rhoFluid_(0),
    nuFluid_(0),
    g_(Zero),
    couplingInterval_(dict_.get<label>("couplingInterval")),
    outputs_(particleOutput::New(mesh_, dict_)),
    alpha_
    (
        IOobject
        (
            "voidfraction",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        createVoidFraction(U)
    ),
    Ksl_
    (
        IOobject("Ksl", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar("zero", dimDensity/dimTime, Zero)
    ),
    Us_
    (
        IOobject("UsDrag", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector("zero", dimVelocity, Zero)
    ),
    averaging_(mesh_),
    UsAvg_
    (
        IOobject
        (
            "Us",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedVector("zero", dimVelocity, Zero)
    ),
    averageEveryStep_(false),
    fExplicit_
    (
        IOobject("fExplicit", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector("zero", dimForce/dimVolume, Zero)
    ),
    gradp_
    (
        IOobject
        (
            "gradp",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        fvc::grad(p)
    ),
    nOutside_(0),
    checkMomentumBalance_(dict_.getOrDefault("checkMomentumBalance", false)),
    fluidImpulse_(Zero),
    haveFluidImpulse_(false),
    reportedArrays_(false),
    logExchange_(dict_.getOrDefault("logExchange", false)),
    progress_(mesh_.time(), dict_),
    writeDEMRestart_(dict_.getOrDefault("writeDEMRestart", true)),
    keepLastGood_(dict_.getOrDefault("writeParticlesAtFailure", true)),
    goodNowTime_(-GREAT),
    goodBeforeTime_(-GREAT),
    restartEveryStep_(false),
    stepRestartTime_(-GREAT),
    stepRestartSlot_(0),
    skipPush_(false)
{
    {
        const wordList choices({"failedStep", "lastGoodStep"});
        const word choice
        (
            dict_.getOrDefault<word>("failureDEMRestart", choices[0])
        );
        if (!choices.found(choice))
        {
            FatalIOErrorInFunction(dict_)
                << "Unknown failureDEMRestart '" << choice << "' in "
                << dict_.name() << nl << nl
                << "Valid failureDEMRestart types :" << nl << choices
                << exit(FatalIOError);
        }
        restartEveryStep_ = choice == "lastGoodStep";
    }

    Info<< nl << "foamDEM: CFD-DEM coupling, model type "
        << modelTypeNames[modelType_] << endl;

    if (couplingInterval_ < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "couplingInterval must be a whole number >= 1, got "
            << couplingInterval_ << exit(FatalIOError);
    }

    {
        const IOdictionary transport
        (
            IOobject
            (
                "transportProperties",
                mesh_.time().constant(),
                mesh_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        rhoFluid_ = readFluidProperty(transport, "rho", dimDensity);
        nuFluid_ = readFluidProperty(transport, "nu", dimViscosity);

        const uniformDimensionedVectorField g
        (
            IOobject
            (
                "g",
                mesh_.time().constant(),
                mesh_,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        g_ = g.value();
    }

    readPressureGradient();

    // Models
    engine_ = demEngine::New(mesh_.time(), dict_);
    locate_ = locateModel::New(dict_, mesh_);
    voidFraction_ = voidFractionModel::New(dict_, mesh_);

    const wordList forceNames(dict_.get<wordList>("forceModels"));
    forces_.setSize(forceNames.size());
    forAll(forceNames, i)
    {
        forces_.set(i, forceModel::New(forceNames[i], dict_, *this));
    }
    momentum_ = momentumCouplingModel::New(dict_);
    pressureScheme_ = pressureScheme::New(mesh_, dict_);
    checkForceModels();
    {
        bool pressureGradientForce = false;
        for (const forceModel& f : forces_)
        {
            pressureGradientForce =
                pressureGradientForce || f.type() == "pressureGradient";
        }
        undisturbed_.reset
        (
            new undisturbedVelocity
            (
                dict_, mesh_, voidFraction_(), rhoFluid_, nuFluid_,
                modelType_ == modelTypes::A && pressureGradientForce
            )
        );
    }
    if (Pstream::parRun())
    {
        transfer_.reset(new particleTransfer(mesh_, engine_->reach()));
        const label nNeighbours = returnReduce
        (
            max(transfer_->sendProcs().size(), transfer_->recvProcs().size()),
            maxOp<label>()
        );
        Info<< "foamDEM exchange: point-to-point with neighbouring ranks"
            << " only (at most " << nNeighbours << " of "
            << Pstream::nProcs() - 1 << " other ranks)" << endl;
        if (logExchange_)
        {
            Pout<< "foamDEM exchange neighbours: sends to "
                << transfer_->sendProcs() << ", receives from "
                << transfer_->recvProcs() << endl;
        }
    }

    // What to exchange: only what the selected models need
    locate_->addRequirements(plan_);
    voidFraction_->addRequirements(plan_);
    averaging_.addRequirements(plan_);
    for (const forceModel& f : forces_)
    {
        f.addRequirements(plan_);
    }
    momentum_->addRequirements(plan_);
    for (const particleOutput& o : outputs_)
    {
        o.addRequirements(plan_);
        averageEveryStep_ = averageEveryStep_ || o.readsCouplingFields();
    }
    plan_.print();
    Info<< "    Us (volume-weighted particle velocity, output only): averaged "
        << (averageEveryStep_
          ? "at every coupling step (a particle output reads it)"
          : "at write times only") << endl;
    engine_->prepare(plan_);

    checkTimeSteps();
    checkGravity();

    Info<< "    DEM time step " << engine_->timeStep() << " s, "
        << couplingInterval_ << " DEM steps per CFD step, "
        << engine_->nGlobal() << " particles" << nl << endl;

    // Coupling terms for the first DEM interval. A DEM continued from the
    // library's restart holds the ones the writing run pushed at that time
    // (computed from the fluid of the step before it): they are kept, so
    // that the continued run repeats the straight one. Bodies whose terms
    // the restart does not carry get new ones, from this time's fields
    if (engine_->continued() && engine_->restartHoldsCouplingTerms())
    {
        Info<< "    continued run: the DEM keeps the coupling terms of its"
            << " restart for the first interval" << endl;
        skipPush_ = true;
    }
    else if (engine_->continued())
    {
        Info<< "    continued run: the restart does not carry the bodies'"
            << " coupling terms; new ones from the fields of the start time"
            << " for the first interval" << endl;
    }
    update();
    skipPush_ = false;
    alpha_.oldTime();

    stabilityGuard(*this, dict_.subOrEmptyDict("stabilityGuard")).check();
    progress_.start();
}


Foam::foamDEM::demCoupling::~demCoupling()
{
    const timers& t = timers_;
    const scalar coupling =
        t.pull + t.locate + t.transfer + t.voidFraction + t.forces + t.push;
    Info<< nl << "foamDEM timing [s]: DEM " << t.dem
        << ", coupling " << coupling << " (pull " << t.pull
        << ", locate " << t.locate << ", transfer " << t.transfer
        << ", void fraction " << t.voidFraction
        << ", forces " << t.forces << ", push " << t.push
        << "), particle output " << t.output << endl;
    const labelPair nb(engine_->neighbourBuilds());
    if (nb.first() >= 0)
    {
        Info<< "foamDEM DEM neighbour-list builds: " << nb.first()
            << " (dangerous " << nb.second() << ")" << endl;
    }
    if (transfer_ && transfer_->nAllRanks())
    {
        // The same on every rank (decided by a reduction)
        Info<< "foamDEM exchange: " << transfer_->nAllRanks()
            << " coupling step(s) exchanged with all ranks (particles"
            << " outside their DEM rank's reach)" << endl;
    }
    progress_.summary(splitSoFar());
}


void Foam::foamDEM::demCoupling::readPressureGradient()
{
    // Written with the fields: a continued run reads the gradient of the
    // last pressure correction, the one the run that wrote it gave the
    // particles at the next step (fvc::grad(p) is not the conductance-
    // consistent gradient of the pressure scheme)
    IOobject io
    (
        "gradp",
        mesh_.time().timeName(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (io.typeHeaderOk<volVectorField>(true))
    {
        gradp_ == volVectorField(io, mesh_);
        Info<< "    particles' pressure gradient read from "
            << mesh_.time().timeName() << "/gradp" << endl;
    }
}


void Foam::foamDEM::demCoupling::writeStepRestart()
{
    // The start time's DEM state is the run's start itself (a fresh run's
    // packing, or the restart a continued run read): not kept, so that a
    // stop in the first step leaves no restart at the start time, from
    // which a rerun would continue
    const Time& runTime = mesh_.time();
    if (runTime.timeIndex() == runTime.startTimeIndex())
    {
        return;
    }

    // The slot not holding the newest: the older one is overwritten
    const label slot = 1 - stepRestartSlot_;
    stepRestartTime_[slot] = runTime.value();
    stepRestartSlot_ = slot;
    if (writeDEMRestart_ && runTime.writeTime())
    {
        // This time's own restart is written already; nothing to move at
        // a stop
        stepRestart_[slot] =
            demEngine::restartFile(runTime, runTime.timeName());
        return;
    }
    stepRestart_[slot] =
        runTime.globalPath()/"DEM"/"restart"
       /("lastGoodStep." + Foam::name(slot) + ".restart");
    engine_->writeRestart(stepRestart_[slot]);
}


void Foam::foamDEM::demCoupling::writeDEMRestart()
{
    const Time& runTime = mesh_.time();
    const fileName file(demEngine::restartFile(runTime, runTime.timeName()));
    engine_->writeRestart(file);
    writtenRestarts_.push(file);

    // Rotated with the fields, as Time does for purgeWrite: the newest N
    // restarts this run wrote are kept
    const label purge =
        runTime.controlDict().getOrDefault<label>("purgeWrite", 0);
    if (purge > 0 && writtenRestarts_.size() > label(purge))
    {
        const fileName oldest(writtenRestarts_.pop());
        if (Pstream::master())
        {
            rm(oldest);
            for (const fileName& f : engine_->restartCompanions(oldest))
            {
                rm(f);
            }
        }
    }
}


Foam::foamDEM::runProgress::split
Foam::foamDEM::demCoupling::splitSoFar() const
{
    const timers& t = timers_;
    runProgress::split s;
    s.dem = t.dem;
    s.coupling =
        t.pull + t.locate + t.transfer + t.voidFraction + t.forces + t.push;
    s.output = t.output;
    return s;
}


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * * //

void Foam::foamDEM::demCoupling::update()
{
    {
        scopedTimer timer(timers_.pull);
        engine_->pull(plan_, particles_);
    }

    label nOutside = 0;
    {
        scopedTimer timer(timers_.locate);
        locate_->beginStep();
        nOutside = locate_->locate(particles_);
    }
    if (transfer_)
    {
        // Particles whose cell is on another rank go there
        scopedTimer timer(timers_.transfer);
        nOutside = transfer_->gather(particles_, locate_(), plan_);
    }
    {
        if (nOutside > 0 && nOutside != nOutside_)
        {
            WarningInFunction
                << nOutside << " particle(s) not found in the CFD mesh at t = "
                << mesh_.time().timeName() << " s: they get no fluid force"
                << " and do not count in the void fraction." << endl;
        }
        nOutside_ = nOutside;
    }

    {
        scopedTimer timer(timers_.voidFraction);
        voidFraction_->compute(particles_, alpha_);
        if (averageEveryStep_ || mesh_.time().writeTime())
        {
            averaging_.average(particles_, voidFraction_(), UsAvg_);
        }
    }

    {
        scopedTimer timer(timers_.forces);
        particleData& p = particles_;
        // u_f at the particles (the cell's U, read with the void
        // fraction's kernel, or interpolated), then the forces, with the
        // undisturbed u_f if the self-induced velocity is corrected
        undisturbed_->read(U_, alpha_, p);
        undisturbed_->evaluate(p, forces_);

        const label nCells = mesh_.nCells();
        scalarField sumK(nCells, Zero);
        vectorField sumKv(nCells, Zero);
        vectorField forceOnFluid(nCells, Zero);
        momentum_->distribute
        (
            p, sumK, sumKv, forceOnFluid,
            undisturbed_->spreads() ? &voidFraction_->cellWeights() : nullptr
        );
        if (momentum_->type() == "implicit")
        {
            // The fluid's implicit term is -K_p (u - v) at the velocity
            // read; the rest of -K_p (u_u - v) is explicit
            undisturbed_->addCorrectionSource(p, forceOnFluid);
        }
        undisturbed_->smooth(sumK, sumKv, forceOnFluid);

        const scalarField& V = mesh_.V();
        Ksl_.primitiveFieldRef() = sumK/V;
        forAll(sumK, c)
        {
            Us_[c] = sumK[c] > 0 ? sumKv[c]/sumK[c] : vector::zero;
        }
        fExplicit_.primitiveFieldRef() = forceOnFluid/V;
        Ksl_.correctBoundaryConditions();
        Us_.correctBoundaryConditions();
        fExplicit_.correctBoundaryConditions();
    }

    // Particles held here, including those moved from other ranks
    checkParticlesFinite();
    if (checkMomentumBalance_)
    {
        reportMomentumBalance();
    }
    if (keepLastGood_)
    {
        // This step's particles for a stop in its fluid solution or in the
        // next step's particles (stopWithLastGoodState)
        scopedTimer timer(timers_.output);
        std::swap(goodBefore_, goodNow_);
        std::swap(goodBeforeTime_, goodNowTime_);
        goodNow_.copyForOutput(particles_);
        goodNowTime_ = mesh_.time().value();
    }
    if (mesh_.time().writeTime())
    {
        scopedTimer timer(timers_.output);
        for (particleOutput& o : outputs_)
        {
            o.write(particles_, plan_);
        }
    }

    if (transfer_)
    {
        scopedTimer timer(timers_.transfer);
        transfer_->scatterBack(particles_, plan_);
        if (logExchange_)
        {
            Pout<< "foamDEM exchange: DEM particles " << particles_.size()
                << ", sent " << transfer_->nSent()
                << ", received " << transfer_->nReceived()
                << ", bytes sent " << transfer_->bytesSent()
                << ", to ranks " << transfer_->lastTo()
                << ", from ranks " << transfer_->lastFrom() << endl;
        }
    }
    if (!skipPush_)
    {
        scopedTimer timer(timers_.push);
        engine_->push(plan_, particles_);
    }
    if (writeDEMRestart_ && mesh_.time().writeTime())
    {
        scopedTimer timer(timers_.output);
        writeDEMRestart();
    }
    if (restartEveryStep_)
    {
        scopedTimer timer(timers_.output);
        writeStepRestart();
    }
    if (!reportedArrays_)
    {
        // What the first exchange allocated (master's particles)
        Info<< "foamDEM particle arrays after the first exchange: "
            << particles_.describeArrays().c_str() << endl;
        reportedArrays_ = true;
    }
}


void Foam::foamDEM::demCoupling::evolve()
{
    // Impulse balance: measured on the DEM side, from the particles' total
    // momentum before and after the interval, less gravity's and the
    // uncoupled forces' impulse (their reaction is not in the fluid's
    // source); the coupled forces are held over the interval, so the held
    // values give that impulse
    progress_.step(splitSoFar());

    vector P0(Zero), uncoupled(Zero);
    if (checkMomentumBalance_)
    {
        P0 = engine_->totalMomentum();
        const particleData& p = particles_;
        forAll(p.cell, i)
        {
            if (p.cell[i] >= 0) uncoupled += p.uncoupledForce[i];
        }
        reduce(uncoupled, sumOp<vector>());
    }
    {
        scopedTimer timer(timers_.dem);
        engine_->advance(couplingInterval_);
    }
    if (checkMomentumBalance_)
    {
        const scalar dt = couplingInterval_*engine_->timeStep();
        const vector Jp =
            engine_->totalMomentum() - P0
          - (engine_->totalMass()*engine_->gravity() + uncoupled)*dt;
        if (haveFluidImpulse_)
        {
            const scalar scale =
                max(mag(Jp), max(mag(fluidImpulse_), VSMALL));
            Info<< "foamDEM impulse balance: particles received " << Jp
                << " N s over the DEM interval, the fluid " << fluidImpulse_
                << " N s in its step, relative mismatch "
                << mag(Jp + fluidImpulse_)/scale << endl;
        }
    }
    update();
}


void Foam::foamDEM::demCoupling::measureFluidImpulse(const volVectorField& U)
{
    if (!checkMomentumBalance_) return;
    fluidImpulse_ = mesh_.time().deltaTValue()*totalFluidSource(U);
    haveFluidImpulse_ = true;
}


Foam::tmp<Foam::fvVectorMatrix>
Foam::foamDEM::demCoupling::momentumSource(volVectorField& U) const
{
    const dimensionedScalar rho("rho", dimDensity, rhoFluid_);
    const volScalarField KByRho(Ksl_/rho);
    return
    (
        fvm::Sp(-KByRho, U)
      + KByRho*Us_
      + fExplicit_/rho
    );
}


Foam::vector Foam::foamDEM::demCoupling::totalFluidSource
(
    const volVectorField& U
) const
{
    const scalarField& V = mesh_.V();
    return gSum
    (
        (Ksl_.primitiveField()*(Us_.primitiveField() - U.primitiveField())
      + fExplicit_.primitiveField())*V
    );
}
