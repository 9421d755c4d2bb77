// The incremental driver's own options: read into Options::driver and Options::accuracy and checked (one line naming
// the option).
#include "tubeform/driver/driver_options.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/core/option_reader.hpp"
#include "tubeform/material/factory.hpp"
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
  PetscCall(ChooseWord(PetscOptionsObject, read, "-plastic_update",
                       "tangent (the rate form with the start's flow direction), radial (radial return: the elastic "
                       "trial projected back onto the yield surface; isotropic J2 only), auto (radial where the "
                       "material has it and the increments are in equilibrium, tangent elsewhere; the default where "
                       "-target_load or -target_c_over_t is given)",
                       kPlasticUpdateWords, d.plastic_update));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Inside the driver's block: inertia, the equilibrium iterations and the kinematics they choose; the factorization.
PetscErrorCode ReadDynamics(PetscOptionItems *PetscOptionsObject, OptionReader &read, DriverParams &d)
{
  PetscFunctionBeginUser;
  PetscCall(ChooseWord(PetscOptionsObject, read, "-dynamics",
                       "quasistatic (no inertia), implicit (lumped mass, backward Euler in time), auto "
                       "(quasi-static until an increment's friction iterations do not settle or a cut step "
                       "cannot meet its first event, implicit from then on)",
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
  PetscCheck(d.plastic_update != PlasticUpdate::Radial || LawOf(opt.material) == LawKind::Elastic ||
               LawOf(opt.material) == LawKind::IsotropicJ2,
             comm, PETSC_ERR_USER_INPUT,
             "-plastic_update radial: isotropic J2 only (not with -hardening chaboche, -material_r, -material_hill)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The accuracy group: whether the run estimates its own error (and the companions' LU), the accuracy demanded of it
// (a finer level where the estimate passes it) or expected by its preset (a warning), and the levels' bounds.
PetscErrorCode ReadAccuracyOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt)
{
  AccuracyParams &a = opt.accuracy;

  PetscFunctionBeginUser;
  PetscCall(read.Bool(PetscOptionsObject, "-error_estimate",
                      "Estimate the error of the load and C/t (tool scenes), the mesh's part and the increments', "
                      "from two companion runs after the main run (docs/accuracy.md, \"The error estimate\")",
                      a.error_estimate));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-error_estimate_factorization",
                       "The companion runs' LU (as -factorization): klu, cheaper per call on their few hundred dofs, "
                       "or mumps",
                       kFactorizationWords, a.estimate_factorization));
  PetscCall(read.Real(PetscOptionsObject, "-target_load",
                      "Accuracy demanded of the load (relative; 0: none): where the estimate passes it, the run "
                      "goes on at a finer level (docs/accuracy.md, \"Accuracy on demand\")",
                      a.target_load));
  PetscCall(read.Real(PetscOptionsObject, "-target_c_over_t",
                      "Accuracy demanded of C/t (absolute; 0: none), as "
                      "-target_load",
                      a.target_c_over_t));
  PetscCall(read.Real(PetscOptionsObject, "-expect_load",
                      "The load's accuracy the discretization is expected to give (relative; the presets set it; "
                      "0: none): an estimate above it is a warning (a -target_load replaces it)",
                      a.expect_load));
  PetscCall(
    read.Real(PetscOptionsObject, "-expect_c_over_t", "As -expect_load, for C/t (absolute)", a.expect_c_over_t));
  PetscCall(read.Int(PetscOptionsObject, "-target_levels",
                     "Most levels a -target_load or -target_c_over_t runs "
                     "(the first included)",
                     a.target_levels));
  PetscCall(read.Real(PetscOptionsObject, "-target_time",
                      "No finer level whose predicted time would bring the job past this many seconds (0: no "
                      "limit): the run ends with its best level, warned",
                      a.target_time));
  // A demanded accuracy leaves the discretization to the run, its plastic update with it: the radial return where
  // the material has it (auto), converged in the step at the presets' increment limits where the tangent update is
  // first order, so that finer levels refine the cells alone (docs/accuracy.md, "Accuracy on demand").
  PetscBool update_named = PETSC_FALSE;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-plastic_update", &update_named));
  if ((a.target_load > 0 || a.target_c_over_t > 0) && !update_named) opt.driver.plastic_update = PlasticUpdate::Auto;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckAccuracyOptions(MPI_Comm comm, const Options &opt)
{
  const AccuracyParams &a = opt.accuracy;
  PetscFunctionBeginUser;
  PetscCheck(a.target_load >= 0 && a.target_load < 1 && a.target_c_over_t >= 0, comm, PETSC_ERR_USER_INPUT,
             "-target_load %g, -target_c_over_t %g: must be a fraction in [0, 1) and a non-negative C/t", a.target_load,
             a.target_c_over_t);
  PetscCheck(a.expect_load >= 0 && a.expect_load < 1 && a.expect_c_over_t >= 0, comm, PETSC_ERR_USER_INPUT,
             "-expect_load %g, -expect_c_over_t %g: must be a fraction in [0, 1) and a non-negative C/t", a.expect_load,
             a.expect_c_over_t);
  PetscCheck(a.target_levels >= 1 && a.target_levels <= kMaxTargetLevels, comm, PETSC_ERR_USER_INPUT,
             "-target_levels %d: must be between 1 and %d", (int)a.target_levels, (int)kMaxTargetLevels);
  PetscCheck(a.target_time >= 0 && std::isfinite(a.target_time), comm, PETSC_ERR_USER_INPUT,
             "-target_time %g: must be a number of seconds >= 0 (0: no limit)", a.target_time);
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::vector<OptionGroup> DriverOptions()
{
  return {{"incremental driver (r_min method)", ReadDriverOptions, CheckDriverOptions},
          {"error estimate and accuracy", ReadAccuracyOptions, CheckAccuracyOptions}};
}

} // namespace tf
