#include "liggghtsEngine.H"
#include "orientationKinematics.H"
#include "addToRunTimeSelectionTable.H"
#include "Pstream.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <mpi.h>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

// LIGGGHTS
#include "lammps.h"
#include "input.h"
#include "atom.h"
#include "update.h"
#include "domain.h"
#include "neighbor.h"
#include "modify.h"
#include "fix.h"
#include "write_restart.h"
#include "fix_gravity.h"
#include "fix_property_global.h"
#include "fix_property_atom.h"
#include "fix_multisphere.h"
#include "fix_neighlist_mesh.h"
#include "multisphere.h"
#include "custom_value_tracker.h"
#include "scalar_container.h"
#include "vector_container.h"

#include "liftTorqueCorrelations.H"
#include "multisphereBodies.H"
#include <stdexcept>

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(liggghtsEngine, 0);
    addToRunTimeSelectionTable(demEngine, liggghtsEngine, dictionary);
}
}


// * * * * * * * * * * * * * Error context on exit  * * * * * * * * * * * * //

namespace
{
    // LIGGGHTS reports errors by printing them and calling exit(1). While a
    // LIGGGHTS call is under way these hold what foamDEM was doing, so that
    // the exit handler can say it.
    std::string liggghtsContext;
    std::string liggghtsLog;
    bool liggghtsMaster = true;

    void reportLiggghtsExit()
    {
        if (liggghtsContext.empty() || !liggghtsMaster) return;

        // The error line itself was echoed when LIGGGHTS wrote it
        std::fprintf
        (
            stderr,
            "\n--> foamDEM FATAL ERROR: LIGGGHTS stopped with an error while "
            "%s.\n    Full LIGGGHTS output: %s\n",
            liggghtsContext.c_str(), liggghtsLog.c_str()
        );
        std::fflush(stderr);
    }

    // Rank 0's LIGGGHTS output: a stream that writes to the log file and
    // echoes ERROR lines to stderr at once, with foamDEM's context. An error
    // met on one rank ends in MPI_Abort, which runs no exit handler.
    struct teeCookie
    {
        FILE* log;
        std::string pending;
    };

    ssize_t teeWrite(void* cookie, const char* buf, size_t size)
    {
        teeCookie& c = *static_cast<teeCookie*>(cookie);
        std::fwrite(buf, 1, size, c.log);
        std::fflush(c.log);
        c.pending.append(buf, size);
        size_t eol;
        while ((eol = c.pending.find('\n')) != std::string::npos)
        {
            const std::string line(c.pending, 0, eol);
            if (line.find("ERROR") != std::string::npos)
            {
                std::fprintf
                (
                    stderr, "\n--> foamDEM: LIGGGHTS error%s%s:\n    %s\n",
                    liggghtsContext.empty() ? "" : " while ",
                    liggghtsContext.c_str(), line.c_str()
                );
                std::fflush(stderr);
            }
            c.pending.erase(0, eol + 1);
        }
        return ssize_t(size);
    }

    int teeClose(void* cookie)
    {
        teeCookie* c = static_cast<teeCookie*>(cookie);
        const int status = std::fclose(c->log);
        delete c;
        return status;
    }

    struct contextGuard
    {
        contextGuard(const std::string& what) { liggghtsContext = what; }
        ~contextGuard() { liggghtsContext.clear(); }
    };
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::foamDEM::liggghtsEngine::liggghtsEngine
(
    const Time& runTime,
    const dictionary& couplingDict
)
:
    demEngine(runTime),
    lmp_(nullptr),
    ownsMPI_(false),
    firstRun_(true),
    implicitDrag_(true),
    multisphere_(nullptr),
    integrates_(false),
    warnedSphereTorque_(false),
    shapedSpheres_(false),
    bodyTermsRestored_(false)
{
    const dictionary& dict = couplingDict.optionalSubDict(typeName + "Coeffs");

    const word dragIntegration
    (
        dict.getOrDefault<word>("dragIntegration", "implicit")
    );
    if (dragIntegration != "implicit" && dragIntegration != "explicit")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown dragIntegration " << dragIntegration << nl << nl
            << "Valid dragIntegration types :" << nl
            << "2(explicit implicit)" << exit(FatalIOError);
    }
    implicitDrag_ = (dragIntegration == "implicit");
    shapedSpheres_ = dict.getOrDefault<bool>("shapedSpheres", false);
    keepHeld_ = couplingDict.getOrDefault<bool>("writeDEMRestart", true);

    // Paths are relative to the (undecomposed) case directory
    const fileName caseDir(runTime.globalPath());
    scriptFile_ = caseDir/dict.getOrDefault<fileName>("script", "DEM/in.liggghts");
    logFile_ = caseDir/dict.getOrDefault<fileName>("log", "log.liggghts");

