// The validation of the options ReadOptions has read: one message per
// problem, naming the option and the range it allows.
#include "tubeform/contact/friction_options.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/core/option_reader.hpp"
#include "tubeform/io/loading_options.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/material/material_options.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>

namespace tf {

namespace {

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

// The material, the tool scenes' options (`tools`), the loads.
PetscErrorCode CheckLoads(MPI_Comm comm, const ToolSceneReaders &tools, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckMaterial(comm, opt.material));
  if (tools.check) PetscCall(tools.check(comm, opt));  // (the tool scenes': the dies, passes, model and release)
  PetscCall(CheckFrictionOptions(comm, opt.friction)); // (contact/friction_options.cpp)
  PetscCall(CheckStrokeOptions(comm, opt));            // (stroke_options.cpp; after -die_path's)
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

PetscErrorCode CheckOptions(MPI_Comm comm, const ToolSceneReaders &tools, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckTubeAndMesh(comm, opt));
  PetscCall(CheckLoads(comm, tools, opt));
  PetscCall(CheckOutputAndStops(comm, opt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
