#include "tubeform/io/options.hpp"

#include <cmath>
#include <fstream>

#include "tubeform/contact/friction_options.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/core/option_reader.hpp"
#include "tubeform/io/loading_options.hpp"
#include "tubeform/material/material_options.hpp"

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
    read.Note("-scene", "Scene to run", PetscOptionsObject->title);
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
  read.Note("-element", "", PetscOptionsObject->title);
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
                      "Run even when an option given is read by nothing or only by other scenes (a warning names "
                      "it; without this, an error)",
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

// Each scene's own options, read by the scene into `own` (one group in -help per scene that has any).
PetscErrorCode ReadSceneOptions(MPI_Comm comm, const std::vector<SceneOptions> &scenes, OptionReader &read,
                                std::vector<std::any> &own)
{
  PetscFunctionBeginUser;
  own.assign(scenes.size(), std::any());
  for (size_t k = 0; k < scenes.size(); ++k) {
    if (!scenes[k].read) continue;
    const std::string title = "tubeform: " + scenes[k].name + " scene";
    read.ReadBy(scenes[k].name);
    TF_OPTIONS_BEGIN(comm, title.c_str());
    PetscCall(scenes[k].read(PetscOptionsObject, read, own[k]));
    TF_OPTIONS_END();
  }
  read.ReadBy("");
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The scenes that press with tools, space-separated (the tool scenes' options are theirs alone).
std::string ToolSceneNames(const std::vector<SceneOptions> &scenes)
{
  std::string names;
  for (const auto &s : scenes)
    if (s.press != ScenePress::None) names += (names.empty() ? "" : " ") + s.name;
  return names;
}

// Every scene's own options checked (given or not: a value out of range is refused all the same); the chosen scene's
// kept in opt.scene_params.
PetscErrorCode CheckSceneOptions(MPI_Comm comm, const std::vector<SceneOptions> &scenes,
                                 const std::vector<std::any> &own, Options &opt)
{
  PetscFunctionBeginUser;
  for (size_t k = 0; k < scenes.size(); ++k) {
    if (scenes[k].check) PetscCall(scenes[k].check(comm, own[k]));
    if (scenes[k].name == opt.scene) opt.scene_params = own[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode ReadOptions(MPI_Comm comm, const std::vector<OptionGroup> &groups, const SceneOptionReaders &scenes,
                           Options &opt)
{
  OptionReader read;         // every option's name, for the check of unknown ones
  std::vector<std::any> own; // each scene's own parameters

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &opt.help));
  PetscCall(ReadScene(comm, scenes.scenes, read, opt));
  PetscCall(ReadMaterialOptions(comm, read, opt.material)); // (material/material_options.cpp)
  for (const OptionGroup &group : groups) PetscCall(ReadGroup(comm, group, read, opt));
  PetscCall(ReadLoading(comm, read, opt));
  PetscCall(ReadFrictionOptions(comm, read, opt.friction)); // (contact/friction_options.cpp)
  PetscCall(ReadSceneOptions(comm, scenes.scenes, read, own));
  read.ReadBy(ToolSceneNames(scenes.scenes));
  if (scenes.tools.read) PetscCall(scenes.tools.read(comm, read, opt)); // (for every scene: a stray one is refused)
  read.ReadBy("");

  opt.known = read.known();
  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);
  if (!opt.allow_unused) PetscCall(read.CheckUnknown(comm));
  if (scenes.refuse_foreign) PetscCall(scenes.refuse_foreign(comm, opt)); // (before any check of a value)

  PetscCall(CheckOptions(comm, scenes.tools, opt));
  for (const OptionGroup &group : groups)
    if (group.check) PetscCall(group.check(comm, opt));
  PetscCall(CheckSceneOptions(comm, scenes.scenes, own, opt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
