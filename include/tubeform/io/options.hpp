// Everything a run is told on the command line / options file, read once and
// validated up front (the names of docs/options-reference.md, which users and scripts rely on).
#pragma once

#include <petscsys.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <string>
#include <vector>

#include "tubeform/body/body.hpp"
#include "tubeform/contact/contact.hpp"
#include "tubeform/contact/friction_params.hpp"
#include "tubeform/core/option_reader.hpp"
#include "tubeform/fe/quad.hpp"
#include "tubeform/io/driver_params.hpp"
#include "tubeform/io/press_params.hpp"
#include "tubeform/material/elastic.hpp"

namespace tf {

// What a scene presses the tube with (its entry's in the scene registry, scenes/registry.hpp; Options::press once
// -scene chose it): no tools (pressure, shear, ...), an upper die over a lower one (squaring: -die_offset, -die_path,
// -full_hold rotation and the later passes' -pass<N>_die_profile are its) or a flat plate (flattening).
enum class ScenePress { None, Die, Plate };

// What a run is told: the run-wide options (the scene, the body's mesh and element, the material, the driver, the
// output), those several scenes share (the tube: the tool scenes', the pressure's and the slide's; the stroke: the tool
// scenes' and the column's; the springback's law: the tool scenes' and the bending's; the friction: the tool scenes'
// and the slide's; the estimate: the tool scenes'), and, opaque to io, the tool scenes' own (their model and passes)
// and the chosen scene's own parameters. Which scene reads which: the scene registry (scenes/registry.cpp).
struct Options {
  std::string scene = "pressure";      // a name of the scene registry (scenes/registry.hpp)
  ScenePress press = ScenePress::None; // what it presses with (its SceneOptions', set with it; PressesWithTools)
  // Geometry and mesh
  double tube_ro = 17.5, tube_t = 1.5;
  PetscInt mesh_nt = 4, mesh_ntheta = 48;
  double mesh_density = 0;     // -mesh_ntheta 0: elements around per bending length sqrt(Ro t)
  double mesh_wall_strain = 0; // -mesh_nt 0: largest change of the bending strain t/Ro across a cell
  PetscInt mesh_nt_min = 2;    // -mesh_nt 0: fewest cells through the wall
  std::string mesh_file;
  fe::Formulation element = fe::Formulation::BBar;
  std::string element_name = "bbar";
  bool element_auto = false;   // -element auto: qm6 or qm6bar from the cells through the wall (ChooseElement)
  PetscInt element_bar_nt = 5; // -element auto: qm6bar from this many cells through the wall on
  // Material
  MaterialParams material;
  // The incremental driver's (io/driver_params.hpp; read and checked by the driver).
  DriverParams driver;
  StrokeParams stroke; // the stroke (io/press_params.hpp; the tool scenes' first pass's and the column's)
  // The tool scenes' own (a ToolSceneParams of scenes/tool_scene.hpp: the model and the passes with their dies),
  // read and checked by them for every scene and read back with ToolsOf; io does not look inside.
  std::any tools;
  FrictionParams friction; // contact and friction (contact/friction_params.hpp; the tool scenes' and the slide's)
  ReleaseParams release;   // the springback's law (io/press_params.hpp; the tool scenes' and the bending's)
  // The chosen scene's own parameters where it has any (a scene without tools: its struct of scenes/scene_params.hpp,
  // read and checked by the scene, SceneOptions), kept here so that they travel with the run's options to its levels
  // and companions; the scene reads them back with OwnParams.
  std::any scene_params;
  // Output
  std::string output = "results/tubeform.h5";
  std::string history_csv;
  PetscInt output_every = 1;
  std::string checkpoint;        // checkpoint file (empty: none)
  PetscInt checkpoint_every = 0; // increments between checkpoints (0: only when a signal or -time_limit stops the run)
  std::string restart;           // checkpoint to continue from
  double output_stroke = 0;      // > 0: fields every this much stroke (mm) instead of every output_every increments
  // The error estimate and the accuracy held to (io/driver_params.hpp; read and checked by the driver).
  AccuracyParams accuracy;
  PetscInt level = 1;     // (not an option: the level this run is, 1 the first)
  double job_started = 0; // (not an option: MPI_Wtime when the job began)
  double time_limit = 0;  // > 0: stop (results written, non-zero exit) after this many seconds of loading
  double progress = 10;   // s between progress lines on rank 0 (0: none); quiet on shorter runs
  PetscBool monitor = PETSC_FALSE;
  PetscBool allow_unused = PETSC_FALSE; // an option nothing reads is a warning, not an error
  PetscBool help = PETSC_FALSE;
  std::vector<KnownOption> known; // every option ReadOptions read (the hints for options nothing reads)
};

// The P held in `held` (Options::tools, Options::scene_params), or P's built-in values where it holds none (options
// built in code).
template <class P>
const P &HeldOr(const std::any &held)
{
  static const P built_in;
  const P *own = std::any_cast<P>(&held);
  return own ? *own : built_in;
}

// The scene presses the tube with tools (squaring, flattening: the dies', stroke's and passes' options are its).
inline bool PressesWithTools(const Options &opt) { return opt.press != ScenePress::None; }
// Its upper tool is a die (squaring), not a plate (flattening).
inline bool PressesWithDie(const Options &opt) { return opt.press == ScenePress::Die; }

class OptionReader;
// A scene -scene accepts, and the reader and checker of its own options (null: it has none): the reader lists them
// in -help under "tubeform: <name> scene" (between PetscOptionsBegin and PetscOptionsEnd, whose PetscOptionsObject
// it takes) and puts them in `own` (its parameters' struct), the checker refuses their bad values in one line naming
// the option. Every scene's are read and checked, whichever runs (a bad value is refused all the same); the chosen
// scene's become Options::scene_params. The scene registry lists them.
struct SceneOptions {
  std::string name;
  ScenePress press = ScenePress::None;
  PetscErrorCode (*read)(PetscOptionItems *PetscOptionsObject, OptionReader &read, std::any &own) = nullptr;
  PetscErrorCode (*check)(MPI_Comm comm, const std::any &own) = nullptr;
};

// The reader and checker of the options of a layer above io (the driver's: driver/driver_options.hpp), handed to
// ReadOptions from above as the scenes' are: the reader lists them in -help under "tubeform: <title>" (between
// PetscOptionsBegin and PetscOptionsEnd, whose PetscOptionsObject it takes), the checker refuses their bad values in
// one line naming the option.
struct OptionGroup {
  std::string title;
  PetscErrorCode (*read)(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt) = nullptr;
  PetscErrorCode (*check)(MPI_Comm comm, const Options &opt) = nullptr;
};

// The reader and checker of the tool scenes' options (squaring, flattening: the model, the passes, the dies), the
// scenes layer's (scenes/tool_options.hpp): read for every scene, each block its own in -help; the check also
// settles what they derive (a -die_path's end is the stroke) before the loading's checks read it.
struct ToolSceneReaders {
  PetscErrorCode (*read)(MPI_Comm comm, OptionReader &read, Options &opt) = nullptr;
  PetscErrorCode (*check)(MPI_Comm comm, Options &opt) = nullptr;
};
// What the scene registry hands ReadOptions: the scenes -scene accepts with their own options, and the tool scenes'.
struct SceneOptionReaders {
  std::vector<SceneOptions> scenes;
  ToolSceneReaders tools;
  // Collective: refuses, in one line naming the scenes that read it, an option given that the run's scene does not
  // read (KnownOption::scenes, and the options the registry lists as only some scenes'); after the options are read,
  // before the values' checks of range and combination. Null: none refused.
  PetscErrorCode (*refuse_foreign)(MPI_Comm comm, const Options &opt) = nullptr;
};

// Collective: reads and validates the options; `groups` the driver's own (each its group in -help, in turn), `scenes`
// the scenes -scene accepts, with their own options, and the tool scenes'. Errors are PETSC_ERR_USER_INPUT with a
// message naming the option and what is allowed.
PetscErrorCode ReadOptions(MPI_Comm comm, const std::vector<OptionGroup> &groups, const SceneOptionReaders &scenes,
                           Options &opt);
// Collective: refuses values out of range (called by ReadOptions; `tools` the tool scenes' check, in its turn).
PetscErrorCode CheckOptions(MPI_Comm comm, const ToolSceneReaders &tools, Options &opt);

// Elements around the quarter tube for `density` elements per bending length
// sqrt(Ro t): the wall between the die's contacts bends over that length (the
// decay length of a ring's or shell's bending under a line load), so the
// bending and the contact patch are resolved alike on any tube. Even (a node
// on the 45-degree line) and at least 8.
inline PetscInt ElementsAround(double ro, double t, double density)
{
  const double n = density * 0.5 * M_PI * ro / std::sqrt(ro * t);
  return std::max<PetscInt>(8, 2 * (PetscInt)std::ceil(0.5 * n));
}

// Cells through the wall for -mesh_nt 0: straightening the ring strains a
// fibre at y from the mid-surface by about y / R, so a cell of height t / n
// spans a bending strain of t / (n Ro); at most `strain` of it, at least `least` cells.
inline PetscInt ElementsThrough(double ro, double t, double strain, PetscInt least)
{
  return std::max<PetscInt>(least, (PetscInt)std::ceil(t / (ro * strain) - 1e-9));
}

// -element auto: the element follows the wall like its cell count. With n
// cells through a bending wall qm6 is stiff by about 1/n where the wall
// yields through its thickness (the strain through a cell is linear, the
// plastic flow's is not), qm6bar soft by about 1/n^2 where it bends
// elastically (its mean dilatation drops the linear volumetric strain of a
// bent cell); from `bar_nt` cells on the second is the smaller
// (docs/accuracy.md, "The element through the wall"). A mesh file keeps qm6.
inline void ChooseElement(Options &opt)
{
  if (!opt.element_auto) return;
  const bool bar = opt.mesh_file.empty() && opt.mesh_nt >= opt.element_bar_nt;
  opt.element = bar ? fe::Formulation::QM6Bar : fe::Formulation::QM6;
  opt.element_name = bar ? "qm6bar" : "qm6";
}

} // namespace tf
