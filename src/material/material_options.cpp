// The material's options, read by the material: -material (a library name, a file or custom) and the constants,
// law, hardening and anisotropy that override its values (include/tubeform/material/material_options.hpp).
#include "tubeform/material/material_options.hpp"

#include <cmath>

#include "tubeform/material/library.hpp"

namespace tf {

PetscErrorCode ReadMaterialOptions(MPI_Comm comm, OptionReader &read, MaterialParams &material)
{
  PetscFunctionBeginUser;
  TF_OPTIONS_BEGIN(comm, "tubeform: material");
  {
    std::string dir, name = material.name;
    PetscCall(read.String(PetscOptionsObject, "-material_library",
                          "Folder of the named materials (default: the source tree's options/materials)", dir));
    dir = MaterialLibraryDir(dir);
    std::string help = "Material: a name from the library (";
    for (const auto &m : LibraryMaterials(dir)) help += m + ", ";
    help += "docs/options.md \"Materials\"), a material file (path.opts), or custom (-material_e, ... given)";
    PetscCall(read.String(PetscOptionsObject, "-material", help.c_str(), name));
    PetscCall(LoadMaterial(comm, name, dir, material));
  }
  PetscCall(read.Real(PetscOptionsObject, "-material_e", "Young's modulus E (MPa)", material.E));
  PetscCall(read.Real(PetscOptionsObject, "-material_nu", "Poisson's ratio", material.nu));
  PetscCall(read.Real(PetscOptionsObject, "-material_sy", "Initial yield stress (MPa)", material.sy));
  PetscCall(read.Real(PetscOptionsObject, "-material_k", "Hardening coefficient K (MPa)", material.K));
  PetscCall(read.Real(PetscOptionsObject, "-material_n", "Hardening exponent n", material.n));
  PetscCall(read.Real(PetscOptionsObject, "-material_density",
                      "Mass density (t/mm^3; aluminum 2.70e-9), used by -dynamics implicit", material.density));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-material_law",
                       "Flow curve: elastic (no yield), ludwik sy+K ep^n, swift K(ep0+ep)^n, table", kFlowLawWords,
                       material.law));
  PetscCall(RealList(PetscOptionsObject, read, "-material_table",
                     "Flow curve for -material_law table: ep0,sy0,ep1,sy1,... (ep0 = 0, ep increasing)",
                     kMaxTableNumbers, material.table));
  PetscCall(RealList(PetscOptionsObject, read, "-material_kinematic",
                     "Backstresses for -hardening chaboche: C1,gamma1[,C2,gamma2[,C3,gamma3]] (MPa, -; gamma 0: "
                     "linear); their share of the flow curve moves to the kinematic part",
                     2 * kMaxBackstresses, material.kinematic));
  PetscCall(RealList(PetscOptionsObject, read, "-material_r",
                     "Hill 1948 yield from the Lankford coefficients r0,r45,r90 (0: along the tube, 90: across; r45 "
                     "does not act in plane strain); 1,1,1: von Mises",
                     3, material.lankford));
  PetscCall(RealList(PetscOptionsObject, read, "-material_hill",
                     "Hill 1948 yield from F,G,H,L in the tube's axes (1 axial, 2 hoop, 3 radial; von Mises: "
                     "0.5,0.5,0.5,1.5)",
                     4, material.hill));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-material_axes",
                       "The material's radial axis for -material_r/-material_hill: tube (from the tube's centre to "
                       "the point, turning with the material) or fixed (at -material_axes_angle)",
                       kMaterialAxesWords, material.axes));
  {
    double degrees = material.axes_angle * 180 / M_PI;
    PetscCall(read.Real(PetscOptionsObject, "-material_axes_angle",
                        "With -material_axes fixed: the radial axis's angle from x (degrees)", degrees));
    material.axes_angle = degrees * M_PI / 180;
  }
  PetscCall(ChooseWord(PetscOptionsObject, read, "-hardening",
                       "isotropic (the flow curve expands the yield surface), or chaboche (the backstresses of "
                       "-material_kinematic move it; the same monotonic flow curve)",
                       kHardeningWords, material.hardening));
  TF_OPTIONS_END();
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
