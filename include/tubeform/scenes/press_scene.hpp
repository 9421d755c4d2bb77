// The press scene (squaring and flattening): the class its two files share (src/scenes/press.cpp: the load
// path, stages, dies and loads; press_results.cpp: what it measures and keeps for a restart).
#pragma once

#include <algorithm>
#include <cmath>

#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/die.hpp"
#include "tubeform/scenes/die_columns.hpp"
#include "tubeform/scenes/hold.hpp"
#include "tubeform/scenes/scene.hpp"
#include "tubeform/scenes/stroke_path.hpp"
#include "tubeform/scenes/support.hpp"

namespace tf {

class PressScene : public Scene {
public:
  PressScene(const Options &opt, bool squaring);

  std::vector<std::string> BoundarySets() const override
  {
    if (WholeTube(part_)) return {"inner", "outer"};
    if (BothDies(part_)) return {"inner", "outer", "x0"};
    return {"inner", "outer", "x0", "y0"};
  }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh, part_); }
  std::string MeshLayout(const Options &opt) const override
  {
    return Scene::MeshLayout(opt) + (WholeTube(part_)  ? " (the full model: four times that around)"
                                     : BothDies(part_) ? " (the half model: twice that around)"
                                                       : "");
  }
  LoadPath Path(const Options &opt) const override;
  // Stages by the lambda an increment starts at: 0 press, 1 release, 2 press (the second pass), 3 release, ...:
  // pass k presses over [2k, 2k + 1] and releases over [2k + 1, 2k + 2].
  static int StageAt(double lambda) { return (int)std::floor(lambda + kLambdaTol); }
  bool Unloading(double lambda) const override { return StageAt(lambda) % 2 == 1; }
  // The quarter model carries half the punch load of the full tube (the
  // other half pushes the left quarter), moving by U; the half model carries
  // half of it on each die, closing by 2 U; the full model all of it on each
  // die. The reversed loads of the paper's unloading do no work along the stroke.
  double LoadWorkShare(double lambda) const override
  {
    if (Unloading(lambda) && passes_[pass_].release == Unload::Reverse) return 0.0;
    return WholeTube(part_) ? 2.0 : BothDies(part_) ? 1.0 : 0.5;
  }
  // Each die's force over its own travel (scenes/common.cpp); a later pass's dies from where they start.
  double ToolWork(const HistoryRow &prev, const HistoryRow &row, double) const override;
  // The stroke of the dies in place: the first pass's, then (once their dies are set up) each later one's.
  double ToolStroke(double lambda) const override;

  // Force control: the model's half of the punch load, rising to the pass's force over its press (-die_force,
  // PassExtent::Ramp); or the side dies' force in the model (-side_force).
  double ToolForce(double lambda) const override;
  PetscErrorCode Initialize(Model &m, ContactSpec &tools) override;
  PetscErrorCode BeginStage(Model &m, double lambda) override;
  PetscErrorCode BeginIncrement(Model &m, double lambda) override;
  PetscErrorCode Load(Model &m, double lambda, double dlambda) override;
  PetscErrorCode ExternalForce(Model &m, double lambda, Vec f) override;
  PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) override;
  std::vector<std::pair<std::string, double>> FinalMetrics(const History &h) const override;
  std::string ReleaseOf(int pass) const override
  {
    return passes_[pass].release == Unload::Withdraw ? "the dies withdrawn"
                                                     : "the contact forces reversed, the dies removed";
  }
  PetscErrorCode Persist(Model &m, Archive &ar) override;
  ~PressScene() override { (void)VecDestroy(&reversed_.forces); }

