// The scenes tubeform runs, by name (the -scene option).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tubeform/scenes/scene.hpp"

namespace tf {

struct SceneEntry {
  const char *name;
  const char *what; // one line for -help and docs/
  std::unique_ptr<Scene> (*make)(const Options &opt);
  ScenePress press; // what it presses the tube with (io/options.hpp): none, an upper die or a plate
  // The options it reads that not every scene does (space-separated; a name ending in '_' a prefix): an option of
  // another scene's list, given to this one, is refused naming the scenes that read it (ForeignOption).
  const char *reads = "";
  // The reader and checker of its own options (SceneOptions; null: none): its file's, on its parameters' struct
  // (scenes/scene_params.hpp), handed over by the registry.
  PetscErrorCode (*read)(PetscOptionItems *PetscOptionsObject, OptionReader &read, std::any &own) = nullptr;
  PetscErrorCode (*check)(MPI_Comm comm, const std::any &own) = nullptr;
};

const std::vector<SceneEntry> &SceneRegistry();
std::vector<std::string> SceneNames();
// The scenes with the readers and checkers of their own options, and the tool scenes' (scenes/tool_options.hpp),
// for ReadOptions.
SceneOptionReaders SceneReaders();
// The scenes that read option `option` (with its dash) where not every scene does, space-separated: those whose
// `reads` list it, else those its reader names (KnownOption::scenes: a scene's own, the tool scenes' dies and
// passes); "" where every scene reads it.
std::string ReadersOf(const std::string &option, const std::vector<KnownOption> &known);
// "" or why the option named `option` is not for the scene `scene`: the scenes that read it (ReadersOf), where
// `scene` is not one of them.
std::string ForeignOption(const std::string &scene, const std::string &option, const std::vector<KnownOption> &known);
// Collective: an option given (command line or options files) that only other scenes read stops the run in one
// line naming them (ForeignOption; SceneOptionReaders::refuse_foreign), before the values' checks of range and
// combination; -allow_unused turns it into a warning line. Its name in any case (PETSc's names ignore it). Also the
// tube's automatic cells (-mesh_nt 0, -mesh_ntheta 0) in a scene whose body is a block.
PetscErrorCode RefuseForeignOptions(MPI_Comm comm, const Options &opt);
// Under -help: each scene, what it is, the options of the `reads` lists it reads and the -help blocks only it and
// other scenes read (`known`: every option read), one line each after the heading "tubeform: scenes:"
// (tools/options_doc.py builds the options reference's scene tables from them).
PetscErrorCode PrintSceneHelp(MPI_Comm comm, const std::vector<KnownOption> &known);
// The scene of opt.scene; null if the name is not registered.
std::unique_ptr<Scene> CreateScene(const Options &opt);

} // namespace tf