    if (!isFile(scriptFile_))
    {
        FatalIOErrorInFunction(dict)
            << "DEM script " << scriptFile_ << " not found." << nl
            << "    Set the keyword 'script' in " << typeName << "Coeffs of "
            << couplingDict.name() << " or create the file."
            << exit(FatalIOError);
    }

    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised)
    {
        MPI_Init(nullptr, nullptr);
        ownsMPI_ = true;
    }

    MPI_Comm comm;
    MPI_Comm_dup(MPI_COMM_WORLD, &comm);
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    liggghtsMaster = (rank == 0);
    liggghtsLog = logFile_;
    std::atexit(reportLiggghtsExit);

    // Relative paths inside the DEM script are taken from the case directory
    if (cwd() != caseDir)
    {
        chDir(caseDir);
    }

    // LIGGGHTS 3.8 crashes with '-screen none' during insertion: its screen
    // output goes to the log file instead.
    std::string logArg(logFile_);
    const char* args[] =
        {"liggghts", "-log", "none", "-screen", logArg.c_str(), "-echo", "none"};
    int nArgs = sizeof(args)/sizeof(args[0]);
    lmp_ = new LAMMPS_NS::LAMMPS(nArgs, const_cast<char**>(args), comm);

    // Only rank 0 has LIGGGHTS screen output. Some LIGGGHTS code prints to
    // it unguarded, and errors met on one rank only go there: the other
    // ranks print to stderr.
    if (!lmp_->screen)
    {
        lmp_->screen = stderr;
    }
    else
    {
        std::fflush(lmp_->screen);
        cookie_io_functions_t io{nullptr, teeWrite, nullptr, teeClose};
        FILE* tee = fopencookie(new teeCookie{lmp_->screen, {}}, "w", io);
        if (tee)
        {
            std::setvbuf(tee, nullptr, _IOLBF, 0);
            lmp_->screen = tee;
        }
    }

    // Continuation: the library's restart of the start time, if the case
    // has one, is offered to the script as the index variable
    // foamDEMRestart (the script's own "variable foamDEMRestart index
    // <fresh start file>" is then ignored) with foamDEMContinued 1
    {
        const fileName restart(restartFile(runTime, runTime.timeName()));
        continued_ = isFile(restart);
        run
        (
            "variable foamDEMContinued index " + word(continued_ ? "1" : "0"),
            "defining foamDEMContinued"
        );
        if (continued_)
        {
            run
            (
                "variable foamDEMRestart index " + restart.relative(caseDir),
                "defining foamDEMRestart"
            );
            Info<< "    LIGGGHTS: continuing from the DEM restart "
                << restart.relative(caseDir) << " (foamDEMRestart,"
                << " foamDEMContinued 1)" << endl;
        }
    }

    Info<< "    LIGGGHTS: reading " << scriptFile_.relative(caseDir)
        << ", output in " << logFile_.relative(caseDir) << endl;
    {
        contextGuard guard("reading the DEM script " + scriptFile_);
        lmp_->input->file(scriptFile_.c_str());
    }

    // A continued run's script must have read the restart it was offered:
    // LIGGGHTS' step must be the one the restart was written at (the
    // '.step' file writeRestart leaves beside it; restarts without one
    // are not checked)
    if (continued_)
    {
        const fileName restart(restartFile(runTime, runTime.timeName()));
        const fileName stepFile(restartStepFile(restart));
        int64_t written = -1;
        if (Pstream::master() && isFile(stepFile))
        {
            IFstream is(stepFile);
            int64_t k = -1;
            is >> k;
            written = is.bad() ? -1 : k;
        }
        Pstream::scatter(written);
        const int64_t now = lmp_->update->ntimestep;
        if (written >= 0 && written != now)
        {
            FatalIOErrorInFunction(dict)
                << "The DEM script " << scriptFile_.relative(caseDir)
                << " (liggghtsCoeffs.script) did not continue from the DEM"
                << " restart " << restart.relative(caseDir) << " it was"
                << " offered: LIGGGHTS is at step " << now << ", the restart"
                << " was written at step " << written << " (t = "
                << runTime.timeName() << " s). A script that can be"
                << " continued reads ${foamDEMRestart}: 'variable"
                << " foamDEMRestart index <file of a fresh start>' then"
                << " 'read_restart ${foamDEMRestart}' (the library defines"
                << " foamDEMRestart and foamDEMContinued 1 first), and does"
                << " not reset the step after it. Or start from startTime."
                << exit(FatalIOError);
        }
    }

    if (!lmp_->atom->radius_flag || !lmp_->atom->rmass_flag)
    {
        FatalIOErrorInFunction(dict)
            << "The DEM script " << scriptFile_ << " must use a granular atom"
            << " style (per-atom radius and mass): 'atom_style granular'."
            << exit(FatalIOError);
    }
    if (lmp_->atom->map_style == 0)
    {
        FatalIOErrorInFunction(dict)
            << "The DEM script " << scriptFile_ << " must contain"
            << " 'atom_modify map array' before the box is created"
            << " (needed by fix couple/cfd)."
            << exit(FatalIOError);
    }

    multisphere_ = dynamic_cast<LAMMPS_NS::FixMultisphere*>
    (
        lmp_->modify->find_fix_style("multisphere", 0)
    );
    if (multisphere_)
    {
        if (implicitDrag_ && dict.found("dragIntegration"))
        {
            FatalIOErrorInFunction(dict)
                << "dragIntegration implicit is not available with multisphere"
                << " bodies (LIGGGHTS moves their spheres with the body, so the"
                << " implicit velocity update is lost). Use explicit."
                << exit(FatalIOError);
        }
        implicitDrag_ = false;

        // The body's held coupling force and torque must move with it when
        // it changes rank: LIGGGHTS declares them 'comm_none', which its
        // body exchange does not pack (a migrating body would lose them
        // until the next coupling step). Let the exchange carry them.
        LAMMPS_NS::Multisphere& ms = multisphere_->data();
        for (const char* name : {"dragforce_cm", "hdtorque_cm"})
        {
            auto* c = ms.prop().getElementProperty
                <LAMMPS_NS::VectorContainer<double, 3>>(name);
            if (!c)
            {
                FatalErrorInFunction
                    << "fix multisphere has no body property " << name
                    << " (LIGGGHTS 3.8 has it)." << exit(FatalError);
            }
            c->setProperties
            (
                name, "comm_exchange_borders", "frame_invariant", "restart_no"
            );
        }
        Info<< "    LIGGGHTS: multisphere bodies coupled as single particles,"
            << " explicit DEM drag integration" << endl;
    }

    for (int i = 0; i < lmp_->modify->nfix; ++i)
    {
        const std::string style(lmp_->modify->fix[i]->style);
        if (style.find("nve") == 0 || style.find("multisphere") == 0)
        {
            integrates_ = true;
        }
    }
    if (!integrates_)
    {
        if (implicitDrag_ && dict.found("dragIntegration"))
        {
            FatalIOErrorInFunction(dict)
                << "dragIntegration implicit with a DEM that integrates no"
                << " particles (no nve or multisphere fix): the implicit"
                << " update would set velocities of frozen particles."
                << " Use explicit." << exit(FatalIOError);
        }
        implicitDrag_ = false;
        Info<< "    LIGGGHTS: no integration fix, particles stay fixed"
            << " (explicit DEM drag integration)" << endl;
    }

    if (shapedSpheres_ && !orientation())
    {
        run("fix foamDEM_orientation all property/atom foamDEMOrientation"
            " vector yes no no 0 0 0 0",
            "adding the shaped spheres' orientation");
        Info<< "    LIGGGHTS: shaped spheres: free spheres carry their atom"
            << " type as shape type and an orientation turned by their spin"
            << endl;
    }

}


