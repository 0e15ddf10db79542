#include "stopSignals.H"
#include "Pstream.H"
#include <pthread.h>
#include <ctime>

volatile std::sig_atomic_t Foam::foamDEM::stopSignals::recorded_ = 0;


void Foam::foamDEM::stopSignals::record(int sig)
{
    const std::sig_atomic_t r = (sig == SIGUSR2 ? 2 : 1);
    if (recorded_ < r)
    {
        recorded_ = r;
    }
}


namespace
{
    sigset_t stopSet()
    {
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, SIGUSR1);
        sigaddset(&set, SIGUSR2);
        return set;
    }
}


Foam::foamDEM::stopSignals::stopSignals()
:
    reported_(false)
{
    struct sigaction act;
    act.sa_handler = record;
    act.sa_flags = SA_RESTART;
    sigemptyset(&act.sa_mask);
    sigaction(SIGUSR1, &act, nullptr);
    sigaction(SIGUSR2, &act, nullptr);

    const sigset_t set = stopSet();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
}


int Foam::foamDEM::stopSignals::check(Time& runTime)
{
    if (!reported_)
    {
        Info<< "foamDEM: SIGUSR1 writes the current step, SIGUSR2 writes it"
            << " and stops the run (checked once per time step)" << endl;
        reported_ = true;
    }

    const sigset_t set = stopSet();
    const timespec noWait{0, 0};
    label request = recorded_;
    recorded_ = 0;
    for (int sig; (sig = sigtimedwait(&set, nullptr, &noWait)) > 0;)
    {
        request = max(request, label(sig == SIGUSR2 ? 2 : 1));
    }
    reduce(request, maxOp<label>());

    if (request == 2)
    {
        Info<< "foamDEM: SIGUSR2: writing this step and stopping" << endl;
        runTime.stopAt(Time::saWriteNow);
    }
    else if (request == 1)
    {
        Info<< "foamDEM: SIGUSR1: writing this step" << endl;
        runTime.writeOnce();
    }
    return int(request);
}
