// What the press scene measures (include/tubeform/scenes/press_scene.hpp): its history row, its final metrics,
// its state for a checkpoint.
#include "tubeform/scenes/press_scene.hpp"

#include <initializer_list>

#include "tubeform/scenes/press_shape.hpp"

namespace tf {

double PressScene::ToolWork(const HistoryRow &prev, const HistoryRow &row, double) const
{
  HistoryRow from = prev; // (a later pass's dies from where they start, its upper die at its path's start)
  const ToolColumns &path = DiePathColumns();
  if (pass_ > 0 && row.stage == PressStage(pass_) && prev.stage < row.stage)
    from.stroke = -UpperBack(), path(from, kDieX) = path(from, kDieTurn) = 0.0;
  // (the lower die's rise by its motion: by U where it mirrors the upper one's, LowerDieMotion; a motion of its own
  // at the pass's tool stroke, U plus how far back the upper die started: UpperBack)
  const MotionHandle &lower = passes_[pass_].lower_motion;
  const double at = LowerDieMoves(opt_, (int)pass_, LowerDieMove::Own) ? UpperBack() : 0.0;
  const DieTravel travel{UpperTravel(opt_, (int)pass_), !LowerDieMoves(opt_, (int)pass_, LowerDieMove::Fixed),
                         lower->Offset(row.stroke + at)[1] - lower->Offset(from.stroke + at)[1]};
  return PressToolWork(part_, travel, from, row);
}

double PressScene::SideStroke(Model &m, double lambda) const
{
  const Pass &p = passes_[pass_];
  if (p.dies.SideForce() > 0) return p.side_from + m.contact->tool(SideDie()).stroke; // (their own)
  if (DieMoves(p.dies.side_motion, kStrokeMotion))
    return pass_ > 0 ? p.side_from + ToolStroke(lambda) : Stroke(m, lambda);
  // (fixed, a path, pulses: how far their motion has taken them in at the pass's stroke)
  return p.side_from + m.contact->tool(SideDie()).motion->Travel(ToolStroke(lambda));
}

PetscErrorCode PressScene::Measure(Model &m, double lambda, Vec f_int, HistoryRow &row)
{
  double force[2], moment;
  PetscFunctionBeginUser;
  row.stroke = Stroke(m, lambda);
  const ToolColumns &upper = UpperDieColumns(), &path = DiePathColumns(), &side = SideDieColumns();
  path(row, kDieX) = passes_[pass_].path.Sideways(ToolStroke(lambda)); // (-die_path; 0 without)
  path(row, kDieTurn) = passes_[pass_].path.Turn(ToolStroke(lambda));
  if (unloading_) {
    for (int k = 0; k < 2; ++k) force[k] = (ReleaseEnd() - lambda) * reversed_.total[k];
    moment = (ReleaseEnd() - lambda) * reversed_.moment;
  } else
    PetscCall(m.contact->TotalForce(kUpper, force, &moment));
  // (in the press's frame: a turned pass's die presses along its -y)
  Vec2 f = Press()({force[0], force[1]});
  row.load = -LoadPerModelForce() * f[1]; // (the punch load on the whole tube)
  upper(row, kDieFx) = -f[0], upper(row, kDieFy) = -f[1], upper(row, kDieMoment) = -Press().det() * moment;
  // (the side dies' travel: the stroke, through the springbacks too, or their own under -side_force)
  bool side_dies = false;
  for (const Pass &p : passes_) side_dies = side_dies || p.side_dies;
  if (side_dies) side(row, kSideStroke) = SideStroke(m, lambda);
  if (passes_[pass_].side_dies && !unloading_) {
    // (the right side die: whole in the half and full models, its upper half in the quarter)
    // (its force along the press's x: a turned pass's side die presses along the press's -x)
    PetscCall(m.contact->TotalForce(SideDie(), force, nullptr));
    double load = -Press()({force[0], force[1]})[0];
    if (WholeTube(part_)) { // (and the left one, along +x: their mean, which their common travel works over)
      PetscCall(m.contact->TotalForce(SideDie() + 1, force, nullptr));
      load = 0.5 * (load + Press()({force[0], force[1]})[0]);
    }
    side(row, kSideLoad) = (BothDies(part_) ? 1.0 : 2.0) * load;
  }
  if (BothDies(part_) && !unloading_) {
    PetscCall(m.contact->TotalForce(kLower, force, &moment));
    f = Press()({force[0], force[1]});
    const ToolColumns &lower = LowerDieColumns();
    lower(row, kDieFx) = -f[0], lower(row, kDieFy) = -f[1], lower(row, kDieMoment) = -Press().det() * moment;
  }
  hold_.SeeLoad(row.load); // (the warning's floor: the largest load so far)
  if (Holding() && !hold_.pins()) PetscCall(hold_.Measure(m, f_int, Press().det(), opt_.tube_ro, row));
  if (passes_[pass_].held && unloading_) // (what the springback's pins carry; scenes/hold.hpp)
    PetscCall(hold_.SupportMoment(m, f_int, reversed_.forces, ReleaseEnd() - lambda, pin_.node(),
                                  RotationHold::Columns()(row, RotationHold::kMoment)));
  PetscCall(OuterExtents(m, row, part_, Press()));
  PetscCall(Shape(m, lambda, row));
  row.stage = StageOf(lambda);
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::vector<std::pair<std::string, double>> PressScene::FinalMetrics(const History &h) const
{
  std::vector<std::pair<std::string, double>> m = PassMetrics(h);
  for (size_t k = 0; k < passes_.size(); ++k) { // (what ends each pass: its stroke or its force)
    const PassExtent &e = passes_[k].extent;
    m.push_back({k == 0 ? Formatted("final_%s_target", e.TargetWord())
                        : Formatted("pass%d_%s_target", (int)k + 1, e.TargetWord()),
                 e.Target()});
  }
  for (int k = 1; k <= pass_; ++k) // (where the upper die of each pass set up started)
    m.push_back({Formatted("pass%d_start_stroke", k + 1), passes_[k].start});
  return m;
}

PetscErrorCode PressScene::Persist(Model &m, Archive &ar)
{
  PetscFunctionBeginUser;
  ar.Group("/scene");
  PetscCall(ar.Value("unloading", unloading_));
  PetscCall(ar.Value("pass", pass_));
  PetscCheck(pass_ >= 0 && pass_ < (PetscInt)passes_.size(), m.comm, PETSC_ERR_USER_INPUT,
             "%s: the checkpoint is in pass %d; the options give %d pass(es)", ar.path().c_str(), (int)pass_ + 1,
             (int)passes_.size());
  PetscCall(ar.Value("floor_y", floor_y_));
  PetscCall(ar.Values("pass2_back", passes_[pass_].start_back)); // (the pass in place's; the name of two passes)
  if (pass_ >= 1) {
    // (in a later pass: the side dies' travel where the pass in place began, where each later pass before it had its
    // upper die start)
    std::vector<double> from = {passes_[pass_].side_from};
    for (int k = 1; k < pass_; ++k) from.push_back(passes_[k].start);
    PetscCall(ar.Values("side_from_pass_starts", from));
    PetscCheck(from.size() == (size_t)pass_, m.comm, PETSC_ERR_USER_INPUT,
               "%s: /scene/side_from_pass_starts is not %d numbers", ar.path().c_str(), (int)pass_);
    passes_[pass_].side_from = from[0];
    for (int k = 1; k < pass_; ++k) passes_[k].start = from[k];
  }
  if (ar.reading() && pass_ > 0) {
    // A restart in a later pass: its dies' shapes for the contact set (its state, strokes included, read),
    // a turned tube's pins.
    std::vector<Tool> tools;
    std::vector<std::pair<std::string, Vec2>> symmetry;
    PetscCall(PassDies(m, tools, symmetry));
    m.contact->ReplaceTools(std::move(tools));
    if (!symmetry.empty()) m.contact->SetSymmetry(symmetry);
  }
  // The springback's total force and moment and the side C is measured on (from the loading).
  std::vector<double> pairs = {reversed_.total[0], reversed_.total[1], (double)side_ends_[0], (double)side_ends_[1],
                               reversed_.moment};
  PetscCall(ar.Values("reversed_total_side_ends_moment", pairs));
  PetscCheck(pairs.size() == 5, m.comm, PETSC_ERR_USER_INPUT,
             "%s: /scene/reversed_total_side_ends_moment is not 5 numbers", ar.path().c_str());
  reversed_.total[0] = pairs[0], reversed_.total[1] = pairs[1];
  side_ends_[0] = (long)pairs[2], side_ends_[1] = (long)pairs[3];
  reversed_.moment = pairs[4];
  for (Support *s : std::initializer_list<Support *>{&pins_, &hold_, &pin_})
    PetscCall(s->Persist(m, ar, Press())); // (scenes/support.hpp)
  if (!unloading_) PetscFunctionReturn(PETSC_SUCCESS);
  // The reversed contact forces: contributions of the owned nodes.
  if (!reversed_.forces) PetscCall(VecDuplicate(m.system.reactions_local(), &reversed_.forces));
  std::vector<double> f(2 * m.mesh.num_nodes);
  PetscScalar *a;
  PetscCall(VecGetArray(reversed_.forces, &a));
  for (PetscInt n = 0; n < m.mesh.num_nodes && !ar.reading(); ++n)
    for (int k = 0; k < 2; ++k) f[2 * n + k] = PetscRealPart(a[m.mesh.node_dof[n] + k]);
  PetscCall(ar.NodeData("reversed", f, 2, true));
  for (PetscInt n = 0; n < m.mesh.num_nodes && ar.reading(); ++n)
    for (int k = 0; k < 2; ++k) a[m.mesh.node_dof[n] + k] = f[2 * n + k];
  PetscCall(VecRestoreArray(reversed_.forces, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode PressScene::Shape(Model &m, double lambda, HistoryRow &row)
{
  const bool release = (int)StageOf(lambda) % 2 == 1; // (whatever releases the tube: reversed loads, a withdrawal)
  const PressShapeState state{squaring_, BothDies(part_), release, pass_ > 0, flank_, apex_, opt_.tube_t, Press()};
  return PressShape(m, state, side_ends_, row);
}

} // namespace tf
