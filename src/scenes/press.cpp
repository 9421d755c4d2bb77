// The tool scenes (docs/scenes.md): `squaring` (quarter tube, upper
// V-die) and `flattening` (quarter ring, flat plate), with unloading.
// With a lower die that does not mirror the upper one (-lower_die,
// -lower_die_motion) or -model half, the half tube x >= 0 between both dies;
// -model full: the whole tube, both dies across the y axis.
//
// Load path: lambda in [0, 1] presses the tool to the final stroke; with
// -unload reverse or withdraw, lambda in [1, 2] unloads:
//   reverse  (the paper): the contact forces at the end of loading applied
//            reversed as nodal loads, tools removed;
//   withdraw: the tool moves back and releases the nodes one by one (r5);
// either with every point elastic (the paper's) or by the material's law:
// -springback, ElasticRelease.
// With -pass2_stroke, a second pass after the paper's unloading: lambda in [2, 3] presses its dies from their
// start, [3, 4] springs back; a third (-pass3_stroke) presses over [4, 5], and so on (pass k over [2k, 2k + 1]);
// -pass2_turn turns the tube before it (its dies drawn turned the other way, its
// metrics and forces in its press's frame: die.hpp, PassTurn). -die_motion force presses by a force (the stroke
// its outcome), -side_die adds dies at the sides, -die_offset and -die_motion path move the die off the axis (the full
// model under the rotation hold, hold.hpp); docs/dies.md, docs/motions.md and docs/passes.md.
// History: stroke = tool stroke U (mm; half the dies' closing; in a later
// pass its upper die's position from the same zero: the die touching the round
// tube; -pass2_stroke, -pass3_stroke, ... is where it ends), load = punch load on the
// full tube (N/mm), the upper die's vertical force on the model: twice it in
// the quarter and the half model, which carry half of it.
#include "tubeform/scenes/press_scene.hpp"

#include <algorithm>

#include "tubeform/scenes/contact_params.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

PressScene::PressScene(const Options &opt, bool squaring)
    : opt_(opt), squaring_(squaring), part_(FullModel(opt)      ? TubePart::Full
                                            : QuarterModel(opt) ? TubePart::Quarter
                                                                : TubePart::Half)
{
  const double corner_radius = FirstPass(opt).corner_radius;
  stroke_ = corner_radius > 0 ? StrokeForCornerRadius(opt.tube_ro, corner_radius, FirstDies(opt).upper.spec.angle)
                              : opt.stroke.u;
  back_ = stroke_; // withdraw: back to the start, so every node has left the tool (by r5)
  passes_.resize(PassCount(opt));
  const ModelChoice model = ModelOf(opt); // (each pass's hold; part_ reads the same choice)
  passes_[0].path =
    FirstDies(opt).motion.OwnPath() ? StrokePath(DiePath(opt)) : StrokePath(StrokePathOf(opt, 0), stroke_);
  for (int k = 0; k < (int)passes_.size(); ++k) {
    Pass &p = passes_[k];
    p.extent = ExtentOf(ToolsOf(opt).passes[k], k, k == 0 ? stroke_ : LaterPass(opt, k).stroke);
    p.turn = PassTurn(opt, k, part_);
    p.dies = DiesOfPass(opt, k), p.reach = DieReach(opt, k, p.dies, squaring), p.release = ReleaseOfPass(opt, k);
    p.held = model.HeldByRotation(k), p.side_dies = !p.dies.side.Is(DieFrom::None);
    p.lower_motion = LowerDieMotion(opt, k);
    if (k > 0 && p.dies.motion.OwnPath()) { // (its own path: -pass<N>_die_path)
      const ToolPath own = MotionPathOf(p.dies.motion.kind, p.dies.motion.spec);
      p.path = StrokePath(own), p.rise = -0.5 * own.Motion(0)[1];
    }
  }
}

