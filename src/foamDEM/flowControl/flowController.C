#include "flowController.H"
#include "fvMatrices.H"
#include "volFields.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(flowController, 0);
}
namespace fv
{
    // The registration macro pastes the type names: unqualified here
    typedef foamDEM::flowController foamDEMFlowController;
    addToRunTimeSelectionTable(option, foamDEMFlowController, dictionary);
}
}


namespace
{
    const Foam::word publishedName("foamDEM:drivingForce");
}


// * * * * * * * * * * * * * * * Private functions  * * * * * * * * * * * * //

void Foam::foamDEM::flowController::readControls()
{
    UName_ = coeffs_.getOrDefault<word>("U", "U");
    alphaName_ = coeffs_.getOrDefault<word>("alpha", "voidfraction");
    fieldNames_ = wordList(1, UName_);
    applied_.setSize(1, false);

    const vector dir(coeffs_.get<vector>("direction"));
    if (mag(dir) < VSMALL)
    {
        FatalIOErrorInFunction(coeffs_)
            << "flowController " << name_ << ": direction must not be zero"
            << exit(FatalIOError);
    }
    dir_ = dir/mag(dir);

    Ubar_ = coeffs_.get<scalar>("Ubar");

    relaxation_ = coeffs_.getOrDefault<scalar>("relaxation", 0.25);
    if (relaxation_ <= 0 || relaxation_ > 1)
    {
        FatalIOErrorInFunction(coeffs_)
            << "flowController " << name_ << ": relaxation must be in (0, 1],"
            << " got " << relaxation_ << exit(FatalIOError);
    }

    deadBand_ = coeffs_.getOrDefault<scalar>("deadBand", 0.05);
    if (deadBand_ < 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "flowController " << name_ << ": deadBand must be >= 0, got "
            << deadBand_ << exit(FatalIOError);
    }

    applyToParticles_ = coeffs_.getOrDefault("applyToParticles", false);
    rho_ = readRho();
}


