#include "stopSignals.H"
#include "Pstream.H"
#include <atomic>
#include <pthread.h>
#include <ctime>

namespace
{
    // The request a handler recorded: 0 none, 1 write, 2 write and stop
    // (lock-free, so usable in a handler and across threads)
    std::atomic<int> recorded(0);

    // Set when check() has taken a SIGUSR2: the run ends at this step
    bool stopped = false;

    void raiseTo(int r)
    {
        int old = recorded.load();
        while (old < r && !recorded.compare_exchange_weak(old, r)) {}
    }

    void record(int sig)
    {
        raiseTo(sig == SIGUSR2 ? 2 : 1);
    }

    sigset_t stopSet()
    {
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, SIGUSR1);
        sigaddset(&set, SIGUSR2);
        return set;
    }

    // A forked child (LIGGGHTS' shell, OpenFOAM's systemCall) starts with
    // the signals unblocked again
    void unblockInChild()
    {
        const sigset_t set = stopSet();
        pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    }
}


Foam::foamDEM::stopSignals::stopSignals()
:
    reported_(false)
{
    const sigset_t set = stopSet();

    struct sigaction act;
    act.sa_handler = record;
    act.sa_flags = SA_RESTART;
    act.sa_mask = set;
    sigaction(SIGUSR1, &act, nullptr);
    sigaction(SIGUSR2, &act, nullptr);

    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    pthread_atfork(nullptr, nullptr, unblockInChild);
}


bool Foam::foamDEM::stopSignals::stopped()
{
    return ::stopped;
}


int Foam::foamDEM::stopSignals::check(Time& runTime)
{
    if (!reported_)
    {
        Info<< "foamDEM: SIGUSR1 writes the coming time step, SIGUSR2"
            << " writes it and stops the run (checked once per time step)"
            << endl;
        reported_ = true;
    }

    const sigset_t set = stopSet();
    const timespec noWait{0, 0};
    label request = recorded.exchange(0);
    for (int sig; (sig = sigtimedwait(&set, nullptr, &noWait)) > 0;)
    {
        request = max(request, label(sig == SIGUSR2 ? 2 : 1));
    }
    reduce(request, maxOp<label>());

    if (request == 2)
    {
        Info<< "foamDEM: SIGUSR2: writing the coming time step and stopping"
            << endl;
        runTime.stopAt(Time::saWriteNow);
        ::stopped = true;
    }
    else if (request == 1)
    {
        Info<< "foamDEM: SIGUSR1: writing the coming time step" << endl;
        runTime.writeOnce();
    }
    return int(request);
}
