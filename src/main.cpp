// tubeform: elasto-plastic FE analysis of squaring a circular tube between
// V-shaped dies (Huang 2008), on PETSc.
//
// Sample runs:
//   mpirun -n 2 build/tubeform -options_file options/pressure.opts -monitor
//   build/tubeform -help
#include <petscsys.h>

#include <cstdlib>
#include <string>

#include "tubeform/core/core.hpp"
#include "tubeform/core/signals.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/io/options_files.hpp"
#include "tubeform/scenes/registry.hpp"

static const char help[] =
  "tubeform: updated-Lagrangian elasto-plastic FE analysis of tube squaring (plane strain).\n"
  "Usage: mpirun -n 2 build/tubeform -options_file options/<scene>.opts [-option value ...]\n\n";

// `collective` tells main whether an error seen so far was found by every
// rank at once (option parsing is: each rank reads the same options).
static PetscErrorCode Run(bool &collective)
{
  tf::Options opt;
  PetscFunctionBeginUser;
  collective = true;
  PetscCall(tf::ReadOptions(PETSC_COMM_WORLD, tf::SceneNames(), opt));
  collective = false;
  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);
  tf::Problem problem;
  PetscCall(problem.Setup(PETSC_COMM_WORLD, opt));
  PetscCall(problem.Run());
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscMPIInt rank;
  // A missing options file, before PETSc reads them (it would stop with a
  // 30-line error): every process finds the same, the first one says it.
  const std::string bad_file = tf::CheckOptionsFiles(argc, argv);
  if (!bad_file.empty()) {
    const char *launcher_rank = std::getenv("OMPI_COMM_WORLD_RANK"); // set by mpirun before MPI starts
    if (!launcher_rank) launcher_rank = std::getenv("PMI_RANK");
    if (!launcher_rank || std::atoi(launcher_rank) == 0) fprintf(stderr, "tubeform: error: %s\n", bad_file.c_str());
    return 1;
  }
  PetscErrorCode ierr = PetscInitialize(&argc, &argv, nullptr, help);
  if (ierr) return 1;
  // Errors come back as codes; main prints one line and every rank exits.
  (void)PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  tf::InstallStopSignals();
  (void)MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  bool collective = false;
  ierr = Run(collective);
  (void)PetscPopErrorHandler();
  if (ierr) {
    const char *text = nullptr;
    char *specific = nullptr;
    (void)PetscErrorMessage(ierr, &text, &specific);
    const char *msg = specific && specific[0] ? specific : (text ? text : "unknown error");
    if (collective || ierr == PETSC_ERR_USER_INPUT || ierr == PETSC_ERR_FILE_WRITE || ierr == PETSC_ERR_NOT_CONVERGED ||
        ierr == PETSC_ERR_SIG) {
      // Collective errors: every rank found the same problem; rank 0 reports it.
      if (rank == 0) fprintf(stderr, "tubeform: error: %s\n", msg);
      (void)PetscFinalize();
      return 1;
    }
    // Anything else may have struck one rank only: report it and abort the job
    // so that no rank waits forever in a collective call.
    fprintf(stderr, "tubeform: error on rank %d: %s\n", rank, msg);
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  ierr = PetscFinalize();
  return ierr ? 1 : 0;
}
