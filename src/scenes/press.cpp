// The tool scenes of METHOD.md section 1: `squaring` (quarter tube, upper V-die) and `flattening` (quarter ring,
// flat plate), with unloading. With a lower die that does not mirror the upper one (-lower_die,
// -lower_die_motion) or -model half, the half tube x >= 0 between both dies; -model full: the whole tube, both
// dies across the y axis.
//
// Load path: lambda in [0, 1] presses the tool to the final stroke; with -unload reverse or withdraw, lambda in
// [1, 2] unloads:
//   reverse  (the paper): the contact forces at the end of loading applied reversed as nodal loads, tools removed;
//   withdraw: the tool moves back and releases the nodes one by one (r5);
// either with every point elastic (the paper's) or by the material's law: -springback, ElasticRelease.
// With -pass2_stroke, a second pass after the paper's unloading: lambda in [2, 3] presses its dies from their
// start, [3, 4] springs back; -pass2_turn turns the tube before it (its dies drawn turned the other way, its
// metrics and forces in its press's frame: die.hpp, PassTurn). -die_force presses by a force (the stroke its
// outcome), -side_die adds dies at the sides, -die_offset and -die_path move the die off the axis (the full
// model under the rotation hold, hold.hpp); docs/dies.md.
// History: stroke = tool stroke U (mm; half the dies' closing; over two passes the sum, the second pass's die at
// stroke - U1), load = punch load on the full tube (N/mm), the upper die's vertical force on the model: twice it
// in the quarter and the half model, which carry half of it.
#include <algorithm>
#include <cmath>

#include "tubeform/metrics/shape.hpp"
#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/contact_params.hpp"
#include "tubeform/scenes/die.hpp"
#include "tubeform/scenes/hold.hpp"
#include "tubeform/scenes/press_shape.hpp"
#include "tubeform/scenes/stroke_path.hpp"

namespace tf {

namespace {

class PressScene : public Scene {
public:
  PressScene(const Options &opt, bool squaring)
      : opt_(opt), squaring_(squaring), half_(!QuarterModel(opt)), full_(FullModel(opt))
  {
    stroke_ = opt.stroke_corner_radius > 0 ? StrokeForCornerRadius(opt.tube_ro, opt.stroke_corner_radius, opt.die_angle)
                                           : opt.stroke;
    back_ = stroke_; // withdraw: back to the start, so every node has left the tool (by r5)
    stroke2_ = opt.pass2_stroke;
    path_ = opt.die_path.empty() ? StrokePath(opt.stroke_path, stroke_) : StrokePath(DiePath(opt));
    for (int pass = 0; pass < 2; ++pass)
      side_dies_[pass] = PassOptions(opt, pass).side_die != "none", held_[pass] = HeldByRotation(opt, pass);
  }

  std::vector<std::string> BoundarySets() const override
  {
    if (full_) return {"inner", "outer"};
    if (half_) return {"inner", "outer", "x0"};
    return {"inner", "outer", "x0", "y0"};
  }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh, Part()); }
  std::string MeshLayout(const Options &opt) const override
  {
    return Scene::MeshLayout(opt) + (full_   ? " (the full model: four times that around)"
                                     : half_ ? " (the half model: twice that around)"
                                             : "");
  }
  LoadPath Path(const Options &opt) const override
  {
    const double t = path_.travel() / opt.punch_speed; // (the press's duration)
    if (stroke2_ > 0) return {kSecondRelease + 1, t, {kFirstRelease, kSecondPress, kSecondRelease}, path_.Kinks()};
    return {opt_.unload == "none" ? kFirstRelease : kFirstRelease + 1, t, {kFirstRelease}, path_.Kinks()};
  }
  // Stages by the lambda an increment starts at: 0 press, 1 release, 2 press (the second pass), 3 release.
  static int StageAt(double lambda) { return (int)std::floor(lambda + kLambdaTol); }
  bool Unloading(double lambda) const override { return StageAt(lambda) % 2 == 1; }
  // The quarter model carries half the punch load of the full tube (the
  // other half pushes the left quarter), moving by U; the half model carries
  // half of it on each die, closing by 2 U; the full model all of it on each
  // die. The reversed loads of the paper's unloading do no work along the stroke.
  double LoadWorkShare(double lambda) const override
  {
    return Unloading(lambda) && opt_.unload == "reverse" ? 0.0 : full_ ? 2.0 : half_ ? 1.0 : 0.5;
  }
  // Each die's force over its own travel (scenes/common.cpp).
  double ToolWork(const HistoryRow &prev, const HistoryRow &row, double) const override
  {
    return PressToolWork(Part(), opt_.lower_die_motion == "fixed", prev, row);
  }
  // The stroke of the dies in place: the first pass's, then (once its dies are set up) the second's.
  double ToolStroke(double lambda) const override
  {
    if (opt_.die_force > 0) return 0.0; // (the force-controlled die keeps its own stroke; a lower one stays)
    if (pass_ == 1) return std::min(std::max(lambda - kSecondPress, 0.0), 1.0) * stroke2_;
    if (lambda <= 1.0) return path_.Stroke(lambda);
    return opt_.unload == "withdraw" ? stroke_ - (lambda - 1.0) * back_ : path_.Stroke(1.0);
  }

