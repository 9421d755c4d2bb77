// The global linear system of one increment: K du = dF with prescribed dofs.
//
// K is a preallocated AIJ matrix whose pattern never changes; every increment
// refills its values. Nodes may carry a rotated local frame (l, n): their two
// dofs are then (u.l, u.n), element blocks are rotated as T^T K T on the way
// in, and a prescribed component (e.g. the normal of a contact node) is a
// plain dof of that frame. Prescribed dofs are imposed by zeroing rows and
// columns (MAT_KEEP_NONZERO_PATTERN), so MUMPS reuses its symbolic analysis.
//
// The body's part of K (its cell blocks in the node frames) is kept in a
// second matrix between the solves of an increment: the friction iterations
// and re-solves of a step change the tangent of few cells or none, so a solve
// starts from a copy of it plus the blocks that changed, instead of adding
// every cell again (Body::AssembleTangent). It is rebuilt whenever a node
// frame turns.
#pragma once

#include <petscksp.h>

#include <cmath>
#include <string>
#include <vector>

#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/fe/quad.hpp"
#include "tubeform/mesh/archive.hpp"
#include "tubeform/mesh/mesh.hpp"

namespace tf {

// A direction counts as a node frame's axis when its component along the axis
// is 1 within this (round-off of the frame angle's sine and cosine).
constexpr double kAxisTol = 1e-12;

struct Prescribed {
  PetscInt node;     // local node
  int comp;          // 0 = x (or l), 1 = y (or n) in the node's frame
  double value;      // displacement increment
  double unit = 0.0; // added to value per unit of the system's extra unknown (ExtraUnknown)
};

// One unknown beyond the dofs: the motion s of a force-controlled tool (docs/theory.md, "Force-controlled
// tools"). Its nodes' prescribed values grow by their `unit` per unit of s; a condition on the reactions fixes
// s. The system solves with the values given (s as the caller guessed it) and with a unit motion alone, on one
// factorization, and takes the combination that meets the condition.
class ExtraUnknown {
public:
  virtual ~ExtraUnknown() = default;
  // Collective: what the condition still misses for the reactions in System::reactions_local() (an affine
  // function of them, e.g. the target force less the tool's force; 0 when met).
  virtual PetscErrorCode Missing(double &missing) = 0;
  // The solution taken moves the unknown by ds beyond the guess its prescribed values were made with.
  virtual void Moved(double ds) = 0;
  // What moves by the unknown, for errors ("the force-controlled V-die").
  virtual std::string Name() const { return "the force-controlled tool"; }
  // "" if a unit of the unknown changes its miss as the condition needs (`slope`: the miss's fall per unit), else
  // why not, for the error: by default, a force that does not grow as its tool advances.
  virtual std::string Stalled(double slope) const;
};

class System {
public:
  System() = default;
  System(const System &) = delete;
  System &operator=(const System &) = delete;
  ~System();

  // `factorization`: the one where every rank factors the whole matrix (linear_solver.hpp).
  PetscErrorCode Setup(const Mesh &mesh, Factorization factorization = Factorization::Mumps);

  // Node frames: angle of the l axis from x (n is l turned +90 degrees).
  void SetFrame(PetscInt node, double angle);
  void ClearFrames();
  bool HasFrame(PetscInt node) const { return has_frame_[node]; }
  double FrameAngle(PetscInt node) const { return std::atan2(sin_[node], cos_[node]); }

