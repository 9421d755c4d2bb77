#include "tubeform/core/job_end.hpp"

#include <cstdio>
#include <ctime>
#include <vector>

namespace tf {

ErrorVerdict AgreeOnError(MPI_Comm agree, PetscErrorCode mine, double seconds)
{
  ErrorVerdict v;
  int size = 1;
  (void)MPI_Comm_size(agree, &size);
  std::vector<int> codes(size, 0);
  const int code = (int)mine;
  MPI_Request request;
  if (MPI_Iallgather(&code, 1, MPI_INT, codes.data(), 1, MPI_INT, agree, &request) != MPI_SUCCESS) {
    v.all_answered = false;
    return v;
  }
  // A rank that met no error waits for the others as long as they take: if
  // one of them did, its own wait ends the job.
  if (!mine) {
    (void)MPI_Wait(&request, MPI_STATUS_IGNORE);
  } else {
    const double end = MPI_Wtime() + seconds;
    int done = 0;
    const timespec pause = {0, 1000000}; // 1 ms between looks
    while (!done && MPI_Wtime() < end) {
      (void)MPI_Test(&request, &done, MPI_STATUS_IGNORE);
      if (!done) nanosleep(&pause, nullptr);
    }
    if (!done) {
      v.all_answered = false; // (the request stays pending: the job ends)
      return v;
    }
  }
  for (int r = 0; r < size; ++r)
    if (codes[r]) {
      if (v.first < 0) v.first = r, v.code = codes[r];
      ++v.failed;
    }
  return v;
}

std::string ErrorText(PetscErrorCode code)
{
  const char *text = nullptr;
  char *specific = nullptr;
  (void)PetscErrorMessage(code, &text, &specific);
  return specific && specific[0] ? specific : (text ? text : "unknown error");
}

void KeepErrorText(const std::function<void()> &cleanup)
{
  char *specific = nullptr;
  (void)PetscErrorMessage(0, nullptr, &specific);
  const std::string kept = specific ? specific : "";
  cleanup();
  (void)PetscErrorMessage(0, nullptr, &specific);
  // Raised again (silently: errors return codes here), the kept text is the last error's once more.
  if (!kept.empty() && kept != (specific ? specific : ""))
    (void)PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, PETSC_ERR_LIB, PETSC_ERROR_INITIAL, "%s",
                     kept.c_str());
}

int EndJob(MPI_Comm agree, PetscErrorCode ierr, double seconds)
{
  int rank = 0, size = 1;
  (void)MPI_Comm_rank(agree, &rank);
  (void)MPI_Comm_size(agree, &size);
  const ErrorVerdict v = AgreeOnError(agree, ierr, seconds);
  if (!v.all_answered) {
    // Only a rank with an error stops waiting: the others are held elsewhere.
    std::fprintf(stderr,
                 "tubeform: error on rank %d: %s (the other ranks did not stop with it within %g s: the job "
                 "is aborted)\n",
                 rank, ErrorText(ierr).c_str(), seconds);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  if (v.failed == 0) return 0;
  if (v.failed == size) {
    // Every rank met it: rank 0 says it.
    if (rank == 0) std::fprintf(stderr, "tubeform: error: %s\n", ErrorText(ierr).c_str());
  } else if (rank == v.first) {
    // Some ranks met it, and the others ended without it: the first says it.
    std::fprintf(stderr, "tubeform: error on rank %d: %s\n", rank, ErrorText(ierr).c_str());
  }
  return 1;
}

} // namespace tf