void Foam::foamDEM::liggghtsEngine::prepare(const exchangePlan& plan)
{
    // The coupling force fix the plan needs, if the script has none:
    // - implicit coupling (K_p and u_f pushed): couple/cfd/force/implicit,
    //   with the Crank-Nicolson update when the DEM integrates the drag;
    // - explicit forces or torques only: couple/cfd/force (one force array);
    // - nothing pushed (a scene whose particles only make void fraction):
    //   no coupling fix at all.
    // LIGGGHTS's per-atom torque array (hdtorque) is never used: bodies take
    // their torque through fix multisphere's hdtorque_cm (see the class
    // description). couple/cfd/force/implicit neither applies it nor needs
    // it: transfer_torque no. couple/cfd/force reads it in every post_force
    // even with transfer_torque no (LIGGGHTS 3.8.0 then dereferences a null
    // fix and crashes), so it keeps it.
    const bool implicitCoeff = plan.has(quantity::implicitCoeff);
    const bool pushes =
        implicitCoeff
     || plan.has(quantity::explicitForce)
     || plan.has(quantity::torque);

    if (pushes && !lmp_->modify->find_fix_style("couple/cfd/force", 0))
    {
        if (!lmp_->modify->find_fix_style("couple/cfd", 0))
        {
            run("fix foamDEM_couple all couple/cfd couple_every 0 mpi",
                "adding the coupling fix");
        }
        string cmd("fix foamDEM_force all couple/cfd/force");
        if (implicitCoeff)
        {
            cmd += "/implicit transfer_torque no";
            if (implicitDrag_) cmd += " CrankNicolson 1.0";
        }
        run(cmd, "adding the coupling force fix");
    }

    // The per-atom force and torque the DEM holds between two runs, kept
    // in the restarts (writeRestart): a continued run starts its first
    // step from them, as the run that wrote the restart did (the set-up
    // of a run recomputes them, with the coupling terms of the new
    // interval instead of the old ones)
    if (keepHeld_ || continued_)
    {
        run
        (
            "fix foamDEM_heldForce all property/atom foamDEMHeldForce vector"
            " yes no no 0 0 0",
            "adding the held force"
        );
        run
        (
            "fix foamDEM_heldTorque all property/atom foamDEMHeldTorque"
            " vector yes no no 0 0 0",
            "adding the held torque"
        );
        if (multisphere_)
        {
            // Each sphere carries its body's held coupling terms (fix
            // multisphere keeps them per body, outside the restart)
            run
            (
                "fix foamDEM_bodyForce all property/atom foamDEMBodyForce"
                " vector yes no no 0 0 0",
                "adding the bodies' held force"
            );
            run
            (
                "fix foamDEM_bodyTorque all property/atom foamDEMBodyTorque"
                " vector yes no no 0 0 0",
                "adding the bodies' held torque"
            );
            run
            (
                "fix foamDEM_bodySet all property/atom foamDEMBodySet"
                " scalar yes no no 0",
                "adding the bodies' held-terms flag"
            );
        }
    }

    // Set the DEM up now (neighbour lists, fix gravity), so that errors
    // surface at start-up and gravity() is known
    run("run 0", "setting up the DEM");

    if (continued_)
    {
        // Back to the forces and torques of the restart's time; the first
        // interval continues without a new set-up
        copyHeld(false);
        // Without bodies the first interval continues without a new
        // set-up, as the straight run does after writing the restart; with
        // bodies the straight run sets up after the write (writeRestart),
        // and so does this one
        firstRun_ = bool(multisphere_);
        Info<< "    LIGGGHTS: continued run: the first step starts from the"
            << " forces and torques held at the restart's time";
        if (multisphere_)
        {
            Info<< "; the bodies' held coupling terms "
                << (bodyTermsRestored_ ? "from the restart" : "recomputed"
                    " (the restart does not hold them)");
        }
        Info<< endl;
    }

    // What exists, per atom, for the coupling (asked of LIGGGHTS, not
    // derived from the plan)
    Info<< "    LIGGGHTS: per-atom coupling arrays:";
    label nDoubles = 0;
    for (const char* name :
        {"dragforce", "hdtorque", "Ksl", "uf", "KslRotation", "ex", "KslExtra"})
    {
        auto* fix = dynamic_cast<LAMMPS_NS::FixPropertyAtom*>
        (
            lmp_->modify->find_fix_id(name)
        );
        if (fix)
        {
            const label n = fix->get_nvalues();
            Info<< ' ' << name << '[' << n << ']';
            nDoubles += n;
        }
    }
    Info<< (nDoubles ? "" : " none") << " (" << nDoubles*sizeof(double)
        << " B per atom)" << endl;
}


