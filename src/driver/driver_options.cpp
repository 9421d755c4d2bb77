// The incremental driver's own options: read into Options::driver and checked (one line naming the option).
#include "tubeform/driver/driver_options.hpp"

#include <cmath>
#include <string>

#include "tubeform/core/core.hpp"
#include "tubeform/io/option_reader.hpp"
#include "tubeform/step/rmin.hpp"

namespace tf {

namespace {

// Inside the driver's block: the increments and r_min's bounds, the stops, the re-solves and friction iterations, the
// drift correction.
PetscErrorCode ReadIncrements(PetscOptionItems *PetscOptionsObject, OptionReader &read, DriverParams &d)
{
  PetscFunctionBeginUser;
  PetscCall(read.Int(PetscOptionsObject, "-increments", "Trial increments over the load path (r_min may cut each)",
                     d.increments));
  PetscCall(read.Int(PetscOptionsObject, "-unload_increments",
                     "Trial increments of the unloading (the path past the end of loading: the tool scenes' "
                     "springback, the slide scene's later stages); 0: as -increments",
                     d.unload_increments));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_deps", "r2: largest principal strain increment", d.rmin_deps));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_deps_yield",
                      "r2 relative to the material: the strain increment also at most this many initial "
                      "yield strains sigma_y0 / E (0: off; materials with E / sigma_y in the thousands)",
                      d.rmin_deps_yield));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_domega", "r3: largest rotation increment (rad)", d.rmin_domega));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_group_tol",
                      "Events within (1 + tol) r_min are taken in the same increment", d.rmin_group_tol));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-rmin_yield",
                       "onset (paper: r1 ends the step where a point meets the yield surface), inside (points "
                       "yield inside a step: tangent weighted by the elastic fraction, update split at the onset)",
                       kRminYieldWords, d.rmin_yield));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_yield_tol",
                      "-rmin_yield inside: re-solve the step while a point's elastic fraction moves by more",
                      d.rmin_yield_tol));
  PetscCall(read.Real(PetscOptionsObject, "-rmin_event_tol",
                      "Steps that are not linear in r (friction, inertia) are solved again until their first "
                      "event lies within this fraction of the step's end",
                      d.rmin_event_tol));
  const std::string stall_help =
    "Stop (results so far written) when this many increments advance the load path by less than " +
    std::to_string(kStallAdvance);
  PetscCall(read.Int(PetscOptionsObject, "-rmin_max_increments",
                     "Stop (results so far written, non-zero exit) after this many increments", d.rmin_max_increments));
  PetscCall(read.Int(PetscOptionsObject, "-rmin_stall_increments", stall_help.c_str(), d.rmin_stall_increments));
  PetscCall(read.Real(PetscOptionsObject, "-max_energy_error",
                      "Stop (results so far written, non-zero exit) when the energy balance error (self-check "
                      "(a)) passes this fraction",
                      d.max_energy_error));
  PetscCall(read.Int(PetscOptionsObject, "-rmin_max_redo",
                     "Re-solves per increment when points switch between loading and unloading", d.rmin_max_redo));
  PetscCall(read.Int(PetscOptionsObject, "-friction_max_iters", "Friction iterations per increment before giving up",
                     d.friction_max_iters));
  PetscCall(read.Int(PetscOptionsObject, "-friction_max_unsettled",
                     "Stop when this many increments in a row are taken with friction iterations unsettled",
                     d.friction_max_unsettled));
  PetscCall(read.Bool(PetscOptionsObject, "-drift_correction",
                      "Scale plastic stresses back onto the yield surface after each update", d.drift_correction));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Inside the driver's block: inertia, the equilibrium iterations and the kinematics they choose; the factorization.
PetscErrorCode ReadDynamics(PetscOptionItems *PetscOptionsObject, OptionReader &read, DriverParams &d)
{
  PetscFunctionBeginUser;
  PetscCall(ChooseWord(PetscOptionsObject, read, "-dynamics",
                       "quasistatic (no inertia), implicit (lumped mass, backward Euler in time), auto "
                       "(quasi-static until an increment's friction iterations do not settle, implicit from "
                       "then on)",
                       kDynamicsWords, d.dynamics));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-factorization",
                       "The LU of a system every rank factors whole (one rank, or up to 20,000 dofs): mumps, or klu "
                       "(cheaper per call up to a few thousand dofs; docs/performance.md, \"Factorization\")",
                       kFactorizationWords, d.factorization));
  PetscCall(read.Real(PetscOptionsObject, "-dynamics_time",
                      "Duration (s) of the load path lambda 0 -> 1 with -dynamics implicit (scenes without tools)",
                      d.dynamics_time));
  PetscCall(
    read.Real(PetscOptionsObject, "-punch_speed",
              "Tool speed (mm/s) with -dynamics implicit in squaring/flattening: the stroke takes stroke / speed",
              d.punch_speed));
  PetscCall(read.Real(PetscOptionsObject, "-equilibrium_tol",
                      "Equilibrium iterations: largest out-of-balance force on a free dof against the "
                      "time-averaged nodal force (Abaqus's R_max <= 0.005 q); 0: off, the paper's forward "
                      "increments",
                      d.equilibrium_tol));
  // auto: midpoint with equilibrium iterations (objective and second order;
  // the iterations balance the pressure its strain leaves near
  // incompressibility), forward without them (the paper's increments, which
  // it keeps in balance best).
  Kinematics asked = Kinematics::Auto;
  PetscCall(ChooseWord(PetscOptionsObject, read, "-kinematics",
                       "Strain/spin increments: forward (start configuration, W sigma - sigma W), midpoint "
                       "(Hughes-Winget), or auto (midpoint with equilibrium iterations, forward without)",
                       kKinematicsWords, asked));
  if (asked == Kinematics::Auto) asked = d.equilibrium_tol > 0 ? Kinematics::Midpoint : Kinematics::Forward;
  d.kinematics = asked == Kinematics::Forward ? ObjectiveScheme::Forward : ObjectiveScheme::Midpoint;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode ReadDriverOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(ReadIncrements(PetscOptionsObject, read, opt.driver));
  PetscCall(ReadDynamics(PetscOptionsObject, read, opt.driver));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// (The friction iterations' tolerance is the contact set's, -friction_tol; it is refused with their counts.)
