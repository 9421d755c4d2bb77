// Time series in an open HDF5 result file: one dataset per field, dimensions
// (step, entity[, component]), grown by one step per write, in the layout
// PETSc's XDMF format uses (/vertex_fields/<name>, /cell_fields/<name>), so the
// .xmf, ParaView and the scripts read it unchanged. Written with HDF5 directly:
// PETSc's VecView flushes the file after every vector (an fsync each; 8 ms per
// field on this machine's disk), which made field output a third of a run.
#pragma once

#include <petscvec.h>
#include <petscviewerhdf5.h>

#include <string>

#include "tubeform/core/core.hpp"

namespace tf {

// Collective: writes the locally owned part of `global` (block size `bs`: 1
// scalar, 2 vector) as step `step` (0 creates the dataset) of dataset `path`,
// whose group must exist.
PetscErrorCode WriteSeriesStep(hid_t file, const char *path, Vec global, PetscInt bs, PetscInt step);

// Collective: `value` as step `step` of the (step, 1) dataset `path`, written by
// the rank with `writer` true (one rank).
PetscErrorCode WriteSeriesValue(hid_t file, const char *path, double value, PetscInt step, bool writer);

// Collective: `rows` x 2 values as step `step` of the (step, rows, 2) dataset `path`, written by the rank
// with `writer` true (one rank; the others' `values` are not read). A dataset first written at a later step
// (a tool of a second pass) is created then, its earlier steps zero, its attribute first_step that step.
PetscErrorCode WriteSeriesPairs(hid_t file, const char *path, const double *values, hsize_t rows, PetscInt step,
                                bool writer);

// Collective: creates the groups of `path` that are missing and, unless it exists, the (rows, 2) dataset
// `path` of HDF5 type `type` (H5T_NATIVE_INT, H5T_NATIVE_DOUBLE), written by the rank with `writer` true.
PetscErrorCode WritePairsOnce(hid_t file, const char *path, hid_t type, const void *values, hsize_t rows, bool writer);

// Whether `path` names an object of the file (false where a group on the way is missing).
bool PathExists(hid_t file, const std::string &path);

} // namespace tf
