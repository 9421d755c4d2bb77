#include "tubeform/step/rmin.hpp"

#include <algorithm>
#include <cmath>

namespace tf {

const char *LimiterName(int code)
{
  static const char *names[kNumLimiters] = {"trial",   "final",      "yield", "strain", "rotation",
                                            "contact", "separation", "stick", "slide"};
  return code >= 0 && code < kNumLimiters ? names[code] : "unknown";
}

double MaxPrincipalStrain(const fe::Voigt &e)
{
  // In-plane eigenvalues of [[exx, gxy/2], [gxy/2, eyy]], and ezz.
  const double c = 0.5 * (e[0] + e[1]), rad = std::hypot(0.5 * (e[0] - e[1]), 0.5 * e[3]);
  return std::max({std::abs(c + rad), std::abs(c - rad), std::abs(e[2])});
}

PetscErrorCode ReduceStepLimit(MPI_Comm comm, StepLimit &limit)
{
  struct {
    double r;
    int rank;
  } in, out;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  in.r = limit.r;
  in.rank = rank;
  PetscCallMPI(MPI_Allreduce(&in, &out, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm));
  PetscInt info[2] = {static_cast<PetscInt>(limit.who), limit.where};
  PetscCallMPI(MPI_Bcast(info, 2, MPIU_INT, out.rank, comm));
  limit.r = out.r;
  limit.who = static_cast<Limiter>(info[0]);
  limit.where = info[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
