// Everything a run is told on the command line / options file, read once and
// validated up front (METHOD.md section 9 names).
#pragma once

#include <petscsys.h>

#include <string>

#include "tubeform/fe/quad.hpp"
#include "tubeform/material/elastic.hpp"

namespace tf {

enum class SceneKind { Squaring, Flattening, Pressure, Shear, Rotation, Column };

struct Options {
  SceneKind scene = SceneKind::Pressure;
  std::string scene_name = "pressure";
  // Geometry and mesh
  double tube_ro = 17.5, tube_t = 1.5;
  PetscInt mesh_nt = 4, mesh_ntheta = 48;
  std::string mesh_file;
  fe::Formulation element = fe::Formulation::BBar;
  std::string element_name = "bbar";
  // Material
  MaterialParams material;
  // Loading
  PetscInt increments = 10;
  double pressure_p = 50.0;
  // Output
  std::string output = "results/tubeform.h5";
  std::string history_csv;
  PetscInt output_every = 1;
  PetscBool monitor = PETSC_FALSE;
  PetscBool help = PETSC_FALSE;
};

// Collective: reads and validates the options. Errors are PETSC_ERR_USER_INPUT
// with a message naming the option and what is allowed.
PetscErrorCode ReadOptions(MPI_Comm comm, Options &opt);

} // namespace tf
