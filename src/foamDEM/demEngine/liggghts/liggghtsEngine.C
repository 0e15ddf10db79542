#include "liggghtsEngine.H"
#include "addToRunTimeSelectionTable.H"
#include "Pstream.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <mpi.h>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <string>

// LIGGGHTS
#include "lammps.h"
#include "input.h"
#include "atom.h"
#include "update.h"
#include "domain.h"
#include "modify.h"
#include "fix.h"
#include "fix_gravity.h"
#include "fix_property_global.h"

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

        std::fprintf
        (
            stderr,
            "\n--> foamDEM FATAL ERROR: LIGGGHTS stopped with an error while "
            "%s.\n    LIGGGHTS said (from %s):\n",
            liggghtsContext.c_str(), liggghtsLog.c_str()
        );
        std::ifstream log(liggghtsLog);
        std::string line;
        bool any = false;
        while (std::getline(log, line))
        {
            if (line.find("ERROR") != std::string::npos)
            {
                std::fprintf(stderr, "    %s\n", line.c_str());
                any = true;
            }
        }
        if (!any)
        {
            std::fprintf(stderr, "    (no ERROR line found; see the log)\n");
        }
        std::fflush(stderr);
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
    implicitDrag_(true)
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

    Info<< "    LIGGGHTS: reading " << scriptFile_.relative(caseDir)
        << ", output in " << logFile_.relative(caseDir) << endl;
    {
        contextGuard guard("reading the DEM script " + scriptFile_);
        lmp_->input->file(scriptFile_.c_str());
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

    if (!lmp_->modify->find_fix_style("couple/cfd", 0))
    {
        run("fix foamDEM_couple all couple/cfd couple_every 0 mpi",
            "adding the coupling fix");
    }
    if (!lmp_->modify->find_fix_style("couple/cfd/force", 0))
    {
        run
        (
            implicitDrag_
          ? "fix foamDEM_force all couple/cfd/force/implicit CrankNicolson 1.0"
          : "fix foamDEM_force all couple/cfd/force/implicit",
            "adding the coupling force fix"
        );
    }

    // Set the DEM up now (neighbour lists, fix gravity), so that errors
    // surface at start-up and gravity() is known
    run("run 0", "setting up the DEM");
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


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * * //

Foam::scalar Foam::foamDEM::liggghtsEngine::timeStep() const
{
    return lmp_->update->dt;
}


Foam::label Foam::foamDEM::liggghtsEngine::nLocal() const
{
    return lmp_->atom->nlocal;
}


Foam::label Foam::foamDEM::liggghtsEngine::nGlobal() const
{
    return label(lmp_->atom->natoms);
}


Foam::boundBox Foam::foamDEM::liggghtsEngine::domain() const
{
    const double* lo = lmp_->domain->boxlo;
    const double* hi = lmp_->domain->boxhi;
    return boundBox(point(lo[0], lo[1], lo[2]), point(hi[0], hi[1], hi[2]));
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
    const string cmd
    (
        firstRun_
      ? "run " + Foam::name(nSteps)
      : "run " + Foam::name(nSteps) + " pre no post no"
    );
    firstRun_ = false;
    run(cmd, "advancing the DEM at t = " + Foam::name(runTime_.value()) + " s");
}


void Foam::foamDEM::liggghtsEngine::pull
(
    const exchangePlan& plan,
    particleData& p
) const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const label n = atom.nlocal;
    p.resize(n, plan);

    if (plan.has(quantity::position))
    {
        for (label i = 0; i < n; ++i)
        {
            p.position[i] = vector(atom.x[i][0], atom.x[i][1], atom.x[i][2]);
        }
    }
    if (plan.has(quantity::velocity))
    {
        for (label i = 0; i < n; ++i)
        {
            p.velocity[i] = vector(atom.v[i][0], atom.v[i][1], atom.v[i][2]);
        }
    }
    if (plan.has(quantity::radius))
    {
        for (label i = 0; i < n; ++i)
        {
            p.radius[i] = atom.radius[i];
        }
    }
    if (plan.has(quantity::density))
    {
        for (label i = 0; i < n; ++i)
        {
            const scalar r = atom.radius[i];
            p.density[i] =
                atom.rmass[i]/(4.0/3.0*constant::mathematical::pi*r*r*r);
        }
    }
    if (plan.has(quantity::angularVelocity))
    {
        if (!atom.omega_flag)
        {
            FatalErrorInFunction
                << "A selected model needs particle angular velocities but"
                << " the DEM atom style has none (use atom_style granular)."
                << exit(FatalError);
        }
        for (label i = 0; i < n; ++i)
        {
            p.angularVelocity[i] =
                vector(atom.omega[i][0], atom.omega[i][1], atom.omega[i][2]);
        }
    }
    if (plan.has(quantity::id))
    {
        for (label i = 0; i < n; ++i)
        {
            p.id[i] = atom.tag[i];
        }
    }
}


void Foam::foamDEM::liggghtsEngine::push
(
    const exchangePlan& plan,
    const particleData& p
)
{
    const label n = lmp_->atom->nlocal;
    if (p.size() != n)
    {
        FatalErrorInFunction
            << "Particle count changed between pull and push: "
            << p.size() << " != " << n << abort(FatalError);
    }

    if (plan.has(quantity::implicitCoeff))
    {
        double* Ksl = scalarProperty("Ksl");
        double** uf = vectorProperty("uf");
        if (!Ksl || !uf)
        {
            FatalErrorInFunction
                << "Implicit coupling needs 'fix couple/cfd/force/implicit'"
                << " in the DEM, but the script defines another force fix."
                << exit(FatalError);
        }
        for (label i = 0; i < n; ++i)
        {
            Ksl[i] = p.implicitCoeff[i];
            for (direction d = 0; d < 3; ++d)
            {
                uf[i][d] = p.fluidVelocity[i][d];
            }
        }
    }
    if (plan.has(quantity::explicitForce))
    {
        double** fExpl = vectorProperty("dragforce");
        if (!fExpl)
        {
            FatalErrorInFunction
                << "The DEM has no coupling force fix (couple/cfd/force)."
                << exit(FatalError);
        }
        for (label i = 0; i < n; ++i)
        {
            for (direction d = 0; d < 3; ++d)
            {
                fExpl[i][d] = p.explicitForce[i][d];
            }
        }
    }
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
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    labelList types(atom.nlocal);
    forAll(types, i)
    {
        types[i] = atom.type[i] - 1;
    }
    return types;
}


void Foam::foamDEM::liggghtsEngine::writeRestart(const fileName& file)
{
    mkDir(file.path());
    run("write_restart " + file, "writing the DEM restart " + file);
}


void Foam::foamDEM::liggghtsEngine::command(const string& cmd)
{
    run(cmd, "running a DEM command from the case");
}
