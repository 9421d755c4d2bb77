// The incremental driver's parameters (docs/theory.md, section 5): its increments and r_min's bounds, its stops, the
// friction and equilibrium iterations of an increment, inertia and the load path's time, the kinematics and the
// factorization; and the error estimate and the accuracy it holds a run to. Options holds one of each (so that they
// travel with the run's options to its levels and companions); the driver reads and checks them
// (src/driver/driver_options.cpp, handed to ReadOptions by main as two groups).
#pragma once

#include <petscsys.h>

#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/body/body.hpp"
#include "tubeform/material/elastic.hpp"

namespace tf {

// Inertia: none, always, or switched on at the first increment whose friction
// iterations do not settle in quasi-static steps (docs/theory.md, "Inertia").
enum class Dynamics { Quasistatic, Implicit, Auto };
inline constexpr const char *kDynamicsWords[] = {"quasistatic", "implicit", "auto"};
// Where r1 ends a step (-rmin_yield): at each yield onset (the paper's), or points yield inside steps.
enum class RminYield { Onset, Inside };
inline constexpr const char *kRminYieldWords[] = {"onset", "inside"};
// The strain and spin update asked for (-kinematics): forward, midpoint (ObjectiveScheme's), or auto: midpoint with
// equilibrium iterations, forward without (DriverParams::kinematics is the one chosen).
enum class Kinematics { Forward, Midpoint, Auto };
inline constexpr const char *kKinematicsWords[] = {"forward", "midpoint", "auto"};
// The words of -factorization and -error_estimate_factorization, in Factorization's order (assembly/linear_solver.hpp).
inline constexpr const char *kFactorizationWords[] = {"mumps", "klu"};

struct DriverParams {
  PetscInt increments = 10;                              // trial increments over the load path
  PetscInt unload_increments = 0;                        // > 0: trial increments per unit of the path past lambda 1
  double rmin_deps = BodyParams{}.rmin_deps;             // r2: largest principal strain increment
  double rmin_deps_yield = BodyParams{}.rmin_deps_yield; // r2 also at most this many yield strains (0: off)
  double rmin_domega = BodyParams{}.rmin_domega;         // r3: largest rotation increment (rad)
  double rmin_group_tol = BodyParams{}.group_tol;        // events within (1 + tol) r_min are taken together
  RminYield rmin_yield = RminYield::Onset; // onset: r1 ends a step at each yield onset; inside: points yield inside
  double rmin_yield_tol = BodyParams{}.yield_tol; // inside: re-solve while an elastic fraction moves by more
  double rmin_event_tol = 1e-2;                   // re-solved steps locate their events to this fraction of the step
  PetscInt rmin_max_increments = 100000;
  PetscInt rmin_stall_increments = 1000; // stop when this many increments advance lambda by < kStallAdvance
  PetscInt rmin_max_redo = 10;           // re-solves per increment for loading/unloading switches
  PetscInt friction_max_iters = 30;
  // An unsettled step is a counted compromise; this many in a row means the
  // iterations no longer converge at any step size: the run stops.
  PetscInt friction_max_unsettled = 50;
  // Stop (results written) when the energy balance error passes this: a quarter of the work
  // unaccounted for means the load-stroke curve is no longer a solution.
  double max_energy_error = 0.25;
  PetscBool drift_correction = PETSC_FALSE;
  PlasticUpdate plastic_update = PlasticUpdate::Tangent; // -plastic_update
  Factorization factorization = Factorization::Mumps;    // where every rank factors the whole matrix (-factorization)
  // Equilibrium iterations in every increment: the largest out-of-balance force
  // on a free dof at most this fraction of the time-averaged nodal force (0: off,
  // the paper's forward increments).
  double equilibrium_tol = 0.005;
  Dynamics dynamics = Dynamics::Quasistatic;             // implicit/auto: lumped mass, backward Euler
  double dynamics_time = 1.0;                            // s for lambda 0 -> 1 (scenes without tools)
  double punch_speed = 1.0;                              // mm/s (tool scenes: duration = stroke / speed)
  ObjectiveScheme kinematics = ObjectiveScheme::Forward; // docs/theory.md, section 2
};

// The most levels -target_levels allows: each finer level costs up to 27 x the last (kMaxRatio cubed), so a
// sixth is beyond any machine's patience.
constexpr PetscInt kMaxTargetLevels = 5;

// The run's estimate of its own error (tool scenes, driver/answer.hpp), and the accuracy it is held to: a target
// demanded (a finer level where the estimate passes it, driver/refine.hpp), else the preset's expectation (a
// warning). Options holds one; the driver reads and checks them (ReadAccuracyOptions, CheckAccuracyOptions).
struct AccuracyParams {
  PetscBool error_estimate = PETSC_TRUE;                     // two companion runs after the main run
  Factorization estimate_factorization = Factorization::Klu; // the companions' (-error_estimate_factorization)
  double target_load = 0, target_c_over_t = 0;               // accuracy on demand (0: none)
  double expect_load = 0, expect_c_over_t = 0; // what the preset's discretization is expected to give (0: none)
  PetscInt target_levels = 3;                  // at most this many levels, the first included
  double target_time = 0;                      // no level predicted to bring the job past this (s; 0: no limit)
  // Not an option: a request to the companions (driver/companions.hpp, RunCompanions) for the increments' part
  // alone, on these options' own cells (a level that takes the last one as its mesh companion, driver/refine.hpp).
  bool steps_only = false;
};

} // namespace tf
