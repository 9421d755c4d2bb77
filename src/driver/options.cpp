#include "tubeform/driver/options.hpp"

#include <cmath>
#include <fstream>

#include "tubeform/core.hpp"

namespace tf {

namespace {
const char *const kScenes[] = {"squaring", "flattening", "pressure", "shear", "rotation", "column"};
const char *const kElements[] = {"q4", "bbar"};
const char *const kMaterials[] = {"aluminum", "copper", "custom"};
const char *const kLaws[] = {"elastic", "ludwik", "swift", "table"};

} // namespace

PetscErrorCode ReadOptions(MPI_Comm comm, Options &opt)
{
  PetscInt choice;
  char buf[PETSC_MAX_PATH_LEN];
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &opt.help));

  PetscOptionsBegin(comm, "", "tubeform: scene and geometry", "tubeform");
  choice = static_cast<PetscInt>(opt.scene);
  PetscCall(PetscOptionsEList("-scene", "Scene to run", "tubeform", kScenes, 6, kScenes[choice], &choice, &set));
  opt.scene = static_cast<SceneKind>(choice);
  opt.scene_name = kScenes[choice];
  PetscCall(PetscOptionsReal("-tube_ro", "Outer radius of the tube (mm)", "tubeform", opt.tube_ro, &opt.tube_ro, nullptr));
  PetscCall(PetscOptionsReal("-tube_t", "Wall thickness (mm)", "tubeform", opt.tube_t, &opt.tube_t, nullptr));
  PetscCall(PetscOptionsInt("-mesh_nt", "Elements through the wall (structured mesh)", "tubeform", opt.mesh_nt, &opt.mesh_nt, nullptr));
  PetscCall(PetscOptionsInt("-mesh_ntheta", "Elements around the quarter (structured mesh)", "tubeform", opt.mesh_ntheta, &opt.mesh_ntheta, nullptr));
  buf[0] = 0;
  PetscCall(PetscOptionsString("-mesh_file", "Gmsh 4.1 ASCII quad mesh with physical curves inner, outer, x0, y0 (replaces the structured mesh)", "tubeform", buf, buf, sizeof(buf), &set));
  if (set) opt.mesh_file = buf;
  choice = 1;
  PetscCall(PetscOptionsEList("-element", "Element formulation: q4 (full integration), bbar (mean dilatation)", "tubeform", kElements, 2, kElements[choice], &choice, nullptr));
  opt.element = choice == 0 ? fe::Formulation::Q4 : fe::Formulation::BBar;
  opt.element_name = kElements[choice];
  PetscOptionsEnd();

  PetscOptionsBegin(comm, "", "tubeform: material", "tubeform");
  choice = 0;
  PetscCall(PetscOptionsEList("-material", "Material preset (Huang 2008, Table 1) or custom", "tubeform", kMaterials, 3, kMaterials[choice], &choice, nullptr));
  MaterialPreset(kMaterials[choice], opt.material);
  PetscCall(PetscOptionsReal("-material_e", "Young's modulus E (MPa)", "tubeform", opt.material.E, &opt.material.E, nullptr));
  PetscCall(PetscOptionsReal("-material_nu", "Poisson's ratio", "tubeform", opt.material.nu, &opt.material.nu, nullptr));
  PetscCall(PetscOptionsReal("-material_sy", "Initial yield stress (MPa)", "tubeform", opt.material.sy, &opt.material.sy, nullptr));
  PetscCall(PetscOptionsReal("-material_k", "Hardening coefficient K (MPa)", "tubeform", opt.material.K, &opt.material.K, nullptr));
  PetscCall(PetscOptionsReal("-material_n", "Hardening exponent n", "tubeform", opt.material.n, &opt.material.n, nullptr));
  choice = 1;
  for (PetscInt k = 0; k < 4; ++k)
    if (opt.material.law == kLaws[k]) choice = k;
  PetscCall(PetscOptionsEList("-material_law", "Flow curve: elastic (no yield), ludwik sy+K ep^n, swift K(ep0+ep)^n, table", "tubeform", kLaws, 4, kLaws[choice], &choice, nullptr));
  opt.material.law = kLaws[choice];
  PetscOptionsEnd();

  PetscOptionsBegin(comm, "", "tubeform: loading and output", "tubeform");
  PetscCall(PetscOptionsInt("-increments", "Number of (trial) load increments", "tubeform", opt.increments, &opt.increments, nullptr));
  PetscCall(PetscOptionsReal("-pressure_p", "Final internal pressure of the pressure scene (MPa)", "tubeform", opt.pressure_p, &opt.pressure_p, nullptr));
  PetscCall(PetscStrncpy(buf, opt.output.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString("-output", "HDF5 result file (an .xmf for ParaView is written beside it)", "tubeform", buf, buf, sizeof(buf), nullptr));
  opt.output = buf;
  buf[0] = 0;
  PetscCall(PetscOptionsString("-history_csv", "Also write the history as CSV to this file", "tubeform", buf, buf, sizeof(buf), &set));
  if (set) opt.history_csv = buf;
  PetscCall(PetscOptionsInt("-output_every", "Write fields every k-th increment (the last is always written)", "tubeform", opt.output_every, &opt.output_every, nullptr));
  PetscCall(PetscOptionsBool("-monitor", "Print one line per increment on rank 0", "tubeform", opt.monitor, &opt.monitor, nullptr));
  PetscOptionsEnd();

  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);

  // Validation: one message per problem, naming the option and the allowed range.
  const auto &m = opt.material;
  PetscCheck(opt.tube_ro > 0 && std::isfinite(opt.tube_ro), comm, PETSC_ERR_USER_INPUT, "-tube_ro %g: the outer radius must be a positive number of mm", opt.tube_ro);
  PetscCheck(opt.tube_t > 0 && opt.tube_t < opt.tube_ro, comm, PETSC_ERR_USER_INPUT, "-tube_t %g: the wall thickness must be positive and smaller than -tube_ro %g", opt.tube_t, opt.tube_ro);
  PetscCheck(opt.mesh_nt >= 1 && opt.mesh_nt <= 1000, comm, PETSC_ERR_USER_INPUT, "-mesh_nt %d: must be between 1 and 1000", (int)opt.mesh_nt);
  PetscCheck(opt.mesh_ntheta >= 2 && opt.mesh_ntheta <= 100000, comm, PETSC_ERR_USER_INPUT, "-mesh_ntheta %d: must be between 2 and 100000", (int)opt.mesh_ntheta);
  PetscCheck(m.E > 0, comm, PETSC_ERR_USER_INPUT, "-material_e %g: Young's modulus must be positive (MPa)", m.E);
  PetscCheck(m.nu > -1 && m.nu < 0.5, comm, PETSC_ERR_USER_INPUT, "-material_nu %g: Poisson's ratio must lie in (-1, 0.5)", m.nu);
  PetscCheck(m.sy > 0, comm, PETSC_ERR_USER_INPUT, "-material_sy %g: the yield stress must be positive (MPa)", m.sy);
  PetscCheck(m.K >= 0, comm, PETSC_ERR_USER_INPUT, "-material_k %g: the hardening coefficient must be non-negative (MPa)", m.K);
  PetscCheck(m.n > 0 && m.n <= 1, comm, PETSC_ERR_USER_INPUT, "-material_n %g: the hardening exponent must lie in (0, 1]", m.n);
  PetscCheck(opt.increments >= 1 && opt.increments <= 10000000, comm, PETSC_ERR_USER_INPUT, "-increments %d: must be between 1 and 1e7", (int)opt.increments);
  PetscCheck(std::isfinite(opt.pressure_p), comm, PETSC_ERR_USER_INPUT, "-pressure_p %g: must be a finite pressure (MPa)", opt.pressure_p);
  PetscCheck(opt.output_every >= 1, comm, PETSC_ERR_USER_INPUT, "-output_every %d: must be at least 1", (int)opt.output_every);
  PetscCheck(!opt.output.empty(), comm, PETSC_ERR_USER_INPUT, "-output: an HDF5 file name is required");
  if (!opt.mesh_file.empty()) {
    std::ifstream probe(opt.mesh_file);
    PetscCheck(probe.good(), comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: cannot open the file (missing or unreadable)", opt.mesh_file.c_str());
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