  // Force control: the model's half of the punch load, rising to -die_force over the press; or the side dies'
  // force in the model (-side_force).
  double ToolForce(double lambda) const override
  {
    const double model =
      opt_.side_force > 0 ? opt_.side_force * SideDiesInModel(Part()) : opt_.die_force / LoadPerModelForce();
    return std::min(lambda, kFirstRelease) * model; // (released: not read)
  }

  PetscErrorCode Initialize(Model &m, ContactSpec &tools) override
  {
    PetscFunctionBeginUser;
    PetscCall(CheckPressReach(m.comm, opt_, squaring_, path_.deepest())); // (before any work)
    if (stroke2_ > 0) {
      // The second pass's dies are checked now, before any work (they are set up after the first springback).
      std::vector<Tool> second;
      PetscCall(PassTools(m, 1, second));
    }
    PetscCall(PassTools(m, 0, tools.tools));
    std::vector<SurfacePoint> outer;
    PetscCall(GatherOuter(m, outer));
    path_.Guide(tools.tools[kUpper]); // (-die_path: a path of its own, to move back along before the offset)
    if (!opt_.die_path_turn.empty()) tools.tools[kUpper].origin = DiePivot(opt_);
    if (opt_.die_offset != 0) PetscCall(OffsetDie(m.comm, !m.quiet, outer, opt_.die_offset, tools.tools[kUpper]));
    tools.tools[kUpper].pad = opt_.die_force > 0;
    for (size_t k = SideDie(); opt_.side_force > 0 && k < tools.tools.size(); ++k) tools.tools[k].pad = true;
    tools.candidates = "outer";
    for (int pass = stroke2_ > 0; full_ && pass >= 0; --pass) { // (the second pass's axis checked now)
      PetscCall(MarkAxisPins(m, PassMap(pass).Inverse()));
      if (held_[pass]) PetscCall(hold_.Mark(m, PassMap(pass).Inverse()));
    }
    hold_.PinSlide(held_[0]);
    tools.symmetry = Symmetry();
    // Default VCRI: 2 % of the mean distance between the outer surface's nodes
    // (of the mesh actually used: generated or read from a file).
    double length = 0;
    for (size_t k = 1; k < outer.size(); ++k)
      length += std::hypot(outer[k].x - outer[k - 1].x, outer[k].y - outer[k - 1].y);
    const double spacing =
      outer.size() > 1 ? length / (outer.size() - 1) : opt_.tube_ro * 0.5 * M_PI / opt_.mesh_ntheta;
    tools.params = MakeContactParams(opt_, kVcriOfSpacing * spacing);
    spec_ = tools; // the second pass's set: the same nodes, supports and law
    spec_.tools.clear();
    if (opt_.stroke_corner_radius > 0 && !m.quiet)
      PetscCall(NoteCornerRadius(m.comm, stroke_, opt_.stroke_corner_radius));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode BeginStage(Model &m, double lambda) override
  {
    PetscFunctionBeginUser;
    const bool elastic = ElasticRelease(opt_);
    if (opt_.unload == "withdraw") m.body.BeginRelease(elastic, false);
    if (opt_.unload != "reverse") PetscFunctionReturn(PETSC_SUCCESS);
    if (!Unloading(lambda)) {
      // The second pass: the springback's loads are all applied; its dies from their start, the material's law.
      // (Its dies first: one the scene refuses, inside the tube, ends the run with the first pass's results; the
      // pass's floor and die measures are already its own then, which nothing reads after a stop.)
      std::vector<Tool> drawn;
      PetscCall(PassTools(m, 1, drawn)); // (the floor under the tube as the springback left it: floor_y_)
      std::vector<SurfacePoint> outer;
      PetscCall(GatherOuter(m, outer));
      PetscCall(StartOnTube(m.comm, !m.quiet, outer, drawn, start_back_));
      unloading_ = false;
      // (the pin stays until the second pass's dies hold the half model's tube: Load)
      reversed_total_[0] = reversed_total_[1] = reversed_moment_ = 0;
      m.body.EndRelease();
      pass_ = 1;
      ContactSpec spec = spec_;
      hold_.PinSlide(held_[1]);
      PetscCall(SecondPass(m, spec.tools, spec.symmetry));
      if (pinned_) PetscCall(ChoosePin(m));
      m.contact->Setup(m.mesh, m.system, m.body.position(), spec);
      m.contact->SetStroke(0.0);
      PetscCall(m.contact->Initialize());
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    if (!m.quiet)
      PetscCall(WarnUntouched(m.comm, *m.contact, pass_ == 1 ? "second" : "first", pass_ == 1 ? stroke2_ : stroke_));
    // The paper's unloading: contact forces become loads, tools go (every point elastic by default: ElasticRelease).
    if (!reversed_) PetscCall(VecDuplicate(m.system.reactions_local(), &reversed_));
    PetscCall(VecZeroEntries(reversed_));
    PetscCall(m.contact->AddContactForces(reversed_));
    if (held_[pass_]) PetscCall(hold_.AddForces(m, reversed_)); // (its couple falls with them)
    PetscCall(m.contact->TotalForce(kUpper, reversed_total_, &reversed_moment_));
    m.contact->Remove();
    m.system.ClearFrames();
    m.body.BeginRelease(elastic, true);
    unloading_ = true;
    if (half_) PetscCall(ChoosePin(m));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode BeginIncrement(Model &m, double lambda) override
  {
    PetscFunctionBeginUser;
    if (Holding() && hold_.pins()) PetscCall(hold_.FreeSlide(m, Stroke(m, lambda))); // (scenes/hold.hpp)
    TurnedSupportFrames(m, AxisHeld(), Holding(), pinned_ ? pin_ : -1);
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    PetscFunctionBeginUser;
    if (unloading_) {
      // Reversed contact forces: from F at the release's start to 0 at its end (ReleaseEnd).
      const PetscScalar *f;
      PetscCall(VecGetArrayRead(reversed_, &f));
      for (PetscInt n = 0; n < m.mesh.num_nodes; ++n) {
        const double fx = -dlambda * PetscRealPart(f[m.mesh.node_dof[n]]);
        const double fy = -dlambda * PetscRealPart(f[m.mesh.node_dof[n] + 1]);
        if (fx != 0 || fy != 0) m.system.AddForce(n, fx, fy);
      }
      PetscCall(VecRestoreArrayRead(reversed_, &f));
    }
    if (!full_) PetscCall(QuarterSymmetry(m)); // (a full model's mesh file may carry x0 or y0 sets: not held)
    // (inside the increment: its failure writes the results so far)
    if (opt_.die_force > 0 && m.contact->active())
      PetscCall(CheckForceReach(m.comm, opt_, squaring_, m.contact->tool(kUpper).stroke));
    if (Holding())
      PetscCall(hold_.Constrain(m, AxisHeld())); // (scenes/hold.hpp; released, the pins hold the tube)
    else if (full_)
      PetscCall(HoldAlong(m, "axis", AxisHeld()[0], AxisHeld()[1])); // (the pins: scenes/pins.cpp)
    // The half model without its dies: the reversed loads are in balance (to the method's drift), and one node
    // holds the tube's rigid motion along the press's y.
    if (pinned_ && !unloading_) {
      // The second pass of the half model: the pin holds the tube until its dies do.
      PetscInt touching;
      PetscCall(m.contact->Count(touching));
      pinned_ = touching == 0;
    }
    const Vec2 pin_dir = PassMap(pass_)({0, 1}); // (the press's y)
    if (pinned_ && pin_ >= 0)
      PetscCheck(m.system.PrescribeAlong(pin_, pin_dir[0], pin_dir[1], 0.0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "the springback's pin is not along a node frame axis");
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode ExternalForce(Model &m, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    if (unloading_) PetscCall(VecAXPY(f, ReleaseEnd() - lambda, reversed_));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) override
  {
    double force[2], moment;
    PetscFunctionBeginUser;
    row.stroke = Stroke(m, lambda);
    row.die_x = pass_ == 0 ? path_.Sideways(ToolStroke(lambda)) : 0.0; // (-die_path)
    row.die_turn = pass_ == 0 ? path_.Turn(ToolStroke(lambda)) : 0.0;
    if (unloading_) {
      for (int k = 0; k < 2; ++k) force[k] = (ReleaseEnd() - lambda) * reversed_total_[k];
      moment = (ReleaseEnd() - lambda) * reversed_moment_;
    } else
      PetscCall(m.contact->TotalForce(kUpper, force, &moment));
    // (in the press's frame: a turned pass's die presses along its -y)
    Vec2 f = Press()({force[0], force[1]});
    row.load = -LoadPerModelForce() * f[1]; // (the punch load on the whole tube)
    row.tool_fx = -f[0], row.tool_fy = -f[1], row.tool_moment = -Press().det() * moment;
    // (the side dies' travel: the stroke, through the springbacks too, or their own under -side_force)
    if (side_dies_[0] || side_dies_[1])
      row.side_stroke = opt_.side_force > 0 ? m.contact->tool(SideDie()).stroke : row.stroke;
    if (side_dies_[pass_] && !unloading_) {
      // (the right side die: whole in the half and full models, its upper half in the quarter)
      // (its force along the press's x: a turned pass's side die presses along the press's -x)
      PetscCall(m.contact->TotalForce(SideDie(), force, nullptr));
      row.side_load = -(half_ ? 1.0 : 2.0) * Press()({force[0], force[1]})[0];
    }
    if (half_ && !unloading_) {
      PetscCall(m.contact->TotalForce(kLower, force, &moment));
      f = Press()({force[0], force[1]});
      row.lower_fx = -f[0], row.lower_fy = -f[1], row.lower_moment = -Press().det() * moment;
    }
    hold_.SeeLoad(row.load); // (the warning's floor: the largest load so far)
    if (Holding() && !hold_.pins()) PetscCall(hold_.Measure(m, f_int, Press().det(), opt_.tube_ro, row));
    if (held_[pass_] && unloading_) // (what the springback's pins carry; scenes/hold.hpp)
      PetscCall(hold_.SupportMoment(m, f_int, reversed_, ReleaseEnd() - lambda, pinned_ ? pin_ : -1, row.hold_moment));
    PetscCall(OuterExtents(m, row, Part(), Press()));
    PetscCall(Shape(m, lambda, row));
    row.stage = StageOf(lambda);
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  std::vector<std::pair<std::string, double>> FinalMetrics(const History &h) const override
  {
    std::vector<std::pair<std::string, double>> m = PassMetrics(h);
    const bool forced = opt_.die_force > 0;
    m.push_back({forced ? "final_force_target" : "final_stroke_target", forced ? opt_.die_force : stroke_});
    if (stroke2_ > 0) m.push_back({"pass2_stroke_target", stroke2_});
    return m;
  }

  PetscErrorCode Persist(Model &m, Archive &ar) override
  {
    PetscFunctionBeginUser;
    ar.Group("/scene");
    PetscCall(ar.Value("unloading", unloading_));
    PetscCall(ar.Value("pass", pass_));
    PetscCall(hold_.Persist(ar));
    PetscCall(ar.Value("floor_y", floor_y_));
    PetscCall(ar.Values("pass2_back", start_back_));
    if (ar.reading() && pass_ == 1) {
      // A restart in the second pass: its dies' shapes for the contact set (its state, strokes included, read),
      // a turned tube's pins.
      std::vector<Tool> tools;
      std::vector<std::pair<std::string, Vec2>> symmetry;
      PetscCall(SecondPass(m, tools, symmetry));
      m.contact->ReplaceTools(std::move(tools));
      if (!symmetry.empty()) m.contact->SetSymmetry(symmetry);
    }
    // The springback's total force and moment and the side C is measured on (from the loading).
    std::vector<double> pairs = {reversed_total_[0], reversed_total_[1], (double)side_ends_[0], (double)side_ends_[1],
                                 reversed_moment_};
    PetscCall(ar.Values("reversed_total_side_ends_moment", pairs));
    PetscCheck(pairs.size() == 5, m.comm, PETSC_ERR_USER_INPUT,
               "%s: /scene/reversed_total_side_ends_moment is not 5 numbers", ar.path().c_str());
    reversed_total_[0] = pairs[0], reversed_total_[1] = pairs[1];
    side_ends_[0] = (long)pairs[2], side_ends_[1] = (long)pairs[3];
    reversed_moment_ = pairs[4];
    PetscCall(ar.Value("pinned", pinned_));
    if (pinned_ && ar.reading()) PetscCall(ChoosePin(m));
    if (!unloading_) PetscFunctionReturn(PETSC_SUCCESS);
    // The reversed contact forces: contributions of the owned nodes.
    if (!reversed_) PetscCall(VecDuplicate(m.system.reactions_local(), &reversed_));
    std::vector<double> f(2 * m.mesh.num_nodes);
    PetscScalar *a;
    PetscCall(VecGetArray(reversed_, &a));
    for (PetscInt n = 0; n < m.mesh.num_nodes && !ar.reading(); ++n)
      for (int k = 0; k < 2; ++k) f[2 * n + k] = PetscRealPart(a[m.mesh.node_dof[n] + k]);
    PetscCall(ar.NodeData("reversed", f, 2, true));
    for (PetscInt n = 0; n < m.mesh.num_nodes && ar.reading(); ++n)
      for (int k = 0; k < 2; ++k) a[m.mesh.node_dof[n] + k] = f[2 * n + k];
    PetscCall(VecRestoreArray(reversed_, &a));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  ~PressScene() override { (void)VecDestroy(&reversed_); }

private:
  // VCRI as a fraction of the outer nodes' spacing: a micro-slip far below an
  // element, so that sticking nodes hold (docs/theory.md, "The law").
  static constexpr double kVcriOfSpacing = 0.02;
  // Where the load path's releases begin (lambda): each pass takes one unit of it to press and one to release.
  static constexpr double kFirstRelease = 1.0, kSecondPress = 2.0, kSecondRelease = 3.0;
  // The tools' places in the contact set.
  static constexpr int kUpper = 0, kLower = 1;
  // The right side die's place (-side_die): after the lower die of the half and full models.
  int SideDie() const { return half_ ? kLower + 1 : kLower; }
  Options opt_;
  bool squaring_;
  bool half_;                      // the half model x >= 0 with both dies (or the full model)
  bool full_;                      // the full model: the whole tube, both dies across the y axis
  bool side_dies_[2];              // each pass has side dies (-side_die, -pass2_side_die)
  double stroke2_ = 0;             // the second pass's stroke (0: one pass)
  PetscInt pass_ = 0;              // the pass whose dies are in place
  double floor_y_ = 0;             // where the floor of the pass in place is
  std::vector<double> start_back_; // how far back along its motion each second-pass die starts (StartOnTube)
  ContactSpec spec_;               // the contact set's nodes, supports and law (for the second pass's dies)
  PetscInt pin_ = -1;              // the half model's springback: the local node whose press y is held (-1: none here)
  bool pinned_ = false;            // the pin holds (every rank alike)
  bool held_[2];                   // the full model's pass held by the rotation hold (not its pins) while pressing
  RotationHold hold_;
  double stroke_ = 0, back_ = 0;
  StrokePath path_;           // the first press's (-stroke_path, or straight to the stroke)
  int flank_ = 0, apex_ = -1; // the die's segments the shape metrics use (scenes/die.hpp)
  bool unloading_ = false;
  Vec reversed_ = nullptr;
  double reversed_total_[2] = {0, 0};
  double reversed_moment_ = 0;   // of the reversed forces about the tool frame's origin (TotalForce)
  long side_ends_[2] = {-1, -1}; // input node numbers of the side's ends (latest loading state)

  // The end of the release stage under way (the load path: press 0-1, release 1-2, press 2-3, release 3-4):
  // the reversed loads fall to zero there.
  double ReleaseEnd() const { return pass_ == 1 ? kSecondRelease + 1 : kFirstRelease + 1; }

  // Collective: the dies of a pass; the floor under the tube's lowest point (kept for a restart).
  PetscErrorCode PassTools(Model &m, int pass, std::vector<Tool> &tools)
  {
    PetscFunctionBeginUser;
    PetscCall(LowestOuterY(m, floor_y_, PassMap(pass).Inverse()));
    PetscCall(PassTools(m, pass, floor_y_, tools));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // (the floor's y in the pass's press frame; the dies drawn there, then turned with the tube: PassMap)
  PetscErrorCode PassTools(Model &m, int pass, double floor_y, std::vector<Tool> &tools)
  {
    PetscFunctionBeginUser;
    PetscCall(BuildPassDies(m.comm, opt_, pass, squaring_, half_, full_, floor_y, tools, flank_, apex_));
    for (Tool &t : tools) t = Transform(t, PassMap(pass));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  // The second pass's dies where they start (drawn on floor_y_, moved back by start_back_) and, in the full
  // model, its pins on the press's axis, and the held directions the contact set keeps (`symmetry`): the pass's
  // start (BeginStage) and a restart inside it (Persist) alike.
  PetscErrorCode SecondPass(Model &m, std::vector<Tool> &tools, std::vector<std::pair<std::string, Vec2>> &symmetry)
  {
    PetscFunctionBeginUser;
    PetscCall(PassTools(m, 1, floor_y_, tools));
    for (size_t k = 0; k < tools.size() && k < start_back_.size(); ++k) tools[k] = MovedBack(tools[k], start_back_[k]);
    if (full_) PetscCall(MarkAxisPins(m, Press()));
    if (held_[1]) PetscCall(hold_.Mark(m, Press())); // (the rotation hold's nodes: scenes/hold.hpp)
    symmetry = Symmetry();
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  TurnMap PassMap(int pass) const { return PassTurn(opt_, pass, half_, full_); }
  // The history's U at lambda: the force-controlled die's own, the second pass's after the first's, -die_path's.
  double Stroke(Model &m, double lambda) const
  {
    const double s = ToolStroke(lambda);
    return opt_.die_force > 0 ? m.contact->tool(kUpper).stroke : pass_ == 1 ? stroke_ + s : path_.U(s);
  }
  // The rotation hold holds the pass in place (its nodes fixed, holding the slide too, until the dies hold it).
  bool Holding() const { return held_[pass_] && !unloading_; }
  // The tube's coordinates into the frame of the press in place (its die moving along -y).
  TurnMap Press() const { return PassMap(pass_).Inverse(); }
  // The full model's pins hold the tube along the press's x.
  Vec2 AxisHeld() const { return PassMap(pass_)({1, 0}); }
  // The nodes whose direction the contact set keeps: the quarter's and the half's symmetry planes (the half tube
  // between both dies is mirrored about the y axis only), the full model's pins (the rotation hold's: inner nodes).
  std::vector<std::pair<std::string, Vec2>> Symmetry() const
  {
    if (full_ && held_[pass_]) return {};
    if (full_) return {{"axis", AxisHeld()}};
    if (half_) return {{"x0", {1, 0}}};
    return {{"x0", {1, 0}}, {"y0", {0, 1}}};
  }

  // The half and full models' springback: one node holds the tube's rigid motion along the press's y
  // (scenes/pins.cpp).
  PetscErrorCode ChoosePin(Model &m)
  {
    PetscFunctionBeginUser;
    PetscCall(ChooseSpringbackPin(m, pin_, Press()));
    pinned_ = true;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // The punch load per vertical force of the model on the upper die: the quarter and the half model carry half.
  double LoadPerModelForce() const { return full_ ? 1.0 : 2.0; }
  TubePart Part() const { return full_ ? TubePart::Full : half_ ? TubePart::Half : TubePart::Quarter; }

  PetscErrorCode Shape(Model &m, double, HistoryRow &row)
  {
    const PressShapeState state{squaring_, half_, unloading_, pass_ == 1, flank_, apex_, opt_.tube_t, Press()};
    return PressShape(m, state, side_ends_, row);
  }
};

} // namespace

std::unique_ptr<Scene> MakeSquaringScene(const Options &opt) { return std::make_unique<PressScene>(opt, true); }
std::unique_ptr<Scene> MakeFlatteningScene(const Options &opt) { return std::make_unique<PressScene>(opt, false); }

} // namespace tf
