// The model the tool scenes' options choose (ModelOf, include/tubeform/scenes/tool_scene.hpp): the quarter where the
// passes' tools keep its mirror symmetries, else the half or the full, and how the full one is held. The options'
// checks (scenes/tool_options.hpp) and the scenes' set-up read it alike.
#include "tubeform/scenes/tool_scene.hpp"

namespace tf {

bool ModelChoice::Mirrored() const
{
  bool mirrored = true;
  for (const PassSymmetry &p : passes) mirrored = mirrored && p.mirrored;
  return mirrored;
}

bool ModelChoice::QuarterExact() const
{
  bool exact = Mirrored();
  for (const PassSymmetry &p : passes) exact = exact && !p.off_axis && p.quarter_turn;
  return exact;
}

bool ModelChoice::HalfExact() const
{
  bool exact = true;
  for (const PassSymmetry &p : passes) exact = exact && !p.off_axis && p.quarter_turn && p.quarters % 2 == 0;
  return exact;
}

bool ModelChoice::OffSymmetry(int pass) const
{
  const PassSymmetry &p = passes[pass];
  bool off = p.off_axis || !p.quarter_turn;
  for (int before = 0; before < pass; ++before)
    off = off || ((p.quarters - passes[before].quarters) % 2 != 0 && !passes[before].mirrored);
  return off;
}

bool ModelChoice::SidesAlike(int pass) const
{
  bool half_turn = !passes[pass].off_axis;
  for (int k = 0; k <= pass; ++k) half_turn = half_turn && passes[k].mirrored;
  return !OffSymmetry(pass) || half_turn;
}

bool ModelChoice::HeldByRotation(int pass) const
{
  return part == TubeModel::Full && (hold == FullHold::Rotation || (hold == FullHold::Auto && OffSymmetry(pass)));
}

ModelChoice ModelOf(const Options &opt)
{
  ModelChoice model;
  model.passes.resize(kMaxPasses);
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    PassSymmetry &p = model.passes[pass];
    p.mirrored = DiesOfPass(opt, pass).lower.Is(DieFrom::Mirror) && LowerDieMoves(opt, pass, LowerDieMove::Mirror);
    p.off_axis = OffAxisBy(opt, pass);
    p.quarters = PassQuarters(opt, pass), p.quarter_turn = QuarterTurn(opt, pass);
  }
  model.part = ToolsOf(opt).model.part, model.hold = ToolsOf(opt).model.full_hold;
  if (model.part == TubeModel::Auto)
    model.part = model.QuarterExact() ? TubeModel::Quarter : model.HalfExact() ? TubeModel::Half : TubeModel::Full;
  return model;
}

} // namespace tf