PetscErrorCode CheckDriverOptions(MPI_Comm comm, const Options &opt)
{
  const DriverParams &d = opt.driver;
  PetscFunctionBeginUser;
  PetscCheck(d.dynamics_time > 0 && std::isfinite(d.dynamics_time), comm, PETSC_ERR_USER_INPUT,
             "-dynamics_time %g: the duration of the load path must be positive (s)", d.dynamics_time);
  PetscCheck(d.punch_speed > 0 && std::isfinite(d.punch_speed), comm, PETSC_ERR_USER_INPUT,
             "-punch_speed %g: the tool speed must be positive (mm/s)", d.punch_speed);
  PetscCheck(d.increments >= 1 && d.increments <= 10000000, comm, PETSC_ERR_USER_INPUT,
             "-increments %d: must be between 1 and 1e7", (int)d.increments);
  PetscCheck(d.rmin_deps > 0 && d.rmin_deps <= 0.5, comm, PETSC_ERR_USER_INPUT,
             "-rmin_deps %g: the strain increment limit must lie in (0, 0.5]", d.rmin_deps);
  PetscCheck(d.rmin_deps_yield >= 0 && std::isfinite(d.rmin_deps_yield), comm, PETSC_ERR_USER_INPUT,
             "-rmin_deps_yield %g: must be a number of yield strains >= 0 (0: off)", d.rmin_deps_yield);
  PetscCheck(d.rmin_domega > 0 && d.rmin_domega <= 0.5, comm, PETSC_ERR_USER_INPUT,
             "-rmin_domega %g: the rotation increment limit must lie in (0, 0.5] rad", d.rmin_domega);
  PetscCheck(d.rmin_yield_tol > 0 && d.rmin_yield_tol <= 1, comm, PETSC_ERR_USER_INPUT,
             "-rmin_yield_tol %g: must lie in (0, 1]", d.rmin_yield_tol);
  PetscCheck(d.rmin_group_tol >= 0 && d.rmin_group_tol <= 1, comm, PETSC_ERR_USER_INPUT,
             "-rmin_group_tol %g: must lie in [0, 1]", d.rmin_group_tol);
  PetscCheck(d.rmin_event_tol > 0 && d.rmin_event_tol <= 0.5, comm, PETSC_ERR_USER_INPUT,
             "-rmin_event_tol %g: must lie in (0, 0.5]", d.rmin_event_tol);
  PetscCheck(d.rmin_max_increments >= 1, comm, PETSC_ERR_USER_INPUT, "-rmin_max_increments %d: must be at least 1",
             (int)d.rmin_max_increments);
  PetscCheck(d.rmin_stall_increments >= 10, comm, PETSC_ERR_USER_INPUT,
             "-rmin_stall_increments %d: must be at least 10", (int)d.rmin_stall_increments);
  PetscCheck(d.rmin_max_redo >= 0, comm, PETSC_ERR_USER_INPUT, "-rmin_max_redo %d: must be non-negative",
             (int)d.rmin_max_redo);
  PetscCheck(opt.friction.tol > 0 && d.friction_max_iters >= 1 && d.friction_max_unsettled >= 1, comm,
             PETSC_ERR_USER_INPUT,
             "-friction_tol %g, -friction_max_iters %d, -friction_max_unsettled %d: need tol > 0 and at least one "
             "iteration and increment",
             opt.friction.tol, (int)d.friction_max_iters, (int)d.friction_max_unsettled);
  PetscCheck(d.equilibrium_tol >= 0 && d.equilibrium_tol < 1, comm, PETSC_ERR_USER_INPUT,
             "-equilibrium_tol %g: must lie in [0, 1) (0: no equilibrium iterations)", d.equilibrium_tol);
  PetscCheck(d.max_energy_error > 0, comm, PETSC_ERR_USER_INPUT,
             "-max_energy_error %g: must be a positive fraction (e.g. 0.25)", d.max_energy_error);
  PetscCheck(d.unload_increments >= 0, comm, PETSC_ERR_USER_INPUT,
             "-unload_increments %d: must be at least 1 (or 0: as -increments)", (int)d.unload_increments);
  PetscFunctionReturn(PETSC_SUCCESS);
}

OptionGroup DriverOptions() { return {"incremental driver (r_min method)", ReadDriverOptions, CheckDriverOptions}; }

} // namespace tf