Foam::foamDEM::liggghtsEngine::~liggghtsEngine()
{
    delete lmp_;
    if (ownsMPI_)
    {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Finalize();
    }
}


// * * * * * * * * * * * * * * * Private functions  * * * * * * * * * * * * //

void Foam::foamDEM::liggghtsEngine::run
(
    const string& cmd,
    const string& context
)
{
    contextGuard guard(context + " (command '" + cmd + "')");
    lmp_->input->one(cmd.c_str());
}


double* Foam::foamDEM::liggghtsEngine::scalarProperty(const char* name) const
{
    LAMMPS_NS::Fix* fix = lmp_->modify->find_fix_property
    (
        name, "property/atom", "scalar", 0, 0, "foamDEM", false
    );
    return fix ? fix->vector_atom : nullptr;
}


double** Foam::foamDEM::liggghtsEngine::vectorProperty(const char* name) const
{
    LAMMPS_NS::Fix* fix = lmp_->modify->find_fix_property
    (
        name, "property/atom", "vector", 0, 0, "foamDEM", false
    );
    return fix ? fix->array_atom : nullptr;
}


double** Foam::foamDEM::liggghtsEngine::orientation() const
{
    return vectorProperty("foamDEMOrientation");
}


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * * //

Foam::scalar Foam::foamDEM::liggghtsEngine::timeStep() const
{
    return lmp_->update->dt;
}


Foam::label Foam::foamDEM::liggghtsEngine::nBodies() const
{
    return multisphere_ ? multisphere_->n_body() : 0;
}


Foam::labelList Foam::foamDEM::liggghtsEngine::freeAtoms() const
{
    const label n = lmp_->atom->nlocal;
    if (!multisphere_)
    {
        return identity(n);
    }
    DynamicList<label> atoms(n);
    for (label i = 0; i < n; ++i)
    {
        if (multisphere_->belongs_to(i) < 0)
        {
            atoms.append(i);
        }
    }
    return labelList(std::move(atoms));
}


Foam::vector Foam::foamDEM::liggghtsEngine::totalMomentum() const
{
    // Over the atoms (the spheres of a body carry its motion)
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    double local[3] = {0, 0, 0}, global[3];
    for (int i = 0; i < atom.nlocal; ++i)
    {
        for (int d = 0; d < 3; ++d) local[d] += atom.rmass[i]*atom.v[i][d];
    }
    MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_SUM, lmp_->world);
    return vector(global[0], global[1], global[2]);
}


Foam::scalar Foam::foamDEM::liggghtsEngine::totalMass() const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    double local = 0, global = 0;
    for (int i = 0; i < atom.nlocal; ++i) local += atom.rmass[i];
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, lmp_->world);
    return global;
}


Foam::label Foam::foamDEM::liggghtsEngine::nLocal() const
{
    return nBodies() + freeAtoms().size();
}


Foam::label Foam::foamDEM::liggghtsEngine::nGlobal() const
{
    if (!multisphere_)
    {
        return label(lmp_->atom->natoms);
    }
    return returnReduce(nLocal(), sumOp<label>());
}


Foam::boundBox Foam::foamDEM::liggghtsEngine::domain() const
{
    const double* lo = lmp_->domain->boxlo;
    const double* hi = lmp_->domain->boxhi;
    return boundBox(point(lo[0], lo[1], lo[2]), point(hi[0], hi[1], hi[2]));
}


Foam::List<Foam::boundBox> Foam::foamDEM::liggghtsEngine::reach() const
{
    // LIGGGHTS migrates an atom at the latest when it has moved half the
    // neighbour skin since the last rebuild; the full skin is the margin.
    // (A multisphere body's centre of mass goes with the rank that owns
    // it.) Particles outside these boxes are still found: particleTransfer
    // then exchanges with all ranks for that step.
    const LAMMPS_NS::Domain& box = *lmp_->domain;
    const scalar skin = lmp_->neighbor->skin;
    point lo(box.sublo[0], box.sublo[1], box.sublo[2]);
    point hi(box.subhi[0], box.subhi[1], box.subhi[2]);
    lo -= vector::uniform(skin);
    hi += vector::uniform(skin);

    // The box and its images by -1, 0, +1 periods in each periodic direction
    DynamicList<boundBox> boxes;
    for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
    for (int k = -1; k <= 1; ++k)
    {
        const int shift[3] = {i, j, k};
        vector s(Zero);
        bool valid = true;
        for (direction d = 0; d < 3; ++d)
        {
            if (shift[d] && !box.periodicity[d]) valid = false;
            s[d] = shift[d]*box.prd[d];
        }
        if (!valid) continue;
        const point l(lo + s), h(hi + s);
        bool overlaps = true;
        for (direction d = 0; d < 3; ++d)
        {
            if (h[d] < box.boxlo[d] || l[d] > box.boxhi[d]) overlaps = false;
        }
        if (overlaps || (!i && !j && !k))
        {
            boxes.append(boundBox(l, h));
        }
    }
    return List<boundBox>(std::move(boxes));
}


