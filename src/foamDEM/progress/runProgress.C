#include "runProgress.H"
#include "stopSignals.H"

Foam::foamDEM::runProgress::estimate
Foam::foamDEM::runProgress::estimateOf
(
    scalar t0, scalar t, scalar tEnd, scalar wallSinceT0
)
{
    estimate e;
    e.fraction = tEnd > 0 ? t/tEnd : 0;
    if (t > t0)
    {
        e.rate = wallSinceT0/(t - t0);
        e.eta = max(tEnd - t, scalar(0))*e.rate;
    }
    return e;
}


Foam::foamDEM::runProgress::runProgress
(
    const Time& runTime,
    const dictionary& couplingDict
)
:
    runTime_(runTime),
    interval_(couplingDict.getOrDefault<label>("progressInterval", 100)),
    created_(clock::now()),
    started_(created_),
    isStarted_(false),
    t0_(runTime.value()),
    endTime_(runTime.endTime().value()),
    steps_(0),
    lastWall_(0),
    lastT_(runTime.value())
{
    if (interval_ < 0)
    {
        FatalIOErrorInFunction(couplingDict)
            << "progressInterval must be >= 0 (0: no progress lines), got "
            << interval_ << exit(FatalIOError);
    }
}


Foam::scalar Foam::foamDEM::runProgress::seconds(clock::time_point since) const
{
    return std::chrono::duration<double>(clock::now() - since).count();
}


void Foam::foamDEM::runProgress::start()
{
    started_ = clock::now();
    isStarted_ = true;
    t0_ = runTime_.value();
    lastT_ = t0_;
    lastWall_ = 0;
}


namespace
{
    Foam::string minutes(Foam::scalar s)
    {
        char buf[64];
        if (s < 120) std::snprintf(buf, sizeof buf, "%.3g s", s);
        else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1f min", s/60);
        else std::snprintf(buf, sizeof buf, "%.2f h", s/3600);
        return buf;
    }

    Foam::string percent(Foam::scalar part, Foam::scalar whole)
    {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.1f %%", whole > 0 ? 100*part/whole : 0.0);
        return buf;
    }
}


void Foam::foamDEM::runProgress::print
(
    const char* head,
    const split& s,
    bool withRecent
)
{
    // The time reached: the previous step's end while a step is starting
    const scalar t = withRecent
        ? runTime_.value() - runTime_.deltaTValue() : runTime_.value();
    const scalar wall = seconds(started_);
    // The case's endTime (a stop signal sets the Time's to the stop)
    const scalar tEnd = endTime_;
    const estimate e = estimateOf(t0_, t, tEnd, wall);
    const scalar cfd = max(wall - s.dem - s.coupling - s.output, scalar(0));

    char buf[256];
    Info<< head << "t = " << t << " s (" << percent(e.fraction, 1).c_str()
        << " of " << tEnd << " s), ";
    // The rate in s or min of wall per simulated s, whichever reads better
    const bool inMin = e.rate >= 120;
    const scalar unit = inMin ? 60 : 1;
    std::snprintf
    (
        buf, sizeof buf, "%.3g %s wall per simulated s", e.rate/unit,
        inMin ? "min" : "s"
    );
    Info<< buf;
    if (withRecent && t > lastT_)
    {
        std::snprintf
        (
            buf, sizeof buf, " (last %d steps %.3g)", int(interval_),
            (wall - lastWall_)/(t - lastT_)/unit
        );
        Info<< buf;
        Info<< ", ETA " << minutes(e.eta).c_str();
    }
    Info<< "; wall " << minutes(wall).c_str() << ": DEM "
        << percent(s.dem, wall).c_str() << ", coupling "
        << percent(s.coupling, wall).c_str() << ", output "
        << percent(s.output, wall).c_str() << ", CFD "
        << percent(cfd, wall).c_str() << endl;
    lastWall_ = wall;
    lastT_ = t;
}


void Foam::foamDEM::runProgress::step(const split& s)
{
    if (!isStarted_) start();
    ++steps_;
    // steps_ counts the step now starting: the previous one has ended
    if (interval_ > 0 && steps_ > 1 && (steps_ - 1) % interval_ == 0)
    {
        print("foamDEM progress: ", s, true);
    }
}


void Foam::foamDEM::runProgress::summary(const split& s)
{
    if (!isStarted_) return;
    Info<< "foamDEM run: from " << t0_ << " s, set-up "
        << minutes(std::chrono::duration<double>(started_ - created_).count()).c_str()
        << "; ";
    print("", s, false);
    if
    (
        stopSignals::stopped()
     && runTime_.value() < endTime_ - 0.5*runTime_.deltaTValue()
    )
    {
        // The run's last step, written, by a SIGUSR2 (stopSignals.H), not
        // the case's last anyway
        Info<< "foamDEM run: stopped by SIGUSR2 at t = " << runTime_.value()
            << " s, before endTime " << endTime_ << " s; written at "
            << runTime_.timeName() << ": continue from that write"
            << " (startFrom latestTime; a tutorial's ./Allrun -continue)"
            << endl;
    }
}