LoadPath PressScene::Path(const Options &opt) const
{
  const StrokePath &path = passes_[0].path;
  const double t = path.travel() / opt.driver.punch_speed;                 // (the press's duration)
  std::vector<double> kinks = path.Kinks(PressKinks(opt_, path.travel())); // (where the dies' motions turn)
  // (the last pass released, or not: -unload none, -pass<N>_unload none)
  const size_t end = 2 * passes_.size() - (passes_.back().release == Unload::None ? 1 : 0);
  if (passes_.size() == 1) return {(double)end, t, {kFirstRelease}, kinks};
  std::vector<double> stages; // (where each stage after the first begins)
  for (size_t k = 1; k < end; ++k) stages.push_back((double)k);
  for (size_t k = 1; k < passes_.size(); ++k) { // (a later pass's upper die on its own path: its points)
    const StrokePath &own = passes_[k].path;
    for (double f : own.Kinks(UpperKinks(passes_[k].dies.motion, own.travel()))) kinks.push_back(PressStage(k) + f);
    if ((PetscInt)k > pass_) continue; // (its lower and side dies' own motions: once its travel is known, StartPass)
    for (double f : own.Kinks(ToolKinks(opt_, (int)k, own.travel()))) kinks.push_back(PressStage(k) + f);
  }
  return {(double)end, t, stages, kinks};
}

double PressScene::ToolStroke(double lambda) const
{
  if (passes_[pass_].extent.Forced()) return 0.0; // (the force-controlled die keeps its own stroke; a lower one stays)
  const StrokePath &path = passes_[pass_].path;
  const double released = lambda - PressStage((int)pass_) - 1.0; // (> 0: in its release, up to its end)
  const bool withdraw = passes_[pass_].release == Unload::Withdraw && released > 0;
  if (pass_ > 0) { // (withdrawn: back along its way to where its dies started)
    const double end = path.Stroke(1.0);
    return withdraw ? end - released * end : path.Stroke(PassExtent::Ramp(lambda, PressStage(pass_)));
  }
  if (lambda <= 1.0) return path.Stroke(lambda);
  return withdraw ? stroke_ - (lambda - 1.0) * back_ : path.Stroke(1.0);
}

double PressScene::ToolForce(double lambda) const
{
  const Pass &p = passes_[pass_];
  const double model =
    p.dies.SideForce() > 0 ? p.dies.SideForce() * SideDiesInModel(part_) : p.extent.force / LoadPerModelForce();
  return PassExtent::Ramp(lambda, PressStage(pass_)) * model; // (released: not read)
}