Foam::vector Foam::foamDEM::liggghtsEngine::gravity() const
{
    vector g(Zero);
    for (int i = 0; i < lmp_->modify->nfix; ++i)
    {
        auto* fg = dynamic_cast<LAMMPS_NS::FixGravity*>(lmp_->modify->fix[i]);
        if (fg)
        {
            double acc[3];
            fg->get_gravity(acc);
            g += vector(acc[0], acc[1], acc[2]);
        }
    }
    return g;
}


void Foam::foamDEM::liggghtsEngine::advance(label nSteps)
{
    if (shapedSpheres_)
    {
        // Turn each free sphere's orientation by its spin over the interval
        namespace corr = ::foamDEM::correlations;
        double** q = orientation();
        const LAMMPS_NS::Atom& atom = *lmp_->atom;
        const double dt = nSteps*lmp_->update->dt;
        for (const label i : freeAtoms())
        {
            if (q[i][0] == 0 && q[i][1] == 0 && q[i][2] == 0 && q[i][3] == 0)
            {
                corr::randomOrientation(std::uint64_t(atom.tag[i]), q[i]);
            }
            corr::rotateBySpin(q[i], atom.omega[i], dt);
        }
    }

    const string cmd
    (
        firstRun_
      ? "run " + Foam::name(nSteps)
      : "run " + Foam::name(nSteps) + " pre no post no"
    );
    firstRun_ = false;
    run(cmd, "advancing the DEM at t = " + Foam::name(runTime_.value()) + " s");
    keepMeshWallBins();
}


namespace
{
    // The time step of a mesh wall's last bin list, a protected member of
    // LIGGGHTS's FixNeighlistMesh, named through a derived class
    struct neighlistMeshAccess : LAMMPS_NS::FixNeighlistMesh
    {
        static constexpr LAMMPS_NS::bigint LAMMPS_NS::FixNeighlistMesh::*
            lastBinUpdate = &neighlistMeshAccess::last_bin_update;
    };
}


Foam::labelPair Foam::foamDEM::liggghtsEngine::neighbourBuilds() const
{
    // LIGGGHTS's own counters, the ones its run summary prints as
    // "Neighbor list builds" and "Dangerous builds". A run's set-up (pre
    // yes) resets them: they count from the first advance (the first run
    // sets up), or, with multisphere bodies, from the set-up after the
    // last restart write (writeRestart)
    return labelPair
    (
        label(lmp_->neighbor->ncalls),
        label(lmp_->neighbor->ndanger)
    );
}


void Foam::foamDEM::liggghtsEngine::keepMeshWallBins()
{
    // A mesh wall (fix wall/gran mesh) keeps, per triangle, the list of
    // neighbour bins it can touch. It builds the lists when the bins change
    // and, because its post_run forgets them, at the first step of every
    // run command: with a run per coupling interval that is every 20-100
    // DEM steps, and for large triangles in fine bins it cost half the DEM
    // time (spoutedBed). The bins do not change between our runs (pre no:
    // no setup; a change during a run rebuilds the lists at that step), so
    // the lists stay valid: mark them as built now.
    for (int i = 0; i < lmp_->modify->nfix; ++i)
    {
        auto* nl = dynamic_cast<LAMMPS_NS::FixNeighlistMesh*>
        (
            lmp_->modify->fix[i]
        );
        if (nl)
        {
            nl->*neighlistMeshAccess::lastBinUpdate = lmp_->update->ntimestep;
        }
    }
}


