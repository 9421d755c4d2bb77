// How a job ends after an error, decided by its ranks agreeing (core/job_end.hpp), as tubeform's main ends it.
// Run on 2 ranks by tests/check_rank_errors.py:
//   mpirun -n 2 test_agree MODE SECONDS
// MODE
//   every  every rank raises the same input error (PETSC_ERR_USER_INPUT, the way a value broadcast first is refused)
//   alone  rank 1 alone raises PETSC_ERR_USER_INPUT (a PetscCheck on PETSC_COMM_SELF, or on a value only it holds)
//          while rank 0 goes on into a collective call that rank 1 will never join
//   late   rank 1 alone raises it after the last collective call; rank 0 ends without error
//   cleanup every rank raises an input error; unwinding it, a destructor's clean-up fails with an error of its own
//          (as a result file closed on the full disk that stopped the run): the first error is the one reported
//   none   no error
// SECONDS is how long a rank with an error waits for the others (tubeform: kAgreeSeconds).
#include <petscsys.h>

#include <cstdlib>
#include <string>

#include "tubeform/core/job_end.hpp"

#ifndef PETSC_SUCCESS
#define PETSC_SUCCESS 0
#endif

static PetscErrorCode FailedClose()
{
  PetscFunctionBeginUser;
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Error in HDF5 call H5Fclose() Status -1");
}

// Holds something its destructor closes; the close fails.
struct Closing {
  ~Closing()
  {
    tf::KeepErrorText([] { (void)FailedClose(); });
  }
};

static PetscErrorCode Body(const std::string &mode)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (mode == "cleanup") {
    Closing file;
    SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_FILE_WRITE, "-output x.h5: 0 MB free on its file system");
  }
  if (mode == "every") SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-test_value 3: must be below 2");
  if (mode == "alone") {
    PetscCheck(rank != 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-test_file x: only rank 1 read it and refused it");
    PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD)); // rank 0: waits here for rank 1, which has left
  }
  if (mode == "late") {
    PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));
    PetscCheck(rank != 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-test_file x: only rank 1 read it and refused it");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  if (argc < 3) return 3;
  const std::string mode = argv[1];
  const double seconds = std::atof(argv[2]);
  PetscErrorCode ierr = PetscInitialize(&argc, &argv, nullptr, nullptr);
  if (ierr) return 1;
  (void)PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm agree;
  (void)MPI_Comm_dup(PETSC_COMM_WORLD, &agree);
  ierr = Body(mode);
  (void)PetscPopErrorHandler();
  const int code = tf::EndJob(agree, ierr, seconds);
  (void)MPI_Comm_free(&agree);
  ierr = PetscFinalize();
  return code ? code : (ierr ? 1 : 0);
}