PetscErrorCode PressScene::Initialize(Model &m, ContactSpec &tools)
{
  PetscFunctionBeginUser;
  PetscCall(CheckPressReach(m.comm, opt_, squaring_, passes_[0].path.deepest())); // (before any work)
  for (int k = (int)passes_.size() - 1; k > 0; --k) {
    // A later pass's dies are checked now, before any work (they are set up after the springback before it).
    std::vector<Tool> later;
    PetscCall(PassTools(m, k, later));
  }
  PetscCall(PassTools(m, 0, tools.tools));
  std::vector<SurfacePoint> outer;
  PetscCall(GatherOuter(m, outer));
  tools.candidates = "outer";
  for (int pass = (int)passes_.size() - 1; WholeTube(part_) && pass >= 0;
       --pass) { // (the later passes' axes checked now)
    PetscCall(pins_.Mark(m, PassMap(pass).Inverse()));
    if (passes_[pass].held) PetscCall(hold_.Mark(m, PassMap(pass).Inverse()));
  }
  hold_.PinSlide(passes_[0].held);
  tools.symmetry = Symmetry();
  // The wall meets its mirror image on the quarter's and the half model's symmetry planes: frictionless walls.
  tools.surfaces = {"outer", "inner"};
  if (!WholeTube(part_))
    for (const auto &s : tools.symmetry) tools.walls.push_back(s.first);
  // Default VCRI: 2 % of the mean distance between the outer surface's nodes
  // (of the mesh actually used: generated or read from a file).
  double length = 0;
  for (size_t k = 1; k < outer.size(); ++k)
    length += std::hypot(outer[k].x - outer[k - 1].x, outer[k].y - outer[k - 1].y);
  const double spacing = outer.size() > 1 ? length / (outer.size() - 1) : opt_.tube_ro * 0.5 * M_PI / opt_.mesh_ntheta;
  tools.params = MakeContactParams(opt_, kVcriOfSpacing * spacing);
  spec_ = tools; // a later pass's set: the same nodes, supports and law
  spec_.tools.clear();
  if (FirstPass(opt_).corner_radius > 0 && !m.quiet)
    PetscCall(NoteCornerRadius(m.comm, stroke_, FirstPass(opt_).corner_radius));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::BeginStage(Model &m, double lambda)
{
  PetscFunctionBeginUser;
  if (!Unloading(lambda)) { // (the next pass)
    PetscCall(StartPass(m));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const Unload release = passes_[pass_].release; // (none: the run ends before its release, Path)
  const bool elastic = ElasticRelease(opt_, release);
  if (release == Unload::Withdraw) { // (the dies go back along their way: ToolStroke; the nodes leave them by r5)
    m.body.BeginRelease(elastic, false);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!m.quiet) PetscCall(WarnUntouched(m.comm, *m.contact, pass_, passes_[pass_].extent.stroke));
  // The paper's unloading: contact forces become loads, tools go (every point elastic by default: ElasticRelease).
  if (!reversed_.forces) PetscCall(VecDuplicate(m.system.reactions_local(), &reversed_.forces));
  PetscCall(VecZeroEntries(reversed_.forces));
  PetscCall(
    m.contact->AddContactForces(reversed_.forces, true)); // (a symmetry wall's force stays: it is the tube's own)
  if (passes_[pass_].held) PetscCall(hold_.AddForces(m, reversed_.forces)); // (its couple falls with them)
  PetscCall(m.contact->TotalForce(kUpper, reversed_.total, &reversed_.moment));
  PetscCall(m.contact->Remove());
  m.system.ClearFrames();
  m.body.BeginRelease(elastic, true);
  unloading_ = true;
  if (BothDies(part_)) PetscCall(pin_.Mark(m, Press()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::StartPass(Model &m)
{
  const int next = (int)pass_ + 1;
  PetscFunctionBeginUser;
  // The next pass: the springback's loads are all applied; its dies from their start, the material's law.
  // (Its dies first: one the scene refuses, inside the tube, ends the run with the results so far; the pass's
  // floor and die measures are already its own then, which nothing reads after a stop.)
  std::vector<Tool> drawn;
  PetscCall(PassTools(m, next, drawn)); // (the floor under the tube as the springback left it: floor_y_)
  std::vector<SurfacePoint> outer;
  PetscCall(GatherOuter(m, outer));
  PetscCall(StartOnTube(m.comm, !m.quiet, outer, drawn, passes_[next].start_back, (int)pass_));
  // (the side dies' travel goes on from where the pass before left it, as its last row reported it: SideStroke; the
  // contact set keeps the pass's tools until its next are set up; kept for a restart: Persist)
  if (passes_[pass_].release == Unload::Withdraw) PetscCall(CheckWithdrawn(m, next));
  passes_[next].side_from = SideStroke(m, ReleaseEnd());
  unloading_ = false;
  // (the pin stays until the next pass's dies hold the half model's tube: Load)
  reversed_.total[0] = reversed_.total[1] = reversed_.moment = 0;
  m.body.EndRelease();
  pass_ = next;
  ContactSpec spec = spec_;
  hold_.PinSlide(passes_[pass_].held);
  PetscCall(PassDies(m, spec.tools, spec.symmetry));
  if (!m.quiet && OwnPath())
    PetscCall(PetscPrintf(m.comm, "tubeform: %s pass: the upper die along its path (%s) from U = %s to %s mm\n",
                          PassOrdinal(next).c_str(), PassOptionName(next, "die_path").c_str(),
                          Formatted("%.4g", PassStart()).c_str(), Formatted("%.4g", PassEnd()).c_str()));
  else if (!m.quiet && passes_[pass_].extent.Forced())
    PetscCall(PetscPrintf(m.comm, "tubeform: %s pass: the upper die presses with up to %s N/mm (%s) from U = %s mm\n",
                          PassOrdinal(next).c_str(), Formatted("%g", passes_[pass_].extent.force).c_str(),
                          passes_[pass_].extent.Option().c_str(), Formatted("%.4g", PassStart()).c_str()));
  else if (!m.quiet && !StrokePathOf(opt_, next).empty()) {
    std::string strokes;
    for (double u : StrokePathOf(opt_, next)) strokes += (strokes.empty() ? "" : ", ") + Formatted("%g", u);
    PetscCall(PetscPrintf(m.comm, "tubeform: %s pass: the upper die from U = %s to %s mm in turn (%s)\n",
                          PassOrdinal(next).c_str(), Formatted("%.4g", PassStart()).c_str(), strokes.c_str(),
                          PassOptionName(next, "stroke_path").c_str()));
  } else if (!m.quiet)
    PetscCall(PetscPrintf(m.comm,
                          "tubeform: %s pass: the dies travel %s mm together until the one furthest along is "
                          "at U = %s mm (%s); the upper die from U = %s to %s mm\n",
                          PassOrdinal(next).c_str(),
                          Formatted("%.4g", passes_[pass_].extent.stroke + StartBack()).c_str(),
                          Formatted("%g", passes_[pass_].extent.stroke).c_str(), PassOptionName(next, "stroke").c_str(),
                          Formatted("%.4g", PassStart()).c_str(), Formatted("%.4g", PassEnd()).c_str()));
  const Pass &p = passes_[pass_]; // (side dies by the stroke where the first pass's move otherwise: say so)
  if (!m.quiet && p.side_dies && DieMoves(p.dies.side_motion, kStrokeMotion) &&
      !DieMoves(FirstDies(opt_).side_motion, kStrokeMotion))
    PetscCall(PetscPrintf(m.comm,
                          "tubeform: %s pass: its side dies move by the stroke (%s for another; the first pass's "
                          "-side_motion is its own)\n",
                          PassOrdinal(next).c_str(), PassOptionName(next, "side_motion").c_str()));
  if (pin_.holds()) PetscCall(pin_.Mark(m, Press()));
  PetscCall(m.contact->Setup(m.mesh, m.system, m.body.position(), spec));
  m.contact->SetStroke(0.0);
  PetscCall(m.contact->Initialize());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::CheckWithdrawn(Model &m, int next) const
{
  double force[2];
  PetscFunctionBeginUser;
  PetscCall(m.contact->TotalForce(kUpper, force, nullptr));
  const double load = LoadPerModelForce() * std::hypot(force[0], force[1]);
  PetscCheck(load <= kWithdrawnLoad * hold_.largest_load(), m.comm, PETSC_ERR_USER_INPUT,
             "%s %s: the %s pass's dies, withdrawn to where they started, still press the tube with %g N/mm (it "
             "reaches past their start); let it go by %s reverse",
             ReleaseOption(opt_, next - 1).c_str(), WordOf(kUnloadWords, Unload::Withdraw),
             PassOrdinal(next - 1).c_str(), load, ReleaseOption(opt_, next - 1).c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::BeginIncrement(Model &m, double lambda)
{
  PetscFunctionBeginUser;
  const SupportStep step = Step(m, lambda);
  for (Support *s : Supports()) { // (scenes/support.hpp)
    PetscCall(s->Settle(m, step));
    s->TakeFrames(m, step.to_tube);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::Load(Model &m, double lambda, double dlambda)
{
  PetscFunctionBeginUser;
  if (unloading_) {
    // Reversed contact forces: from F at the release's start to 0 at its end (ReleaseEnd).
    const PetscScalar *f;
    PetscCall(VecGetArrayRead(reversed_.forces, &f));
    for (PetscInt n = 0; n < m.mesh.num_nodes; ++n) {
      const double fx = -dlambda * PetscRealPart(f[m.mesh.node_dof[n]]);
      const double fy = -dlambda * PetscRealPart(f[m.mesh.node_dof[n] + 1]);
      if (fx != 0 || fy != 0) m.system.AddForce(n, fx, fy);
    }
    PetscCall(VecRestoreArrayRead(reversed_.forces, &f));
  }
  if (!WholeTube(part_)) PetscCall(QuarterSymmetry(m)); // (a full model's mesh file may carry x0 or y0 sets: not held)
  // (inside the increment: its failure writes the results so far)
  const Pass &p = passes_[pass_];
  if (p.extent.Forced() && m.contact->active())
    PetscCall(CheckForceReach(m.comm, p.extent, p.reach, squaring_, Stroke(m, lambda)));
  // The full model's axis held by the rotation hold or the pins; the half model without its dies: the reversed
  // loads are in balance (to the method's drift), and one node holds the tube's rigid motion along the press's y, in
  // a later pass until its dies hold the tube (scenes/support.hpp).
  const SupportStep step = Step(m, lambda);
  for (Support *s : Supports()) PetscCall(s->Constrain(m, step));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::ExternalForce(Model &m, double lambda, Vec f)
{
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(f));
  if (unloading_) PetscCall(VecAXPY(f, ReleaseEnd() - lambda, reversed_.forces));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::PassTools(Model &m, int pass, std::vector<Tool> &tools)
{
  PetscFunctionBeginUser;
  PetscCall(LowestOuterY(m, floor_y_, PassMap(pass).Inverse()));
  PetscCall(PassTools(m, pass, floor_y_, tools));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::PassTools(Model &m, int pass, double floor_y, std::vector<Tool> &tools)
{
  PetscFunctionBeginUser;
  PetscCall(BuildPassDies(m.comm, opt_, pass, squaring_, part_, floor_y, tools, flank_, apex_));
  for (Tool &t : tools) t = Transform(t, PassMap(pass));
  PetscCall(
    SetSideMotions(m.comm, opt_, pass, SideDie(), tools)); // (-side_motion, -pass<N>_side_motion: die_motion.cpp)
  // Its upper die off the axis (-die_offset, -pass<N>_die_offset): its zero, as every pass's, where it touches the
  // round tube (the first pass's printed; a later pass's start from there: StartOnTube).
  const double offset = DiesOfPass(opt_, pass).offset;
  if (offset == 0) PetscFunctionReturn(PETSC_SUCCESS);
  std::vector<SurfacePoint> round;
  PetscCall(GatherRoundOuter(m, round));
  PetscCall(StartOffAxis(m.comm, pass == 0 && !m.quiet, round, offset, tools[kUpper]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::PassDies(Model &m, std::vector<Tool> &tools,
                                    std::vector<std::pair<std::string, Vec2>> &symmetry)
{
  Pass &p = passes_[pass_];
  PetscFunctionBeginUser;
  PetscCall(PassTools(m, pass_, floor_y_, tools));
  p.back = kNever;
  for (size_t k = 0; k < tools.size() && k < p.start_back.size(); ++k) {
    tools[k] = MovedBack(tools[k], p.start_back[k]);
    // (the dies that travel by the pass's stroke together are those on a stroke motion: not a force's, one that
    // stays, a lower or side die on a motion of its own, nor an upper die on its own path, whose pass is its path)
    if (tools[k].motion->Kind() == kStrokeMotion) p.back = std::min(p.back, p.start_back[k]);
  }
  if (p.back == kNever) p.back = 0; // (no die moves by the stroke)
  // By its stroke: straight from where its dies start (on a path of its own: its path; under force: the die's stroke).
  if (!p.dies.motion.OwnPath() && !p.extent.Forced()) { // (its strokes in turn, where it has them, from there too)
    std::vector<double> strokes = StrokePathOf(opt_, (int)pass_);
    for (double &s : strokes) s += p.back;
    p.path = StrokePath(strokes, p.extent.stroke + p.back);
  }
  p.start = PassStart();
  if (WholeTube(part_)) PetscCall(pins_.Mark(m, Press()));
  if (p.held) PetscCall(hold_.Mark(m, Press())); // (the rotation hold's nodes: scenes/hold.hpp)
  symmetry = Symmetry();
  PetscFunctionReturn(PETSC_SUCCESS);
}

double PressScene::Stroke(Model &m, double lambda) const
{
  const Pass &p = passes_[pass_];
  return p.extent.U(m.contact->tool(kUpper).stroke, p.path.U(ToolStroke(lambda)), UpperBack());
}

std::vector<std::pair<std::string, Vec2>> PressScene::Symmetry() const
{
  if (WholeTube(part_) && passes_[pass_].held) return {};
  if (WholeTube(part_)) return {{"axis", AxisHeld()}};
  if (BothDies(part_)) return {{"x0", {1, 0}}};
  return {{"x0", {1, 0}}, {"y0", {0, 1}}};
}

std::unique_ptr<Scene> MakeSquaringScene(const Options &opt) { return std::make_unique<PressScene>(opt, true); }
std::unique_ptr<Scene> MakeFlatteningScene(const Options &opt) { return std::make_unique<PressScene>(opt, false); }

} // namespace tf
