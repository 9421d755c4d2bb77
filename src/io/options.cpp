#include "tubeform/io/options.hpp"

#include <cmath>
#include <fstream>

#include "tubeform/core/core.hpp"
#include "tubeform/io/friction_options.hpp"
#include "tubeform/io/loading_options.hpp"
#include "tubeform/io/material_library.hpp"
#include "tubeform/io/option_reader.hpp"

namespace tf {

namespace {
const char *const kElements[] = {"q4", "bbar", "qm6", "qm6bar", "auto"};

// The scene, the tube and its mesh and element.
PetscErrorCode ReadScene(MPI_Comm comm, const std::vector<SceneOptions> &scenes, OptionReader &read, Options &opt)
{
  PetscInt choice;
  PetscBool set;

  PetscFunctionBeginUser;
  TF_OPTIONS_BEGIN(comm, "tubeform: scene and geometry");
  {
    std::vector<const char *> names;
    for (const auto &s : scenes) names.push_back(s.name.c_str());
    choice = 0;
    for (size_t k = 0; k < scenes.size(); ++k)
      if (scenes[k].name == opt.scene) choice = (PetscInt)k;
    read.Note("-scene", "Scene to run");
    PetscCall(PetscOptionsEList("-scene", "Scene to run", "tubeform", names.data(), (PetscInt)names.size(),
                                names[choice], &choice, &set));
    opt.scene = scenes[choice].name, opt.press = scenes[choice].press;
    if (!set && !opt.help) {
      std::string list;
      for (const auto &n : scenes) list += (list.empty() ? "" : ", ") + n.name;
      SETERRQ(comm, PETSC_ERR_USER_INPUT,
              "no scene given: run a scene file (-options_file options/squaring.opts, ...) or name one with -scene "
              "(%s)",
              list.c_str());
    }
  }
  PetscCall(read.Real(PetscOptionsObject, "-tube_ro", "Outer radius of the tube (mm)", opt.tube_ro));
  PetscCall(read.Real(PetscOptionsObject, "-tube_t", "Wall thickness (mm)", opt.tube_t));
  PetscCall(read.Int(PetscOptionsObject, "-mesh_nt",
                     "Elements through the wall (structured mesh); 0: from -mesh_wall_strain and the tube",
                     opt.mesh_nt));
  PetscCall(read.Real(PetscOptionsObject, "-mesh_wall_strain",
                      "With -mesh_nt 0: largest change of the ring's bending strain t/Ro across a cell (the presets: "
                      "fast 0.044, default 0.022, accurate 0.011)",
                      opt.mesh_wall_strain));
  PetscCall(read.Int(PetscOptionsObject, "-mesh_nt_min",
                     "With -mesh_nt 0: fewest elements through the wall (the presets: fast 2, default 4, accurate 8)",
                     opt.mesh_nt_min));
  PetscCall(read.Int(PetscOptionsObject, "-mesh_ntheta",
                     "Elements around the quarter (structured mesh); 0: from -mesh_density and the tube",
                     opt.mesh_ntheta));
  PetscCall(read.Real(PetscOptionsObject, "-mesh_density",
                      "With -mesh_ntheta 0: elements around the tube per bending length sqrt(Ro t) (the presets: "
                      "fast 12, default 24, accurate 32)",
                      opt.mesh_density));
  PetscCall(
    read.String(PetscOptionsObject, "-mesh_file",
                "Gmsh 4.1 ASCII quad mesh with physical curves inner, outer, x0, y0 (replaces the structured mesh)",
                opt.mesh_file));
  choice = 1;
  read.Note("-element");
  PetscCall(
    PetscOptionsEList("-element",
                      "Element formulation: q4 (full integration), bbar (mean dilatation), qm6 (incompatible "
                      "modes: no shear locking in bending), qm6bar (qm6 with the mean dilatation: no volumetric "
                      "locking in plastic flow either), auto (the presets: qm6, or qm6bar from -element_bar_nt cells "
                      "through the wall on)",
                      "tubeform", kElements, 5, kElements[choice], &choice, nullptr));
  const fe::Formulation kForms[] = {fe::Formulation::Q4, fe::Formulation::BBar, fe::Formulation::QM6,
                                    fe::Formulation::QM6Bar, fe::Formulation::QM6};
  opt.element = kForms[choice];
  opt.element_name = kElements[choice];
  opt.element_auto = choice == 4;
  PetscCall(
    read.Int(PetscOptionsObject, "-element_bar_nt",
             "With -element auto: qm6bar from this many cells through the wall on, qm6 below (docs/accuracy.md, "
             "\"The element through the wall\")",
             opt.element_bar_nt));
  TF_OPTIONS_END();
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The material: named or its constants, its law and hardening.
PetscErrorCode ReadMaterial(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  TF_OPTIONS_BEGIN(comm, "tubeform: material");
  {
    std::string dir, name = opt.material.name;
    PetscCall(read.String(PetscOptionsObject, "-material_library",
                          "Folder of the named materials (default: the source tree's options/materials)", dir));
    dir = MaterialLibraryDir(dir);
    std::string help = "Material: a name from the library (";
    for (const auto &m : LibraryMaterials(dir)) help += m + ", ";
    help += "docs/options.md \"Materials\"), a material file (path.opts), or custom (-material_e, ... given)";
    PetscCall(read.String(PetscOptionsObject, "-material", help.c_str(), name));
    PetscCall(LoadMaterial(comm, name, dir, opt.material));
  }
  PetscCall(read.Real(PetscOptionsObject, "-material_e", "Young's modulus E (MPa)", opt.material.E));
  PetscCall(read.Real(PetscOptionsObject, "-material_nu", "Poisson's ratio", opt.material.nu));
  PetscCall(read.Real(PetscOptionsObject, "-material_sy", "Initial yield stress (MPa)", opt.material.sy));
  PetscCall(read.Real(PetscOptionsObject, "-material_k", "Hardening coefficient K (MPa)", opt.material.K));
  PetscCall(read.Real(PetscOptionsObject, "-material_n", "Hardening exponent n", opt.material.n));
  PetscCall(read.Real(PetscOptionsObject, "-material_density",
                      "Mass density (t/mm^3; aluminum 2.70e-9), used by -dynamics implicit", opt.material.density));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-material_law",
                       "Flow curve: elastic (no yield), ludwik sy+K ep^n, swift K(ep0+ep)^n, table", kFlowLawWords,
                       opt.material.law));
  PetscCall(RealList(PetscOptionsObject, read, "-material_table",
                     "Flow curve for -material_law table: ep0,sy0,ep1,sy1,... (ep0 = 0, ep increasing)",
                     kMaxTableNumbers, opt.material.table));
  PetscCall(RealList(PetscOptionsObject, read, "-material_kinematic",
                     "Backstresses for -hardening chaboche: C1,gamma1[,C2,gamma2[,C3,gamma3]] (MPa, -; gamma 0: "
                     "linear); their share of the flow curve moves to the kinematic part",
                     2 * kMaxBackstresses, opt.material.kinematic));
  PetscCall(RealList(PetscOptionsObject, read, "-material_r",
                     "Hill 1948 yield from the Lankford coefficients r0,r45,r90 (0: along the tube, 90: across; r45 "
                     "does not act in plane strain); 1,1,1: von Mises",
                     3, opt.material.lankford));
  PetscCall(RealList(PetscOptionsObject, read, "-material_hill",
                     "Hill 1948 yield from F,G,H,L in the tube's axes (1 axial, 2 hoop, 3 radial; von Mises: "
                     "0.5,0.5,0.5,1.5)",
                     4, opt.material.hill));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-material_axes",
                       "The material's radial axis for -material_r/-material_hill: tube (from the tube's centre to "
                       "the point, turning with the material) or fixed (at -material_axes_angle)",
                       kMaterialAxesWords, opt.material.axes));
  {
    double degrees = opt.material.axes_angle * 180 / M_PI;
    PetscCall(read.Real(PetscOptionsObject, "-material_axes_angle",
                        "With -material_axes fixed: the radial axis's angle from x (degrees)", degrees));
    opt.material.axes_angle = degrees * M_PI / 180;
  }
  PetscCall(ChooseWord(PetscOptionsObject, read, "-hardening",
                       "isotropic (the flow curve expands the yield surface), or chaboche (the backstresses of "
                       "-material_kinematic move it; the same monotonic flow curve)",
                       kHardeningWords, opt.material.hardening));
  TF_OPTIONS_END();
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Inside the loading block: the stroke and the release.
PetscErrorCode ReadLoads(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(ReadStrokeOptions(PetscOptionsObject, read, opt.stroke));   // (stroke_options.cpp)
  PetscCall(ReadReleaseOptions(PetscOptionsObject, read, opt.release)); // (release_options.cpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Inside the loading block: the output, the stops and what is printed.
PetscErrorCode ReadOutput(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(read.String(PetscOptionsObject, "-output", "HDF5 result file (an .xmf for ParaView is written beside it)",
                        opt.output));
  PetscCall(
    read.String(PetscOptionsObject, "-history_csv", "Also write the history as CSV to this file", opt.history_csv));
  PetscCall(read.String(PetscOptionsObject, "-checkpoint",
                        "Checkpoint file (HDF5): the whole state every -checkpoint_every increments and when a "
                        "signal or -time_limit stops the run",
                        opt.checkpoint));
  PetscCall(read.Int(PetscOptionsObject, "-checkpoint_every",
                     "Write the -checkpoint file every this many increments (0: only when the run is stopped)",
                     opt.checkpoint_every));
  PetscCall(read.String(PetscOptionsObject, "-restart",
                        "Continue the run saved in this checkpoint file (same options; the results continue in "
                        "-output)",
                        opt.restart));
  PetscCall(read.Int(PetscOptionsObject, "-output_every",
                     "Write fields every k-th increment (the last is always written)", opt.output_every));
  PetscCall(read.Real(PetscOptionsObject, "-output_stroke",
                      "Write fields each time the loading advances this much stroke (mm; later stages: the same "
                      "fraction of the stage) and at every stage end; 0: every -output_every increments",
                      opt.output_stroke));
  PetscCall(read.Real(PetscOptionsObject, "-time_limit",
                      "Stop after this many seconds of the incremental loop, results up to there written, with "
                      "an error (non-zero exit); 0: no limit",
                      opt.time_limit));
  PetscCall(read.Real(PetscOptionsObject, "-progress",
                      "Print a progress line on rank 0 (stage, percent, stroke, time left) every this many "
                      "seconds of a run; 0: none",
                      opt.progress));
  PetscCall(read.Bool(PetscOptionsObject, "-monitor", "Print one line per increment on rank 0", opt.monitor));
  PetscCall(read.Bool(PetscOptionsObject, "-allow_unused",
                      "Run even when an option given is read by nothing (a warning names it; without this, an error)",
                      opt.allow_unused));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The loading (the stroke and the release) and the output: a group each in -help.
PetscErrorCode ReadLoading(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  {
    TF_OPTIONS_BEGIN(comm, "tubeform: loading (stroke, springback)");
    PetscCall(ReadLoads(PetscOptionsObject, read, opt));
    TF_OPTIONS_END();
  }
  {
    TF_OPTIONS_BEGIN(comm, "tubeform: output, checkpoints and stops");
    PetscCall(ReadOutput(PetscOptionsObject, read, opt));
    TF_OPTIONS_END();
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A layer's own options (the driver's), read by it (one group in -help).
PetscErrorCode ReadGroup(MPI_Comm comm, const OptionGroup &group, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  if (!group.read) PetscFunctionReturn(PETSC_SUCCESS);
  const std::string title = "tubeform: " + group.title;
  TF_OPTIONS_BEGIN(comm, title.c_str());
  PetscCall(group.read(PetscOptionsObject, read, opt));
  TF_OPTIONS_END();
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Each scene's own options, read by the scene (one group in -help per scene that has any).
PetscErrorCode ReadSceneOptions(MPI_Comm comm, const std::vector<SceneOptions> &scenes, OptionReader &read,
                                Options &opt)
{
  PetscFunctionBeginUser;
  for (const SceneOptions &s : scenes) {
    if (!s.read) continue;
    const std::string title = "tubeform: " + s.name + " scene";
    TF_OPTIONS_BEGIN(comm, title.c_str());
    PetscCall(s.read(PetscOptionsObject, read, opt));
    TF_OPTIONS_END();
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode ReadOptions(MPI_Comm comm, const std::vector<OptionGroup> &groups, const SceneOptionReaders &scenes,
                           Options &opt)
{
  OptionReader read; // every option's name, for the check of unknown ones

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &opt.help));
  PetscCall(ReadScene(comm, scenes.scenes, read, opt));
  PetscCall(ReadMaterial(comm, read, opt));
  for (const OptionGroup &group : groups) PetscCall(ReadGroup(comm, group, read, opt));
  PetscCall(ReadLoading(comm, read, opt));
  PetscCall(ReadFrictionOptions(comm, read, opt)); // (friction_options.cpp)
  PetscCall(ReadSceneOptions(comm, scenes.scenes, read, opt));
  if (scenes.tools.read) PetscCall(scenes.tools.read(comm, read, opt)); // (for every scene: a stray one is refused)

  opt.known = read.known();
  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);
  if (!opt.allow_unused) PetscCall(read.CheckUnknown(comm));

  PetscCall(CheckOptions(comm, scenes.tools, opt));
  for (const OptionGroup &group : groups)
    if (group.check) PetscCall(group.check(comm, opt));
  for (const SceneOptions &s :
       scenes.scenes) // (every scene's, given or not: a value out of range is refused all the same)
    if (s.check) PetscCall(s.check(comm, opt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
