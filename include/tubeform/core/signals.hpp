// Stopping a run cleanly on request: SIGINT (Ctrl-C), SIGTERM (a kill, a
// batch system's end of job) and SIGUSR1 (a scheduler's warning before the
// kill; Open MPI's mpirun forwards it to every rank) only set a flag; the
// driver looks at it before every solve and between increments, the ranks
// agreeing on it, and ends the run as it ends one that reached -time_limit:
// results written, flagged, one line, non-zero exit.
#pragma once

namespace tf {

// Installs the handlers (after PetscInitialize, replacing PETSc's for these
// signals, which would abort at once); SIGPIPE is ignored, and a rank started
// by an MPI launcher receives SIGTERM when the launcher dies.
void InstallStopSignals();
// Installs the handlers again, if InstallStopSignals did: after a library call
// that replaced them (METIS) and put them back for one signal only.
void RearmStopSignals();
// The last stop signal received by this process, 0 if none.
int StopSignal();
// Its name ("SIGTERM", ...).
const char *SignalName(int sig);

} // namespace tf
