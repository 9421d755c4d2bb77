// Node-to-rigid-surface contact with the regularized Coulomb law (METHOD.md
// sections 3 and 4: r4, r5, r6). Each contact node carries the tool's local
// frame (l, n); its normal displacement is prescribed to follow the tool,
// its normal force is the reaction, and friction enters as an unsymmetric
// correction of its l row. State lives on every rank for its local nodes
// (owned and ghost) and is updated identically from ghost-filled vectors.
#pragma once

#include <petscvec.h>

#include <string>
#include <vector>

#include "tubeform/step/rmin.hpp"
#include "tubeform/tool/tool.hpp"

namespace tf {

class Problem;

struct ContactParams {
  double mu = 0;          // Coulomb coefficient
  double vcri = 0.01;     // quasi-stick slip (mm)
  double dphi_max = 1.0;  // r6: largest change of f_l / (mu f_n) in an increment
  double tol = 1e-4;      // friction iterations: change of f_l / (mu f_n) between iterates
  double group_tol = 1e-6; // contact/separation events within (1 + tol) r_min go together
  double gap_tol = 1e-7;   // a free node this close to the surface (mm) is in contact
};

class ContactSet {
public:
  // `candidates`: the node set that may touch the tool (e.g. "outer").
  // `symmetry`: node sets whose component along a global axis is held (e.g. x0 -> (1, 0)).
  void Setup(Problem &p, Tool *tool, const std::string &candidates, const std::vector<std::pair<std::string, Vec2>> &symmetry, const ContactParams &prm);
  PetscErrorCode Initialize(Problem &p); // nodes touching the tool at stroke 0

  // Frames of the contact nodes on the current geometry (before assembly).
  PetscErrorCode BeginIncrement(Problem &p);
  // New trial of a tool step: the committed active set, a new friction iteration sequence.
  void ResetIterates();
  // Friction iterate back to the increment's start (slip 0, committed f_n), no
  // predictor; the trial's releases stand.
  void LinearizeAtStart();
  // Prescribed normal motion (tool step dU, closing any gap) and friction rows.
  PetscErrorCode Constrain(Problem &p, double dU);
  // After a solve: new slip iterates; converged when the friction forces changed
  // by less than tol (relative to mu f_n) on every rank.
  PetscErrorCode UpdateIterates(Problem &p, Vec du, double dU, bool &converged);
  // Nodes that came into contact without force and that the solution du would
  // pull off the tool: counted, and released with `apply` for this trial (the
  // step is then re-solved; their force and slip state are dropped only when
  // the increment is committed, and a new trial starts from the committed set).
  // A released node that the next solution leaves inside the tool is grazing:
  // it goes back into contact and stays for the rest of the trial.
  PetscErrorCode ReleasePulled(Problem &p, Vec du, double dU, bool apply, PetscInt &released);
  // r4 (contact), r5 (separation), r6 (stick / reversal) for the solution du of step dU.
  PetscErrorCode LimitStep(Problem &p, Vec du, double dU, StepLimit &limit);
  // Accepts the increment (du for tool step dU, reactions scaled by react_scale,
  // r the accepted fraction of the trial): forces, slip, events, and the
  // projection of contact nodes back onto the tool. Returns the friction work.
  PetscErrorCode Commit(Problem &p, Vec du, double dU, double react_scale, double r, double &w_friction);
  // Releases every node (tools removed) after recording their forces.
  void ReleaseAll();

  // Friction forces on the body (owned nodes, global frame) into a contribution vector.
  PetscErrorCode AddFrictionForces(Problem &p, Vec f) const;
  // Contact force on the body of every owned contact node, global frame, added to f.
  PetscErrorCode AddContactForces(Problem &p, Vec f) const;
  // Sum over owned contact nodes of the force on the body (global frame), over ranks.
  PetscErrorCode TotalForce(Problem &p, double force[2]) const;
  PetscErrorCode Count(Problem &p, PetscInt &n) const;
  // Sum over contact nodes of the normal force magnitude f_n.
  PetscErrorCode NormalForceSum(Problem &p, double &sum) const;
  // Largest penetration (>= 0) and largest tension (normal force < 0) over contact nodes.
  PetscErrorCode Violations(Problem &p, double &penetration, double &tension) const;

  bool InContact(PetscInt node) const { return contact_[node]; }
  int Segment(PetscInt node) const { return segment_[node]; }
  const Tool &tool() const { return *tool_; }
  bool friction() const { return prm_.mu > 0; }

private:
  Tool *tool_ = nullptr;
  ContactParams prm_;
  std::vector<PetscInt> candidates_;
  std::vector<char> contact_, global_frame_;
  std::vector<Vec2> sym_dir_;      // held direction on a symmetry plane, {0, 0} if none
  std::vector<int> segment_;
  std::vector<double> fn_, x_, gap_, kappa_, dxk_, fnk_, r4_, r5_;
  std::vector<double> rate_;    // slip per unit stroke of the latest solution: predicts the next iterate
  std::vector<double> last_dx_; // slip of the last increment (predictor for static tools)
  bool predict_ = true;
  bool settled_ = true; // the last friction iterate met the tolerance (or there is no friction)
  int iteration_ = 0;
  std::vector<char> released_, frozen_; // within the current step
  double f_small_ = 0; // contact forces below this count as zero (1e-6 of the largest)
  std::vector<Vec2> n_, l_;

  bool SlipFree(PetscInt node) const { return contact_[node] && !global_frame_[node] && sym_dir_[node][0] == 0 && sym_dir_[node][1] == 0; }
  double NormalReaction(Problem &p, PetscInt node, const PetscScalar *react) const;
  double Slip(PetscInt node, const Vec2 &u, double dU) const;
};

} // namespace tf