private:
  // VCRI as a fraction of the outer nodes' spacing: a micro-slip far below an
  // element, so that sticking nodes hold (docs/theory.md, "The law").
  static constexpr double kVcriOfSpacing = 0.02;
  // Where the first pass's release begins (lambda): each pass takes one unit of it to press and one to release.
  static constexpr double kFirstRelease = 1.0;
  // The load the withdrawn dies may still carry before the next pass (their contact set then goes), over the largest
  // load so far: a node that touched at the start, back there after an elastic press, keeps the equilibrium
  // iterations' residual (1e-4-2e-4 of it, 0.02 mm on the paper's tube); a die the tube reaches past carries a share
  // of the press's load, and one released by the withdrawal none.
  static constexpr double kWithdrawnLoad = 1e-2;
  // The tools' places in the contact set.
  static constexpr int kUpper = 0, kLower = 1;
  // The right side die's place (-side_die): after the lower die of the half and full models.
  int SideDie() const { return BothDies(part_) ? kLower + 1 : kLower; }
  Options opt_;
  bool squaring_;
  TubePart part_; // the quarter, the half model x >= 0 with both dies, or the whole tube (ModelOf)
  // A pass: how far it presses, its turn, its dies, its upper die's way, its hold, its side dies and (a later pass)
  // where its dies start; the scene's passes are a list of them, built once from the options.
  struct Pass {
    PassExtent extent;                // its stroke or force (the first pass's stroke: stroke_; scenes/pass_extent.hpp)
    TurnMap turn;                     // draws its dies, built in its press's frame, into the tube's (PassTurn)
    StrokePath path;                  // its stroke over its press: the first pass's -stroke_path or -die_path; a later
                                      // one's straight by its stroke from where its dies start (PassDies), or its
                                      // upper die's path of its own (-pass<N>_die_path)
    double rise = 1;                  // U per unit of its upper die's start_back: 1 by the stroke; on a path of its
                                      // own, -y / 2 per unit stroke along its first piece
    DieSet dies;                      // its dies (DiesOfPass: the upper one's shape and motion, lower, side)
    Unload release = Unload::Reverse; // how it lets the tube go (ReleaseOfPass: -unload, -pass<N>_unload)
    MotionHandle lower_motion;        // its lower die's motion at the stroke U, for the tools' work (LowerDieMotion)
    double reach = kNever;            // where they close on the tube (DieReach; pressed by a force: CheckForceReach)
    bool held = false;                // the full model's pass held by the rotation hold (not its pins) while pressing
    bool side_dies = false;           // it has side dies (-side_die, -pass<N>_side_die)
    std::vector<double> start_back;   // how far back along its motion each die starts (StartOnTube; a later pass)
    double back = 0;                  // StartBack(), from start_back and the dies' motions (PassDies)
    double side_from = 0;             // the side dies' travel where it starts (SideStroke at the release before it)
    double start = 0;                 // where its upper die starts (PassStart; once its dies are set up)
  };
  std::vector<Pass> passes_;
  PetscInt pass_ = 0;  // the pass whose dies are in place
  double floor_y_ = 0; // where the floor of the pass in place is
  ContactSpec spec_;   // the contact set's nodes, supports and law (for a later pass's dies)
  AxisPins pins_;      // the full model's pins on the press's axis (scenes/support.hpp)
  RotationHold hold_;  // or, in their place, the rotation hold (scenes/hold.hpp)
  SpringbackPin pin_;  // the half and full models' springback pin along the press's y
  double stroke_ = 0, back_ = 0;
  int flank_ = 0, apex_ = -1; // the die's segments the shape metrics use (scenes/die.hpp)
  bool unloading_ = false;
  // The contact forces a release reverses (the paper's unloading): nodal, their total on the upper die and its moment
  // about the tool frame's origin (TotalForce).
  struct Reversed {
    Vec forces = nullptr;
    double total[2] = {0, 0};
    double moment = 0;
  } reversed_;
  long side_ends_[2] = {-1, -1}; // input node numbers of the side's ends (latest loading state)

  // The end of the release stage under way (the load path: press 0-1, release 1-2, press 2-3, release 3-4, ...):
  // the reversed loads fall to zero there.
  double ReleaseEnd() const { return 2.0 * pass_ + 2; }
  // The load path's stage where pass k presses.
  static double PressStage(int k) { return 2.0 * k; }

  // Collective: the dies of a pass; the floor under the tube's lowest point (kept for a restart).
  PetscErrorCode PassTools(Model &m, int pass, std::vector<Tool> &tools);
  // (the floor's y in the pass's press frame; the dies drawn there, then turned with the tube: PassMap; an upper die
  // off the axis moved back to where it touches the round tube)
  PetscErrorCode PassTools(Model &m, int pass, double floor_y, std::vector<Tool> &tools);

  // The later pass in place's dies where they start (drawn on floor_y_, moved back by its start_back) and, in the
  // full model, its pins on the press's axis, and the held directions the contact set keeps (`symmetry`): the
  // pass's start (BeginStage, StartPass) and a restart inside it (Persist) alike.
  PetscErrorCode PassDies(Model &m, std::vector<Tool> &tools, std::vector<std::pair<std::string, Vec2>> &symmetry);
  // Collective: the next pass's dies set up from where they touch the tube the springback left (BeginStage).
  PetscErrorCode StartPass(Model &m);
  // The side dies' travel at `lambda` (the history's side_stroke): by the stroke from where the pass's begins (the
  // first pass's: its U), their own under a force, or as far as their motion has taken them in at the pass's stroke
  // (fixed, a path, pulses: Motion::Travel); through the releases too, so that a pass's side dies go on
  // from the row before them (StartPass), whatever moved the pass before.
  double SideStroke(Model &m, double lambda) const;
  // Collective: the dies of the pass before `next`, withdrawn (-unload withdraw, -pass<N>_unload), carry no load.
  PetscErrorCode CheckWithdrawn(Model &m, int next) const;

  TurnMap PassMap(int pass) const { return passes_[pass].turn; }
  // The history's U at lambda (PassExtent::U): the force-controlled die's own, -die_path's, a later pass's upper
  // die's position (from the same zero as the first pass's, the die touching the round tube; it starts UpperBack()
  // before it).
  double Stroke(Model &m, double lambda) const;
  // How far back the later pass's dies start to touch the tube where the pass before left it (PassDies; 0 before
  // they are set up): the least any die that moves by the stroke (not by a force) is moved back (they travel together
  // until the one furthest along is at its -pass<N>_stroke: no die passes it, and in a press symmetric top to bottom
  // every die ends there), and the upper die's.
  double StartBack() const { return passes_[pass_].back; }
  // (in U: a path of its own moved back along its first piece)
  double UpperBack() const
  {
    const Pass &p = passes_[pass_];
    return p.start_back.empty() ? 0.0 : p.start_back[kUpper] * p.rise;
  }
  // The later pass's stroke (the upper die's position) where it starts and ends (on a path of its own: its stroke
  // from where it starts).
  double PassStart() const { return UpperBack() != 0 ? -UpperBack() : 0.0; }
  double PassEnd() const { return passes_[pass_].extent.stroke + (OwnPath() ? 0.0 : StartBack()) - UpperBack(); }
  // The pass in place's upper die is on a path of its own (-pass<N>_die_path).
  bool OwnPath() const { return pass_ > 0 && passes_[pass_].dies.motion.OwnPath(); }
  // The rotation hold holds the pass in place (its nodes fixed, holding the slide too, until the dies hold it).
  bool Holding() const { return passes_[pass_].held && !unloading_; }
  // The tube's coordinates into the frame of the press in place (its die moving along -y).
  TurnMap Press() const { return PassMap(pass_).Inverse(); }
  // The full model's pins hold the tube along the press's x.
  Vec2 AxisHeld() const { return PassMap(pass_)({1, 0}); }
  // What holds the full model's tube along the press's x in place of a symmetry plane: the rotation hold while
  // it holds the pass, else the pins; none in the quarter and half models.
  Support *AxisSupport() { return !WholeTube(part_) ? nullptr : Holding() ? static_cast<Support *>(&hold_) : &pins_; }
  // The supports at work, in the order they constrain: the axis's (AxisSupport), the springback pin (holding in a
  // release of the half and full models, nothing otherwise).
  std::vector<Support *> Supports()
  {
    std::vector<Support *> at_work;
    if (Support *axis = AxisSupport()) at_work.push_back(axis);
    at_work.push_back(&pin_);
    return at_work;
  }
  // What the supports read of the press at `lambda` (its stroke asked only where one needs it).
  SupportStep Step(Model &m, double lambda) const
  {
    return {PassMap(pass_), !unloading_, [this, &m, lambda] { return Stroke(m, lambda); }};
  }
  // The nodes whose direction the contact set keeps: the quarter's and the half's symmetry planes (the half tube
  // between both dies is mirrored about the y axis only), the full model's pins (the rotation hold's: inner nodes).
  std::vector<std::pair<std::string, Vec2>> Symmetry() const;

  // The punch load per vertical force of the model on the upper die: the quarter and the half model carry half.
  double LoadPerModelForce() const { return WholeTube(part_) ? 1.0 : 2.0; }

  PetscErrorCode Shape(Model &m, double, HistoryRow &row);
};

} // namespace tf