  // Assembly of one increment: Begin, Add*, then Solve.
  PetscErrorCode Begin();
  // A cell block into K, or between BeginBody and EndBody into the kept body
  // matrix (a whole block when rebuilding, else a change ke_new - ke_old).
  PetscErrorCode AddElement(PetscInt cell, const fe::ElemMat &ke);
  // The kept body matrix (after Begin, before any other Add*): collective
  // BeginBody tells whether it must be rebuilt (`rebuild` on input: the
  // caller's wish, e.g. most cells changed; true on output if it or any rank
  // needs it: no kept matrix yet, or a frame turned); EndBody copies it into K.
  PetscErrorCode BeginBody(bool &rebuild);
  PetscErrorCode EndBody();
  // The kept body matrix no longer matches the cell blocks (rebuilt next time).
  void InvalidateBody() { kb_valid_ = false; }
  // scale x d (a global vector, e.g. lumped masses) added to the diagonal of K
  // (rotation invariant when both dofs of a node carry the same value).
  PetscErrorCode AddDiagonal(Vec d, double scale);
  // Adds a dense block coupling `nn` local nodes (2 nn x 2 nn, row-major,
  // global frame); used for load stiffness and contact rows.
  PetscErrorCode AddBlock(const PetscInt *nodes, int nn, const double *k);
  void AddForce(PetscInt node, double fx, double fy);
  // A force on every dof (local contribution vector, global frame), prescribed ones included (their reactions).
  PetscErrorCode AddForces(Vec f, double scale = 1.0);
  // A load given in the node's frame (l, n).
  void AddFrameForce(PetscInt node, double fl, double fn);
  // k on the node's l dof (l l^T in the global frame): a tangential spring.
  PetscErrorCode AddFrameStiffness(PetscInt node, double k_ll);
  // Adds an out-of-balance force (global frame, contribution vector) to the
  // loads of the free dofs; call after the prescribed dofs are known.
  PetscErrorCode AddFreeForce(Vec f);
  // Owned nodes only: after assembly, row l of the node's frame gets
  // coeff x (row n, with its load): the unsymmetric friction correction row
  // (docs/theory.md, section 6). Rows l and n of a node share their pattern.
  void AddRowCoupling(PetscInt node, double coeff) { couplings_.push_back({node, 0, coeff}); }
  void Prescribe(PetscInt node, int comp, double value, double unit = 0.0)
  {
    prescribed_.push_back({node, comp, value, unit});
  }
  // The extra unknown of this assembly (every rank alike; nullptr: none). Begin clears it.
  void SetExtraUnknown(ExtraUnknown *extra) { extra_ = extra; }
  // Prescribes the displacement along the global unit direction (dx, dy); with
  // a frame, that direction must be one of the frame's axes. False otherwise.
  // `unit`: as Prescribed::unit, along the same direction.
  bool PrescribeAlong(PetscInt node, double dx, double dy, double value, double unit = 0.0);
  // Solves; `du` (local vector, global frame, ghosts filled) receives the
  // increment and `reactions` the force increments at the prescribed dofs
  // (same order as prescribed(); entries for unowned nodes are 0).
  PetscErrorCode Solve(Vec du, std::vector<double> &reactions);
  // Equilibrium iterations: the next Solve starts from the iterate du_i
  // (local, global frame; nullptr: none), whose body forces the caller has put
  // into the loads as f_ext - f_int(du_i). The Solve then reports the iterate's
  // largest out-of-balance force on the free dofs, or the extra unknown's miss if larger (iterate_residual), and, when
  // it is at most `accept_below`, takes du_i as the solution without factoring
  // (accepted()); above `reject_above` it neither factors nor solves (the
  // caller backtracks: a line search); else it solves for the correction of du_i.
  void SetIterate(Vec du_local, double accept_below, double reject_above = PETSC_MAX_REAL)
  {
    iterate_ = du_local;
    accept_below_ = accept_below;
    reject_above_ = reject_above;
  }
  double iterate_residual() const { return iterate_residual_; }
  bool solved() const { return solved_; }
  bool accepted() const { return accepted_; }
  // Collective: the sign of the last factored matrix's determinant (0: not
  // computed; linear_solver.hpp), asked once an increment, not at every solve.
  PetscErrorCode DeterminantSign(int &sign) const;
  // The reaction increments of the last solve as a local vector in the node
  // frames (prescribed dofs only, ghosts filled).
  Vec reactions_local() const { return reactions_local_; }

  const std::vector<Prescribed> &prescribed() const { return prescribed_; }
  Vec CreateLocalVector() const;

  // Global 2-norm and largest entry of a local force vector (global frame)
  // with the prescribed dofs removed: the out-of-balance force of the free dofs.
  PetscErrorCode FreeNorms(Vec f_local, double &norm2, double &norm_max);