void Foam::foamDEM::liggghtsEngine::pull
(
    const exchangePlan& plan,
    particleData& p
) const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const label nB = nBodies();
    const labelList atoms(freeAtoms());
    p.resize(nB + atoms.size(), plan);
    if (plan.has(quantity::torque))
    {
        p.torque = Zero;    // the torque models add to it
    }

    auto vec = [](const double* a) { return vector(a[0], a[1], a[2]); };
    const scalar pi = constant::mathematical::pi;

    // LIGGGHTS maps atoms back into a periodic box only when it rebuilds
    // its neighbour lists; the copy is wrapped so that it lies in the box
    // (and the mesh). LIGGGHTS's own positions and image flags are left.
    const LAMMPS_NS::Domain& box = *lmp_->domain;
    auto wrapped = [&](const double* a)
    {
        vector x(a[0], a[1], a[2]);
        for (direction d = 0; d < 3; ++d)
        {
            if (!box.periodicity[d]) continue;
            if (x[d] < box.boxlo[d]) x[d] += box.prd[d];
            else if (x[d] >= box.boxhi[d]) x[d] -= box.prd[d];
        }
        return x;
    };

    // Multisphere bodies
    if (nB)
    {
        LAMMPS_NS::Multisphere& ms = multisphere_->data();
        double** exSpace = ms.extract_double_vector("ex_space");
        double** eySpace = ms.extract_double_vector("ey_space");
        double** ezSpace = ms.extract_double_vector("ez_space");
        double** inertia = ms.extract_double_vector("inertia");
        LAMMPS_NS::ScalarContainer<int>* clumpTypes =
            ms.prop().getElementProperty<LAMMPS_NS::ScalarContainer<int>>
            ("clumptype");

        double a[4];
        for (label b = 0; b < nB; ++b)
        {
            ms.xcm(a, b);
            p.position[b] = wrapped(a);
            if (plan.has(quantity::velocity))
            {
                ms.vcm(a, b);
                p.velocity[b] = vec(a);
            }
            if (plan.has(quantity::angularVelocity))
            {
                ms.omega(a, b);
                p.angularVelocity[b] = vec(a);
            }
            if (plan.has(quantity::radius))
            {
                p.radius[b] = cbrt(3*ms.volume(b)/(4*pi));
            }
            if (plan.has(quantity::density))
            {
                p.density[b] = ms.density(b);
            }
            if (plan.has(quantity::orientation))
            {
                // Principal axes ordered by increasing moment of inertia
                const vector axes[3] =
                    {vec(exSpace[b]), vec(eySpace[b]), vec(ezSpace[b])};
                label order[3] = {0, 1, 2};
                std::sort(order, order + 3, [&](label i, label j)
                    { return inertia[b][i] < inertia[b][j]; });
                const vector& e0 = axes[order[0]];
                const vector& e1 = axes[order[1]];
                const vector e2 = e0 ^ e1;     // right-handed
                p.orientation[b] = tensor
                (
                    e0.x(), e1.x(), e2.x(),
                    e0.y(), e1.y(), e2.y(),
                    e0.z(), e1.z(), e2.z()
                );
            }
            if (plan.has(quantity::type))
            {
                p.type[b] = (*clumpTypes)(b);
            }
            if (plan.has(quantity::id))
            {
                p.id[b] = -ms.tag(b);   // bodies: negative ids
            }
        }
    }

    // A shaped sphere's axes (columns), from its quaternion (a sphere not
    // yet turned gets its random start orientation)
    double** q = shapedSpheres_ ? orientation() : nullptr;
    auto sphereAxes = [&](label i)
    {
        namespace corr = ::foamDEM::correlations;
        if (q[i][0] == 0 && q[i][1] == 0 && q[i][2] == 0 && q[i][3] == 0)
        {
            corr::randomOrientation(std::uint64_t(atom.tag[i]), q[i]);
        }
        double R[3][3];
        corr::quaternionToMatrix(q[i], R);
        return tensor
        (
            R[0][0], R[0][1], R[0][2],
            R[1][0], R[1][1], R[1][2],
            R[2][0], R[2][1], R[2][2]
        );
    };

    // Free spheres
    forAll(atoms, k)
    {
        const label i = atoms[k];
        const label j = nB + k;
        p.position[j] = wrapped(atom.x[i]);
        if (plan.has(quantity::velocity)) p.velocity[j] = vec(atom.v[i]);
        if (plan.has(quantity::radius)) p.radius[j] = atom.radius[i];
        if (plan.has(quantity::density))
        {
            const scalar r = atom.radius[i];
            p.density[j] = atom.rmass[i]/(4.0/3.0*pi*r*r*r);
        }
        if (plan.has(quantity::angularVelocity))
        {
            if (!atom.omega_flag)
            {
                FatalErrorInFunction
                    << "A selected model needs particle angular velocities"
                    << " but the DEM atom style has none (use atom_style"
                    << " granular)." << exit(FatalError);
            }
            p.angularVelocity[j] = vec(atom.omega[i]);
        }
        if (plan.has(quantity::orientation))
        {
            p.orientation[j] = shapedSpheres_ ? sphereAxes(i) : tensor::I;
        }
        if (plan.has(quantity::type))
        {
            p.type[j] = shapedSpheres_ ? atom.type[i] : 0;
        }
        if (plan.has(quantity::id)) p.id[j] = atom.tag[i];
    }
}


