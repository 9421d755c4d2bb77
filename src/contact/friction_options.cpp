// The contact and friction options: read into a FrictionParams (their own group in -help) and checked, one line
// naming the option.
#include "tubeform/contact/friction_options.hpp"

namespace tf {

PetscErrorCode ReadFrictionOptions(MPI_Comm comm, OptionReader &read, FrictionParams &f)
{

  PetscFunctionBeginUser;
  TF_OPTIONS_BEGIN(comm, "tubeform: contact and friction");
  PetscCall(read.Real(PetscOptionsObject, "-friction_mu",
                      "Coulomb friction coefficient (0: frictionless, no friction work at all)", f.mu));
  PetscCall(read.Real(PetscOptionsObject, "-friction_vcri",
                      "Quasi-stick slip VCRI (mm) of the tanh law; 0: 2% of the circumferential element size", f.vcri));
  PetscCall(read.Real(PetscOptionsObject, "-friction_tol",
                      "Friction iterations: largest change of f_l / (mu f_n) between iterates", f.tol));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_dphi",
                      "r6, slide to stick: largest fall of the friction mobilization f_l / (mu f_n), towards "
                      "stick or through it into a reversal, in an increment",
                      f.rmin_dphi));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_dphi_rise",
                      "r6, stick to slide: largest rise of |f_l / (mu f_n)| in an increment (1: no bound)",
                      f.rmin_dphi_rise));
  TF_OPTIONS_END();
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckFrictionOptions(MPI_Comm comm, const FrictionParams &f)
{
  PetscFunctionBeginUser;
  PetscCheck(f.mu >= 0 && f.mu <= 2, comm, PETSC_ERR_USER_INPUT,
             "-friction_mu %g: the friction coefficient must lie in [0, 2]", f.mu);
  PetscCheck(f.vcri >= 0, comm, PETSC_ERR_USER_INPUT, "-friction_vcri %g: must be non-negative (0: automatic)", f.vcri);
  PetscCheck(f.rmin_dphi > 0 && f.rmin_dphi <= 2, comm, PETSC_ERR_USER_INPUT, "-rmin_dphi %g: must lie in (0, 2]",
             f.rmin_dphi);
  PetscCheck(f.rmin_dphi_rise > 0 && f.rmin_dphi_rise <= 1, comm, PETSC_ERR_USER_INPUT,
             "-rmin_dphi_rise %g: must lie in (0, 1]", f.rmin_dphi_rise);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