  PetscInt factorizations() const { return nsolves_; }
  PetscInt ndofs() const { return ndofs_; }     // global
  bool redundant() const { return redundant_; } // every rank factors the whole matrix (PCREDUNDANT)
  // Which factorization the solver uses and why (one line).
  const std::string &solver() const { return solver_; }
  // Collective: writes or reads what carries between increments: the node
  // frames (kept by nodes that left a tool) and the factorization count.
  PetscErrorCode Persist(Archive &ar)
  {
    PetscFunctionBeginUser;
    ar.Group("/system");
    PetscCall(ar.Value("factorizations", nsolves_));
    PetscCall(ar.Nodes("has_frame", has_frame_));
    PetscCall(ar.Nodes("cos", cos_));
    PetscCall(ar.Nodes("sin", sin_));
    kb_valid_ = false;
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  // Collective: work of an increment du of the external actions, component by
  // component in the node frames: the applied force f_ext on free dofs and the
  // support reaction (= internal force f_int; none if f_int is null) on
  // prescribed ones. Forces are per-rank contribution vectors (local, not
  // ghost-summed), e.g. trapezoidal means of the start and end of the increment.
  PetscErrorCode ExternalWork(Vec f_ext, Vec f_int, Vec du, double &work);

private:
  const Mesh *mesh_ = nullptr;
  Mat k_ = nullptr, reaction_rows_ = nullptr;
  Mat kb_ = nullptr;      // the body's part of K (see above)
  bool kb_valid_ = false; // kb_ holds the blocks of the current frames
  Mat target_ = nullptr;  // where AddBlock puts values: k_, or kb_ between BeginBody and EndBody
  Vec rhs_ = nullptr, sol_ = nullptr, fixed_ = nullptr, f_local_ = nullptr, diag_ = nullptr;
  KSP ksp_ = nullptr;
  PetscInt ndofs_ = 0;
  bool redundant_ = true;
  ISLocalToGlobalMapping ltog_ = nullptr;
  std::vector<char> has_frame_;
  std::vector<double> cos_, sin_;
  std::vector<Prescribed> prescribed_, couplings_; // couplings: value = coefficient
  Vec reactions_local_ = nullptr, reactions_global_ = nullptr;
  std::vector<PetscInt> last_rows_;
  PetscInt nsolves_ = 0;
  std::string solver_;

  Vec iterate_ = nullptr; // the iterate of SetIterate (not owned)
  double accept_below_ = 0, reject_above_ = 0, iterate_residual_ = 0;
  bool solved_ = true, accepted_ = false;
  Vec x_ = nullptr, work_ = nullptr, work_local_ = nullptr; // the iterate in node frames; scratch
  ExtraUnknown *extra_ = nullptr;
  // The extra unknown's unit motion: its prescribed values, K times them, then its solution.
  Vec unit_ = nullptr, unit_sol_ = nullptr;

  // Reactions of a solution (node frames) at the prescribed rows: K(rows, :) sol - b_rows, into `reactions`
  // (prescribed() order) and reactions_local().
  PetscErrorCode Reactions(Vec sol, const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows,
                           std::vector<double> &reactions);
  // The extra unknown (assembly/extra_unknown.cpp): its unit motion's prescribed values and their loads K u_1
  // (after the couplings, before the prescribed rows are zeroed); after the factorization, the unit solution
  // and the combination of the two that meets the condition.
  PetscErrorCode PrepareUnitMotion(bool &any);
  PetscErrorCode CombineUnitMotion(const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows,
                                   std::vector<double> &reactions);

  void Rotate(PetscInt node, double &a, double &b, bool to_local) const;
  // A local vector (global frame) into a global one in the node frames (ADD: summed contributions; INSERT: values).
  PetscErrorCode LocalToNodeFrames(Vec v_local, Vec v_global, InsertMode mode);
  // The friction correction rows into K and the loads (after assembly).
  PetscErrorCode AddCouplings();
  // The steps of Solve: the prescribed dofs owned here as global rows and their values; the rows
  // K(rows, :) kept for the reactions (rebuilt only when some rank's prescribed set changed); an iterate's
  // largest out-of-balance force on the free rows, or the extra unknown's miss if larger (iterate_residual_; its
  // b - K x left in work_); the prescribed values into K and the loads (of the correction, with an iterate); the
  // factorization and solve.
  PetscErrorCode PrescribedRows(std::vector<PetscInt> &rows, std::vector<PetscScalar> &vals);
  PetscErrorCode KeepReactionRows(const std::vector<PetscInt> &rows);
  PetscErrorCode IterateResidual(const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows, bool extra,
                                 std::vector<double> &reactions);
  PetscErrorCode ApplyPrescribed(const std::vector<PetscInt> &rows, std::vector<PetscScalar> &vals);
  PetscErrorCode FactorAndSolve(const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows, bool extra,
                                std::vector<double> &reactions);
};

} // namespace tf
