#include "tubeform/core/signals.hpp"

#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <initializer_list>

namespace tf {

namespace {

volatile std::sig_atomic_t received = 0;
bool installed = false; // InstallStopSignals was called

extern "C" void OnStopSignal(int sig) { received = sig; }

// Before main (and MPI_Init, which may set variables of its own): whether an MPI
// launcher (mpirun) started this process, and the process that did.
const bool launched = std::getenv("OMPI_COMM_WORLD_RANK") || std::getenv("PMI_RANK") || std::getenv("PMIX_RANK");
const pid_t launcher = getppid();

} // namespace

void RearmStopSignals()
{
  if (!installed) return;
  struct sigaction action = {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART; // system calls in progress (file writes, MPI) carry on
  for (int sig : {SIGINT, SIGTERM, SIGUSR1}) sigaction(sig, &action, nullptr);
}

void InstallStopSignals()
{
  installed = true;
  RearmStopSignals();
  // A write to an output whose reader is gone (mpirun's, once it has left)
  // fails instead of ending the run, which goes on to write its results.
  signal(SIGPIPE, SIG_IGN);
  // A rank whose launcher dies is told so by a SIGTERM of its own (Linux):
  // mpirun killed, or sent a second SIGTERM or SIGINT (as `timeout` sends one
  // to it and one to its process group), leaves at once, the second time
  // without waiting for its ranks, which would run on unseen. (Not for a run
  // without mpirun: its parent is a shell, which may end while it goes on, as
  // under nohup.)
  if (launched) {
    (void)prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != launcher) received = SIGTERM; // (it died before the request)
  }
}

int StopSignal() { return received; }

const char *SignalName(int sig)
{
  switch (sig) {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  case SIGUSR1:
    return "SIGUSR1";
  default:
    return "a signal";
  }
}

} // namespace tf