void Foam::foamDEM::liggghtsEngine::push
(
    const exchangePlan& plan,
    const particleData& p
)
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const label nB = nBodies();
    const labelList atoms(freeAtoms());
    if (p.size() != nB + atoms.size())
    {
        FatalErrorInFunction
            << "Particle count changed between pull and push: "
            << p.size() << " != " << nB + atoms.size() << abort(FatalError);
    }

    double* Ksl = nullptr;
    double** uf = nullptr;
    double** fExpl = nullptr;
    if (plan.has(quantity::implicitCoeff))
    {
        Ksl = scalarProperty("Ksl");
        uf = vectorProperty("uf");
        if (!Ksl || !uf)
        {
            FatalErrorInFunction
                << "Implicit coupling needs 'fix couple/cfd/force/implicit'"
                << " in the DEM, but the script defines another force fix."
                << exit(FatalError);
        }
    }
    const bool explicitForce = plan.has(quantity::explicitForce);
    const bool torque = plan.has(quantity::torque);
    if (explicitForce || torque)
    {
        fExpl = vectorProperty("dragforce");
        if (!fExpl)
        {
            FatalErrorInFunction
                << "The DEM has no coupling force fix (couple/cfd/force)."
                << exit(FatalError);
        }
    }

    // Terms of free sphere j, written to atom i
    auto write = [&](label i, label j)
    {
        if (Ksl)
        {
            Ksl[i] = p.implicitCoeff[j];
            for (direction d = 0; d < 3; ++d) uf[i][d] = p.fluidVelocity[j][d];
        }
        if (fExpl)
        {
            for (direction d = 0; d < 3; ++d)
            {
                fExpl[i][d] = explicitForce ? p.explicitForce[j][d] : 0;
            }
        }
    };

    if (multisphere_)
    {
        // Bodies: the force and torque go to the body itself (fix
        // multisphere adds dragforce_cm and hdtorque_cm to the body's sums
        // every DEM step; both are per-body data, exchanged with the body
        // between ranks: see the constructor). Its spheres, wherever they
        // are, get nothing.
        LAMMPS_NS::Multisphere& ms = multisphere_->data();
        double** fBody = ms.extract_double_vector("dragforce_cm");
        double** tBody = ms.extract_double_vector("hdtorque_cm");
        if (!fBody || !tBody)
        {
            FatalErrorInFunction
                << "fix multisphere has no dragforce_cm/hdtorque_cm body"
                << " properties (LIGGGHTS 3.8 has them)." << exit(FatalError);
        }
        // The implicit drag K (u_f - v) of a body is evaluated with the
        // body's velocity of this coupling step and held, like the explicit
        // terms, until the next one (no DEM-side implicit update for bodies)
        const bool implicitPart = Ksl && p.velocity.size() == p.size();
        if (Ksl && !implicitPart)
        {
            FatalErrorInFunction
                << "Implicit coupling of multisphere bodies needs the body"
                << " velocities in the exchange plan." << abort(FatalError);
        }
        for (label b = 0; b < nB; ++b)
        {
            vector F(explicitForce ? p.explicitForce[b] : vector::zero);
            if (implicitPart)
            {
                F += p.implicitCoeff[b]*(p.fluidVelocity[b] - p.velocity[b]);
            }
            const vector T(torque ? p.torque[b] : vector::zero);
            for (direction d = 0; d < 3; ++d)
            {
                fBody[b][d] = F[d];
                tBody[b][d] = T[d];
            }
        }
        for (label i = 0; i < atom.nlocal; ++i)
        {
            if (multisphere_->belongs_to(i) >= 0)
            {
                if (Ksl) Ksl[i] = 0;
                if (fExpl) fExpl[i][0] = fExpl[i][1] = fExpl[i][2] = 0;
            }
        }
    }
    forAll(atoms, k)
    {
        write(atoms[k], nB + k);
    }

    // A free sphere cannot take a torque through this path (see header)
    if (torque && !warnedSphereTorque_)
    {
        forAll(atoms, k)
        {
            if (magSqr(p.torque[nB + k]) > 0)
            {
                WarningInFunction
                    << "A torque model gave free spheres a torque: it is not"
                    << " applied (LIGGGHTS's implicit coupling fix carries no"
                    << " per-sphere torque). Reported once." << endl;
                warnedSphereTorque_ = true;
                break;
            }
        }
    }
}


Foam::scalarList Foam::foamDEM::liggghtsEngine::contactRadii() const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const label nB = nBodies();
    const labelList atoms(freeAtoms());
    scalarList r(nB + atoms.size(), GREAT);
    if (nB)
    {
        // The rank that owns a body holds all its spheres, as own atoms or
        // ghosts (fix multisphere extends the ghost cut-off by the largest
        // bounding radius and sums the body's forces over them)
        LAMMPS_NS::Multisphere& ms = multisphere_->data();
        const label nAll = atom.nlocal + atom.nghost;
        for (label i = 0; i < nAll; ++i)
        {
            const int bodyTag = multisphere_->belongs_to(i);
            const label b = bodyTag >= 0 ? ms.map(bodyTag) : -1;
            if (b >= 0)
            {
                r[b] = min(r[b], scalar(atom.radius[i]));
            }
        }
    }
    forAll(atoms, k)
    {
        r[nB + k] = atom.radius[atoms[k]];
    }
    return r;
}


void Foam::foamDEM::liggghtsEngine::materialProperties
(
    scalarList& E,
    scalarList& nu
) const
{
    const label nTypes = lmp_->atom->ntypes;
    auto perType = [&](const char* name, scalarList& values)
    {
        values.clear();
        auto* fix = dynamic_cast<LAMMPS_NS::FixPropertyGlobal*>
        (
            lmp_->modify->find_fix_property
            (
                name, "property/global", "peratomtype", 0, 0, "foamDEM", false
            )
        );
        if (fix)
        {
            values.setSize(nTypes);
            forAll(values, t)
            {
                values[t] = fix->compute_vector(t);
            }
        }
    };
    perType("youngsModulus", E);
    perType("poissonsRatio", nu);
}


Foam::labelList Foam::foamDEM::liggghtsEngine::particleTypes() const
{
    // Atom types (0-based), in pull order: bodies (their spheres' type),
    // then free spheres
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const labelList atoms(freeAtoms());
    const label nB = nBodies();
    labelList types(nB + atoms.size());
    for (label b = 0; b < nB; ++b)
    {
        types[b] = multisphere_->data().atomtype(b) - 1;
    }
    forAll(atoms, k)
    {
        types[nB + k] = atom.type[atoms[k]] - 1;
    }
    return types;
}


void Foam::foamDEM::liggghtsEngine::copyHeld(bool toRestart)
{
    double** heldF = vectorProperty("foamDEMHeldForce");
    double** heldT = vectorProperty("foamDEMHeldTorque");
    LAMMPS_NS::Atom& atom = *lmp_->atom;
    if (multisphere_) copyBodyTerms(toRestart);
    if (!heldF || !heldT || !atom.f || !atom.torque) return;
    for (int i = 0; i < atom.nlocal; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            if (toRestart)
            {
                heldF[i][k] = atom.f[i][k];
                heldT[i][k] = atom.torque[i][k];
            }
            else
            {
                atom.f[i][k] = heldF[i][k];
                atom.torque[i][k] = heldT[i][k];
            }
        }
    }
}


