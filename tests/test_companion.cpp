// The error estimate's companion run as the driver meets it (Problem::Finish, Problem::Estimate): a tubeform run
// whose companion ends as MODE says, run from the source directory by tests/check_companion.py:
//   mpirun -n N test_companion MODE [tubeform options ...]
// MODE
//   input   every rank raises PETSC_ERR_USER_INPUT (as its coarser mesh's inverted element or a second pass's
//           die check do)
//   lib     every rank raises PETSC_ERR_LIB (a failed HDF5 or MUMPS call)
//   alone   rank 1 alone raises PETSC_ERR_LIB while rank 0 goes on into a collective call it will never join
//   signal  every rank returns PETSC_ERR_SIG (a stop signal during the companion)
//   rows    the companions give the run's own history, the steps' with every load 1 % higher: an estimate
//   fill    as rows, after filling the file system of -output (rank 0: a file `filler` beside it) to 100 kB free
// The job ends as tubeform's main ends it (core/job_end.hpp).
#include <petscsys.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tubeform/core/job_end.hpp"
#include "tubeform/driver/driver_options.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/scenes/registry.hpp"

static PetscErrorCode Companion(const std::string &mode, const std::string &output, const tf::Problem &run,
                                tf::Companions &out)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (mode == "input") SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "an element of the companion's mesh inverted");
  if (mode == "lib") SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_LIB, "HDF5 call failed: H5Dwrite (the companion's)");
  if (mode == "alone") {
    PetscCheck(rank != 1, PETSC_COMM_SELF, PETSC_ERR_LIB, "MUMPS failed on rank 1 alone (the companion's)");
    PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD)); // rank 0 waits here for rank 1, which has left
  }
  if (mode == "signal") SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_SIG, "interrupted by SIGTERM (the companion's)");
  if (mode == "fill" && rank == 0) {
    const auto dir = std::filesystem::absolute(output).parent_path();
    std::ofstream filler(dir / "filler", std::ios::binary);
    const std::vector<char> block(65536, 0);
    std::error_code ec;
    while (std::filesystem::space(dir, ec).available > 100000 && filler.write(block.data(), (long)block.size()))
      filler.flush();
  }
  out.mesh = out.steps = run.history().rows();
  for (auto &r : out.steps) r.load *= 1.01;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(const std::string &mode)
{
  tf::Options opt;
  PetscFunctionBeginUser;
  PetscCall(tf::ReadOptions(PETSC_COMM_WORLD, tf::DriverOptions(), tf::SceneReaders(), opt));
  tf::Problem problem;
  PetscCall(problem.Setup(PETSC_COMM_WORLD, opt));
  problem.SetCompanion(
    [&](const tf::Options &, tf::Companions &out) { return Companion(mode, opt.output, problem, out); });
  PetscCall(problem.Run());
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  if (argc < 2) return 3;
  const std::string mode = argv[1];
  argv[1] = argv[0]; // PETSc reads the options after MODE
  int n = argc - 1;
  char **rest = argv + 1;
  PetscErrorCode ierr = PetscInitialize(&n, &rest, nullptr, nullptr);
  if (ierr) return 1;
  (void)PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm agree;
  (void)MPI_Comm_dup(PETSC_COMM_WORLD, &agree);
  ierr = Run(mode);
  (void)PetscPopErrorHandler();
  const int code = tf::EndJob(agree, ierr);
  (void)MPI_Comm_free(&agree);
  ierr = PetscFinalize();
  return code ? code : (ierr ? 1 : 0);
}