Foam::scalar Foam::foamDEM::flowController::readRho() const
{
    if (coeffs_.found("rho"))
    {
        const scalar rho = coeffs_.get<scalar>("rho");
        if (rho <= 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "flowController " << name_ << ": rho must be positive, got "
                << rho << exit(FatalIOError);
        }
        return rho;
    }

    IOobject io
    (
        "transportProperties",
        mesh_.time().constant(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (io.typeHeaderOk<IOdictionary>(true))
    {
        const IOdictionary transport(io);
        if (transport.found("rho"))
        {
            return dimensionedScalar("rho", dimDensity, transport).value();
        }
    }
    if (applyToParticles_)
    {
        FatalIOErrorInFunction(coeffs_)
            << "flowController " << name_ << ": applyToParticles needs the"
            << " fluid density, for f = rho a: give 'rho' or an entry 'rho'"
            << " in constant/transportProperties." << exit(FatalIOError);
    }
    return 1;
}


Foam::tmp<Foam::scalarField> Foam::foamDEM::flowController::weights() const
{
    auto tw = tmp<scalarField>::New(cells_.size(), 1.0);
    const volScalarField* alpha =
        mesh_.findObject<volScalarField>(alphaName_);
    if (alpha)
    {
        tw.ref() = scalarField(alpha->primitiveField(), cells_);
    }
    return tw;
}


Foam::scalar Foam::foamDEM::flowController::meanVelocity
(
    const volVectorField& U
) const
{
    const scalarField w(weights());
    const scalarField& V = mesh_.V();
    scalar sumWU = 0, sumW = 0;
    forAll(cells_, i)
    {
        const label c = cells_[i];
        sumWU += w[i]*(U[c] & dir_)*V[c];
        sumW += w[i]*V[c];
    }
    reduce(sumWU, sumOp<scalar>());
    reduce(sumW, sumOp<scalar>());
    return sumWU/max(sumW, VSMALL);
}


Foam::scalar Foam::foamDEM::flowController::sensitivity
(
    const scalarField& w
) const
{
    const scalar dt = mesh_.time().deltaTValue();
    const scalarField& V = mesh_.V();
    const bool haveMatrix =
        rA_.size() == cells_.size() && multiplier_.size() == cells_.size();

    scalar num = 0, den = 0;
    forAll(cells_, i)
    {
        const scalar Vc = V[cells_[i]];
        // Before the first matrix: inertia only, m/A = dt
        num += w[i]*Vc*(haveMatrix ? multiplier_[i]*rA_[i] : dt);
        den += w[i]*Vc;
    }
    reduce(num, sumOp<scalar>());
    reduce(den, sumOp<scalar>());
    return num/max(den, VSMALL);
}


void Foam::foamDEM::flowController::writeLogLine
(
    scalar t,
    scalar Um,
    scalar a,
    bool updated
)
{
    if (!log_.valid() || t <= tLogged_)
    {
        return;
    }
    log_()
        << t << tab << Um << tab << Ubar_ << tab << a << tab << rho_*a
        << tab << r_ << tab << (updated ? 1 : 0) << endl;
    tLogged_ = t;
}


void Foam::foamDEM::flowController::publish()
{
    if (published_.valid())
    {
        published_->value() = forcePerVolume();
    }
    state_.set("force", force_);
    state_.set("Umean", Uprev_);
    state_.set("hasUmean", hasUprev_);
}


void Foam::foamDEM::flowController::update(const volVectorField& U)
{
    if (updateIndex_ == mesh_.time().timeIndex())
    {
        return;
    }
    updateIndex_ = mesh_.time().timeIndex();

    const scalar dt = mesh_.time().deltaTValue();
    const scalar tPrev = mesh_.time().value() - dt;
    const scalar Um = meanVelocity(U);

    // The step that has ended (at tPrev) ran with the current force
    writeLogLine(tPrev, Um, force_, updated_);

    r_ = sensitivity(weights());

    // Resistance estimate, then the dead-beat force
    const scalar R = hasUprev_ ? force_ - (Um - Uprev_)/r_ : force_;
    const scalar aStar = R + (Ubar_ - Um)/r_;

    updated_ = mag(aStar - force_) > deadBand_*mag(force_);
    if (updated_)
    {
        force_ += relaxation_*(aStar - force_);
    }
    Uprev_ = Um;
    hasUprev_ = true;

    publish();

    if (log)
    {
        Info<< type() << ' ' << name_ << ": mean velocity " << Um
            << " (target " << Ubar_ << "), force " << rho_*force_
            << " N/m^3" << (updated_ ? "" : " (dead band, unchanged)")
            << endl;
    }
}


void Foam::foamDEM::flowController::addSource
(
    const scalarField& m,
    fvMatrix<vector>& eqn
)
{
    const scalarField& V = mesh_.V();
    vectorField& source = eqn.source();
    forAll(cells_, i)
    {
        const label c = cells_[i];
        multiplier_[i] = m[c];
        // fvMatrix source is on the left-hand side: subtract
        source[c] -= m[c]*force_*dir_*V[c];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::foamDEM::flowController::flowController
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    fv::cellSetOption(name, modelType, dict, mesh),
    UName_("U"),
    alphaName_("voidfraction"),
    dir_(Zero),
    Ubar_(0),
    relaxation_(0.25),
    deadBand_(0.05),
    applyToParticles_(false),
    rho_(1),
    force_(0),
    Uprev_(0),
    hasUprev_(false),
    r_(mesh.time().deltaTValue()),
    updateIndex_(-1),
    updated_(false),
    multiplier_(),
    rA_(),
    Ulatest_(0),
    tLatest_(-GREAT),
    tLogged_(-GREAT),
    forceLatest_(0),
    updatedLatest_(false),
    state_
    (
        IOobject
        (
            name + "Properties",
            mesh.time().timeName(),
            "uniform",
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    )
{
    readControls();
    multiplier_.setSize(cells_.size(), 1.0);

    if (state_.found("force"))
    {
        force_ = state_.get<scalar>("force");
        Uprev_ = state_.getOrDefault<scalar>("Umean", 0);
        hasUprev_ = state_.getOrDefault("hasUmean", false);
        Info<< "    flowController " << name_ << ": force " << force_
            << " m/s^2 from " << state_.objectPath() << endl;

        // The last matrix's sensitivity data, if written for these cells
        // (another decomposition: from inertia, r = dt, at the first step)
        if (state_.found("rA") && state_.found("multiplier"))
        {
            // Dictionary entries hold their lists as text tokens, also in
            // a file whose header says binary (writeFormat binary): read
            // them as such
            ITstream& isA = state_.lookup("rA");
            isA.format(IOstream::ASCII);
            scalarField rA(isA);
            ITstream& isM = state_.lookup("multiplier");
            isM.format(IOstream::ASCII);
            scalarField m(isM);
            if (rA.size() == cells_.size() && m.size() == cells_.size())
            {
                rA_.transfer(rA);
                multiplier_.transfer(m);
            }
        }
    }
    else
    {
        force_ = coeffs_.getOrDefault<scalar>("initialForce", 0);
    }

    if (applyToParticles_)
    {
        if (mesh_.foundObject<uniformDimensionedVectorField>(publishedName))
        {
            FatalIOErrorInFunction(coeffs_)
                << "flowController " << name_ << ": another object already"
                << " publishes " << publishedName << "; only one"
                << " flowController may apply its force to the particles."
                << exit(FatalIOError);
        }
        published_.reset
        (
            new uniformDimensionedVectorField
            (
                IOobject
                (
                    publishedName,
                    mesh_.time().constant(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE
                ),
                dimensionedVector(dimForce/dimVolume, Zero)
            )
        );
    }
    publish();

    if (Pstream::master())
    {
        const fileName dir
        (
            mesh_.time().globalPath()/"postProcessing"/name_
           /mesh_.time().timeName()
        );
        mkDir(dir);
        log_.reset(new OFstream(dir/"flowController.dat"));
        log_()
            << "# flowController " << name_ << ": direction " << dir_
            << ", target " << Ubar_ << " m/s, relaxation " << relaxation_
            << ", dead band " << deadBand_ << ", rho " << rho_
            << ", applyToParticles " << applyToParticles_ << nl
            << "# time Umean Ubar force[m/s^2] force[N/m^3] r[s] updated"
            << endl;
        log_().precision(10);
    }

    Info<< "    flowController " << name_ << ": direction " << dir_
        << ", target mean velocity " << Ubar_ << " m/s (weight "
        << alphaName_ << "), relaxation " << relaxation_ << ", dead band "
        << deadBand_ << (applyToParticles_ ? ", force on particles" : "")
        << endl;
}


Foam::foamDEM::flowController::~flowController()
{
    // The step that ended last
    writeLogLine(tLatest_, Ulatest_, forceLatest_, updatedLatest_);
}


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * //

void Foam::foamDEM::flowController::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    update(eqn.psi());
    addSource(scalarField(mesh_.nCells(), 1.0), eqn);
}


void Foam::foamDEM::flowController::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    update(eqn.psi());
    addSource(rho.primitiveField(), eqn);
}


void Foam::foamDEM::flowController::constrain
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    const scalarField A(eqn.A()().primitiveField());
    rA_.setSize(cells_.size());
    forAll(cells_, i)
    {
        rA_[i] = 1/max(A[cells_[i]], VSMALL);
    }
}


void Foam::foamDEM::flowController::correct(volVectorField& U)
{
    Ulatest_ = meanVelocity(U);
    tLatest_ = mesh_.time().value();
    forceLatest_ = force_;
    updatedLatest_ = updated_;

    // The next step's sensitivity uses this step's matrix (rA_) and
    // multipliers: keep them in the state, so that a run continued from a
    // write takes the same first update as the run straight through (only
    // the state written matters: copied at write times only)
    if (mesh_.time().writeTime() && rA_.size() == cells_.size())
    {
        state_.set("rA", rA_);
        state_.set("multiplier", multiplier_);
    }
}


bool Foam::foamDEM::flowController::read(const dictionary& dict)
{
    if (fv::cellSetOption::read(dict))
    {
        readControls();
        return true;
    }
    return false;
}