void Foam::foamDEM::liggghtsEngine::copyBodyTerms(bool toRestart)
{
    double** sphereF = vectorProperty("foamDEMBodyForce");
    double** sphereT = vectorProperty("foamDEMBodyTorque");
    double* set = scalarProperty("foamDEMBodySet");
    LAMMPS_NS::Multisphere& ms = multisphere_->data();
    double** fBody = ms.extract_double_vector("dragforce_cm");
    double** tBody = ms.extract_double_vector("hdtorque_cm");
    if (!sphereF || !sphereT || !set || !fBody || !tBody) return;
    const LAMMPS_NS::Atom& atom = *lmp_->atom;

    if (toRestart)
    {
        // Every sphere of a body held on this rank gets the body's terms
        for (int i = 0; i < atom.nlocal; ++i)
        {
            const int tag = multisphere_->belongs_to(i);
            const int b = tag >= 0 ? ms.map(tag) : -1;
            set[i] = b >= 0 ? 1 : 0;
            for (int k = 0; k < 3; ++k)
            {
                sphereF[i][k] = b >= 0 ? fBody[b][k] : 0;
                sphereT[i][k] = b >= 0 ? tBody[b][k] : 0;
            }
        }
        return;
    }

    // Each body on this rank from one of its local spheres (the
    // properties are not sent to ghosts: a body none of whose spheres is
    // on its own rank keeps recomputed terms, and the log says so)
    const label nB = ms.n_body();
    List<bool> done(nB, false);
    for (int i = 0; i < atom.nlocal; ++i)
    {
        const int tag = multisphere_->belongs_to(i);
        const int b = tag >= 0 ? ms.map(tag) : -1;
        if (b < 0 || done[b] || set[i] != 1) continue;
        for (int k = 0; k < 3; ++k)
        {
            fBody[b][k] = sphereF[i][k];
            tBody[b][k] = sphereT[i][k];
        }
        done[b] = true;
    }
    label missing = 0;
    forAll(done, b)
    {
        if (!done[b]) ++missing;
    }
    bodyTermsRestored_ = returnReduce(missing, sumOp<label>()) == 0;
}


Foam::List<Foam::fileName> Foam::foamDEM::liggghtsEngine::restartCompanions
(
    const fileName& restart
) const
{
    List<fileName> files(demEngine::restartCompanions(restart));
    files.append(fileName(bodyStateFile(restart)));
    return files;
}


void Foam::foamDEM::liggghtsEngine::writeRestart(const fileName& file)
{
    copyHeld(true);
    mkDir(file.path());
    contextGuard guard("writing the DEM restart " + file);

    // Written as LIGGGHTS writes its periodic restarts during a run
    // (WriteRestart::write), not with the write_restart command: the
    // command re-initialises LIGGGHTS and migrates atoms (init, pbc,
    // exchange, borders), which leaves the neighbour lists, the bins and
    // the forces of migrated atoms stale for the next 'run ... pre no': a
    // segmentation fault in Neighbor::bin_atoms with bodies, and LIGGGHTS's
    // own errors turned into segmentation faults. Written this way the run
    // goes on exactly as without the write, and needs no new set-up.
    LAMMPS_NS::Modify& modify = *lmp_->modify;
    LAMMPS_NS::Atom& atom = *lmp_->atom;
    LAMMPS_NS::Domain& domain = *lmp_->domain;

    // Fixes copy their per-atom state in (the contact history from the
    // neighbour lists)
    modify.setup_pre_exchange();

    // An atom that crossed a periodic boundary since the last neighbour
    // build is outside the box, and read_restart would lose it: the file
    // gets it wrapped, the run keeps it as it is (remap changes an atom's
    // image flags exactly when it wraps it)
    struct moved { int i; double x[3]; LAMMPS_NS::tagint image; };
    std::vector<moved> wrapped;
    for (int i = 0; i < atom.nlocal; ++i)
    {
        moved m{i, {atom.x[i][0], atom.x[i][1], atom.x[i][2]}, atom.image[i]};
        domain.remap(atom.x[i], atom.image[i]);
        if (atom.image[i] != m.image) wrapped.push_back(m);
    }

    std::vector<char> name(file.begin(), file.end());
    name.push_back('\0');
    LAMMPS_NS::WriteRestart(lmp_).write(name.data());

    for (const moved& m : wrapped)
    {
        for (int k = 0; k < 3; ++k) atom.x[m.i][k] = m.x[k];
        atom.image[m.i] = m.image;
    }

    label nWrapped = label(wrapped.size());
    reduce(nWrapped, sumOp<label>());
    if (nWrapped)
    {
        Info<< "DEM restart " << file.name() << ": " << nWrapped
            << " atom(s) past a periodic boundary written wrapped into the"
            << " box" << endl;
    }

    // With bodies, their states beside it (multisphereBodies.H): a few MB
    // that rebuild the restart's spheres on another machine (not in a
    // periodic domain, whose images they do not carry)
    if
    (
        multisphere_
     && !domain.xperiodic && !domain.yperiodic && !domain.zperiodic
    )
    {
        try
        {
            writeBodyStates(*lmp_, *multisphere_, bodyStateFile(file));
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "Writing the bodies' states beside the DEM restart " << file
                << ": " << e.what() << exit(FatalError);
        }
    }

    // With bodies the next run sets up again, so that a run continued from
    // this restart, which must set up, starts its first interval alike: fix
    // multisphere's set-up recomputes the bodies' force and torque sums,
    // which are not in the restart
    if (multisphere_)
    {
        firstRun_ = true;
    }

    // Its step, for the check of a continued run (see the constructor)
    if (Pstream::master())
    {
        OFstream os(restartStepFile(file));
        os  << int64_t(lmp_->update->ntimestep) << endl;
    }
}
