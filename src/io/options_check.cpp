// The validation of the options ReadOptions has read: one message per
// problem, naming the option and the range it allows.
#include "tubeform/core/core.hpp"
#include "tubeform/io/friction_options.hpp"
#include "tubeform/io/motion_checks.hpp"
#include "tubeform/io/option_reader.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/io/press_options.hpp"
#include "tubeform/io/tool_options.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>

namespace tf {

namespace {

// The dies: which dies, forces and side dies go together.
PetscErrorCode CheckDies(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  const bool press = PressesWithTools(opt);
  const DieSet &first = FirstDies(opt);
  bool asked = !first.lower.Is(DieFrom::Mirror) || !LowerDieMoves(opt, LowerDieMove::Mirror) ||
               opt.model.part != TubeModel::Auto || !DieMoves(first, kStrokeMotion) || !first.side.Is(DieFrom::None) ||
               first.side_force != 0 || opt.model.die_offset != 0 || opt.model.full_hold != FullHold::Auto;
  for (int pass = 1; pass < kMaxPasses; ++pass) {
    const PassSpec &p = LaterPass(opt, pass);
    asked = asked || p.stroke != 0 || p.turn != 0 || !p.dies.upper.kind.empty() || p.dies.lower.Given() ||
            p.dies.side.Given();
  }
  PetscCheck(
    press || !asked, comm, PETSC_ERR_USER_INPUT,
    "-lower_die, -lower_die_motion, -model, -pass<N>_*, -die_motion, -die_force, -die_offset, -die_path, -side_die, "
    "-side_force, -full_hold: "
    "the %s scene presses with no dies (these are the squaring and flattening scenes' options)",
    opt.scene.c_str());
  PetscCall(CheckUpperMotion(comm, opt, 0));     // (its motion kind's check; a later pass's with its stroke)
  PetscCall(CheckPassStrokesAndDies(comm, opt)); // (passes_check.cpp)
  PetscCall(CheckSideDieOptions(comm, opt));     // (die_shape_options.cpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

// -die_motion path (checked by the path motion's check, motion_check_path.cpp): the stroke U where the path ends.
void SetDiePathStroke(Options &opt) { opt.stroke.u = -0.5 * FirstDies(opt).motion.spec.points.back()[1]; }

// A lower die on a motion of its own (neither mirror nor fixed: a path, or another kind; its options are its
// kind's own reader's, tool/motion.hpp): one pass, the stroke rising.
PetscErrorCode CheckLowerDieMotion(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  const bool own = LowerDieMoves(opt, LowerDieMove::Own);
  PetscCheck(!own || (opt.stroke.path.empty() && opt.release.unload != Unload::Withdraw && PassCount(opt) == 1 &&
                      opt.stroke.corner_radius <= 0),
             comm, PETSC_ERR_USER_INPUT,
             "-lower_die_motion %s: the lower die follows its motion as the stroke rises, in one pass: not with "
             "-stroke_path, -unload withdraw, -pass2_stroke or -stroke_corner_radius",
             opt.lower_motion.word.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The later passes' turns, the model (a die off the axis, the rotation hold) and the release.
PetscErrorCode CheckPassesAndHolds(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckPassTurns(comm, opt));      // (passes_check.cpp)
  PetscCall(CheckModelOptions(comm, opt));   // (model_options.cpp)
  PetscCall(CheckReleaseOptions(comm, opt)); // (release_options.cpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The lower die, the model and the second pass (the tool scenes').
PetscErrorCode CheckDiesAndPasses(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckDies(comm, opt));
  if (FirstDies(opt).motion.OwnPath()) SetDiePathStroke(opt);
  PetscCall(CheckLowerDieMotion(comm, opt));
  PetscCall(CheckPassesAndHolds(comm, opt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The tube, its mesh and element (the counts a preset leaves at 0 derived here).
PetscErrorCode CheckTubeAndMesh(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCheck(opt.tube_ro > 0 && std::isfinite(opt.tube_ro), comm, PETSC_ERR_USER_INPUT,
             "-tube_ro %g: the outer radius must be a positive number of mm", opt.tube_ro);
  PetscCheck(opt.tube_t > 0 && opt.tube_t < opt.tube_ro, comm, PETSC_ERR_USER_INPUT,
             "-tube_t %g: the wall thickness must be positive and smaller than -tube_ro %g", opt.tube_t, opt.tube_ro);
  PetscCheck(opt.mesh_nt >= 0 && opt.mesh_nt <= 1000, comm, PETSC_ERR_USER_INPUT,
             "-mesh_nt %d: must be between 1 and 1000, or 0 (from -mesh_wall_strain)", (int)opt.mesh_nt);
  PetscCheck(opt.mesh_nt > 0 || (opt.mesh_wall_strain > 0 && opt.mesh_wall_strain <= 1), comm, PETSC_ERR_USER_INPUT,
             "-mesh_nt 0 needs -mesh_wall_strain in (0, 1] (the largest change of the bending strain t/Ro across a "
             "cell; got %g)",
             opt.mesh_wall_strain);
  PetscCheck(opt.mesh_nt > 0 || (opt.mesh_nt_min >= 1 && opt.mesh_nt_min <= 1000), comm, PETSC_ERR_USER_INPUT,
             "-mesh_nt_min %d: must be between 1 and 1000", (int)opt.mesh_nt_min);
  if (opt.mesh_nt == 0)
    opt.mesh_nt =
      std::min<PetscInt>(1000, ElementsThrough(opt.tube_ro, opt.tube_t, opt.mesh_wall_strain, opt.mesh_nt_min));
  PetscCheck(opt.element_bar_nt >= 1, comm, PETSC_ERR_USER_INPUT,
             "-element_bar_nt %d: must be at least 1 (cells through the wall)", (int)opt.element_bar_nt);
  ChooseElement(opt);
  PetscCheck(opt.mesh_ntheta == 0 || (opt.mesh_ntheta >= 2 && opt.mesh_ntheta <= 100000), comm, PETSC_ERR_USER_INPUT,
             "-mesh_ntheta %d: must be between 2 and 100000, or 0 (from -mesh_density)", (int)opt.mesh_ntheta);
  PetscCheck(opt.mesh_ntheta > 0 || (opt.mesh_density > 0 && opt.mesh_density <= 1000), comm, PETSC_ERR_USER_INPUT,
             "-mesh_ntheta 0 needs -mesh_density in (0, 1000] (elements per bending length sqrt(Ro t); got %g)",
             opt.mesh_density);
  if (opt.mesh_ntheta == 0) opt.mesh_ntheta = ElementsAround(opt.tube_ro, opt.tube_t, opt.mesh_density);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The material, the tools and passes, the loads.
PetscErrorCode CheckLoads(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckMaterial(comm, opt.material));
  PetscCall(CheckDiesAndPasses(comm, opt));
  PetscCall(CheckShape(comm, kVShape, "die_", UpperDieShape(opt).spec)); // (the V-die's options: read with a file too)
  PetscCall(CheckFrictionOptions(comm, opt.friction));                   // (friction_options.cpp)
  PetscCall(CheckStrokeOptions(comm, opt));                              // (stroke_options.cpp; after -die_path's)
  PetscCheck(opt.output_every >= 1, comm, PETSC_ERR_USER_INPUT, "-output_every %d: must be at least 1",
             (int)opt.output_every);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The stops, the output and the mesh file.
PetscErrorCode CheckOutputAndStops(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCheck(opt.time_limit >= 0 && std::isfinite(opt.time_limit), comm, PETSC_ERR_USER_INPUT,
             "-time_limit %g: must be 0 (no limit) or a positive number of seconds", opt.time_limit);
  PetscCheck(opt.progress >= 0 && std::isfinite(opt.progress), comm, PETSC_ERR_USER_INPUT,
             "-progress %g: must be 0 (none) or a positive number of seconds", opt.progress);
  PetscCheck(opt.output_stroke >= 0 && opt.output_stroke <= opt.stroke.u, comm, PETSC_ERR_USER_INPUT,
             "-output_stroke %g: must be between 0 (off) and the stroke %g mm", opt.output_stroke, opt.stroke.u);
  PetscCheck(!opt.output.empty(), comm, PETSC_ERR_USER_INPUT, "-output: an HDF5 file name is required");
  PetscCheck(opt.checkpoint_every >= 0, comm, PETSC_ERR_USER_INPUT,
             "-checkpoint_every %d: must be 0 (only when stopped) or a number of increments",
             (int)opt.checkpoint_every);
  PetscCheck(opt.checkpoint_every == 0 || !opt.checkpoint.empty(), comm, PETSC_ERR_USER_INPUT,
             "-checkpoint_every %d: needs -checkpoint FILE", (int)opt.checkpoint_every);
  if (!opt.mesh_file.empty()) {
    // Rank 0 reads the mesh, so rank 0 looks (another rank, on another node,
    // may see another file system) and tells the others.
    PetscMPIInt rank;
    int readable = 0;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    if (rank == 0) readable = std::ifstream(opt.mesh_file).good();
    PetscCallMPI(MPI_Bcast(&readable, 1, MPI_INT, 0, comm));
    PetscCheck(readable, comm, PETSC_ERR_USER_INPUT, "-mesh_file %s: cannot open the file (missing or unreadable)",
               opt.mesh_file.c_str());
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode CheckOptions(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckTubeAndMesh(comm, opt));
  PetscCall(CheckLoads(comm, opt));
  PetscCall(CheckOutputAndStops(comm, opt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
