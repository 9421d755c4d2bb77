#include "tubeform/core/signals.hpp"

#include <csignal>
#include <initializer_list>

namespace tf {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void OnStopSignal(int sig) { received = sig; }

} // namespace

void InstallStopSignals()
{
  struct sigaction action = {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART; // system calls in progress (file writes, MPI) carry on
  for (int sig : {SIGINT, SIGTERM, SIGUSR1}) sigaction(sig, &action, nullptr);
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
