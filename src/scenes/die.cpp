#include "tubeform/scenes/die.hpp"

#include <algorithm>
#include <cmath>

#include "tubeform/contact/contact.hpp"
#include "tubeform/core/text_file.hpp"
#include "tubeform/tool/profile.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

namespace {

// How far back (negative: ahead) along its motion a force-controlled die clear of the tube's outer points starts
// where it first touches them (no point deeper than `tol`): its force moves it only where it holds the tube
// (ContactSet::Initialize). 0 where it would not touch them within the tube's extent.
double TouchBack(const Tool &t, const std::vector<Vec2> &points, double tol, double extent)
{
  const Vec2 d = t.Axis();
  const double speed = std::hypot(d[0], d[1]);
  const auto overlaps = [&](double ahead) {
    const Tool moved = MovedBack(t, -ahead);
    for (const Vec2 &p : points) {
      const Projection pr = moved.Project(p);
      if (pr.segment >= 0 && pr.gap < -tol) return true;
    }
    return false;
  };
  double lo = 0, hi = speed > 0 ? 2 * extent / speed : 0; // (across the whole tube)
  if (hi == 0 || !overlaps(hi)) return 0;
  while (hi - lo > 1e-12 * extent / speed) (overlaps(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
  return -lo;
}

// Collective: the tool of the drawing file `path` of the shape kind `kind` (profile, dxf) given to `option`, or an
// error on every rank. Rank 0 reads the file; every rank parses the same text, so each reaches the same verdict.
PetscErrorCode ReadProfileTool(MPI_Comm comm, const char *option, const std::string &kind, const std::string &path,
                               Tool &tool)
{
  std::string text;
  bool ok;
  PetscFunctionBeginUser;
  PetscCall(ReadTextOnRoot(comm, path, ok, text));
  PetscCheck(ok, comm, PETSC_ERR_USER_INPUT, "%s %s: cannot read the file", option, path.c_str());
  ShapeSpec spec;
  spec.text = text, spec.file = path;
  const std::string error = MakeShape(kind, spec, tool); // (tool/shape.hpp)
  PetscCheck(error.empty(), comm, PETSC_ERR_USER_INPUT, "%s %s", option, error.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Collective: a lower or side die given as a file or a shape of its own (`option` names it), drawn as an upper die
// on the tube of outer radius `ro` (its right half).
PetscErrorCode DrawnDie(MPI_Comm comm, const char *option, const DieChoice &shape, double ro, Tool &drawn)
{
  PetscFunctionBeginUser;
  if (shape.Is(DieFrom::Drawing)) {
    PetscCall(ReadProfileTool(comm, option, shape.kind, shape.spec.file, drawn));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  ShapeSpec spec = shape.spec;
  spec.ro = ro;
  const std::string error = MakeShape(shape.kind, spec, drawn); // (its numbers checked: CheckDieShapes)
  PetscCheck(error.empty(), comm, PETSC_ERR_USER_INPUT, "%s %s: %s", option, shape.kind.c_str(), error.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The squaring dies' cavity has a closed form: two equal V-dies (the lower one mirroring the upper one, closing by
// 2 U as mirror and fixed do), no side dies.
bool ClosedForm(const Options &o, int pass, const DieSet &dies)
{
  return dies.upper.VDie() && dies.lower.Is(DieFrom::Mirror) && LowerDieClosing(o, pass) && dies.side.Is(DieFrom::None);
}

} // namespace

PetscErrorCode BuildDie(MPI_Comm comm, const DieShape &shape, Die &die)
{
  PetscFunctionBeginUser;
  if (shape.VDie()) {
    const ShapeSpec &v = shape.spec;
    const std::string error = MakeShape(shape.kind, v, die.tool);
    PetscCheck(error.empty(), comm, PETSC_ERR_USER_INPUT,
               "-die_angle %g, -die_r_apex %g, -die_u_close %g, -die_r_edge %g make no die: %s", v.angle, v.r_apex,
               v.u_close, v.r_edge, error.c_str());
    die.flank = v.r_apex > 0 ? 1 : 0;
    die.apex = die.flank - 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(ReadProfileTool(comm, "-die_profile", shape.kind, shape.spec.file, die.tool));
  die.flank = LongestLine(die.tool);
  PetscCheck(die.flank >= 0, comm, PETSC_ERR_USER_INPUT,
             "-die_profile %s: no straight segment (C/t is measured against the profile's longest line)",
             shape.spec.file.c_str());
  die.apex = die.flank > 0 && die.tool.segments[die.flank - 1].kind == Segment::Arc ? die.flank - 1 : -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode BuildLowerDie(MPI_Comm comm, const Options &opt, int pass, DieChoice shape, Tool &upper, double floor_y,
                             TubePart part, Tool &lower)
{
  PetscFunctionBeginUser;
  if (shape.Is(DieFrom::Mirror)) {
    lower = MirrorY(upper);
  } else if (shape.Is(DieFrom::Plate)) {
    // A floor under the tube, reaching past its widening on the outside.
    ShapeSpec &spec = shape.spec;
    spec.y = floor_y, spec.x1 = (1 + kFloorReach) * opt.tube_ro, spec.floor = true;
    spec.x0 = WholeTube(part) ? -(1 + kFloorReach) * opt.tube_ro : -kFloorOverhang * opt.tube_ro;
    MakeShape(shape.kind, spec, lower); // (the flat kind draws any plate)
  } else {
    Tool drawn;
    PetscCall(DrawnDie(comm, "-lower_die", shape, opt.tube_ro, drawn));
    lower = WholeTube(part) ? BothSides(MirrorY(drawn)) : MirrorY(drawn);
  }
  // Its name in errors and in the results (/tools/<name>): no spaces.
  lower.name = shape.Is(DieFrom::Plate) ? "floor" : shape.Is(DieFrom::Mirror) ? "lower-" + upper.name : "lower-die";
  PetscCall(SetLowerMotion(comm, opt, pass, upper, lower)); // (-lower_die_motion, its pass's: die_motion.cpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode AddSideDies(MPI_Comm comm, const Options &o, DieChoice shape, const char *option, bool squaring,
                           const Tool &upper_right, TubePart part, std::vector<Tool> &tools)
{
  Tool drawn; // drawn as an upper die (its right half), then turned to the side by the reflection about y = x
  PetscFunctionBeginUser;
  const bool plate = shape.Is(DieFrom::Plate) || (shape.Is(DieFrom::Mirror) && !squaring);
  if (plate) {
    // (the whole plate in the half and full models, which reach below the x axis)
    ShapeSpec &spec = shape.spec;
    spec.y = o.tube_ro, spec.x1 = (1 + kPlateReach) * o.tube_ro, spec.floor = false;
    spec.x0 = BothDies(part) ? -(1 + kPlateReach) * o.tube_ro : -kPlateOverhang * o.tube_ro;
    MakeShape(kFlatShape, spec, drawn); // (the flat kind draws any plate; the flattening scene's mirror too)
  } else if (shape.Is(DieFrom::Mirror)) {
    drawn = BothDies(part) ? BothSides(upper_right) : upper_right;
  } else {
    PetscCall(DrawnDie(comm, option, shape, o.tube_ro, drawn));
    drawn = BothDies(part) ? BothSides(drawn) : drawn;
  }
  Tool right = Transform(drawn, {true, 1}); // (x, y) -> (y, x): moving along -x by the stroke
  right.name = "side-" + std::string(plate ? "plate" : shape.Is(DieFrom::Mirror) ? tools[0].name : "die");
  MotionSpec in;
  in.direction = {-1.0, 0.0};
  PetscCall(SetMotion(comm, option, kStrokeMotion, in, right));
  tools.push_back(right);
  if (WholeTube(part)) {
    Tool left = MirrorX(right);
    left.name = "left-" + right.name;
    tools.push_back(left);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode BuildPassDies(MPI_Comm comm, const Options &opt, int pass, bool squaring, TubePart part, double floor_y,
                             std::vector<Tool> &tools, int &flank, int &apex)
{
  const DieSet dies = DiesOfPass(opt, pass);
  Tool upper, right_half; // (the upper die, and its right half as drawn: the side dies' mirror)
  PetscFunctionBeginUser;
  if (squaring) {
    Die die;
    PetscCall(BuildDie(comm, dies.upper, die));
    upper = WholeTube(part) ? BothSides(die.tool) : die.tool; // (the right half's segments first: flank and apex stay)
    right_half = die.tool;
    flank = die.flank, apex = die.apex;
  } else {
    const double from = WholeTube(part) ? -(1 + kPlateReach) * opt.tube_ro : -kPlateOverhang * opt.tube_ro;
    upper = BuildFlatPlate(opt.tube_ro, from, (1 + kPlateReach) * opt.tube_ro);
  }
  tools = {upper};
  if (BothDies(part)) {
    Tool lower;
    PetscCall(BuildLowerDie(comm, opt, pass, dies.lower, tools[0], floor_y, part, lower));
    tools.push_back(lower);
  }
  if (!dies.side.Is(DieFrom::None))
    PetscCall(
      AddSideDies(comm, opt, dies.side, PassOptionName(pass, "side_die").c_str(), squaring, right_half, part, tools));
  // Its upper die's own motion (a path, a force: the first pass's -die_motion, a later one's), after the stroke its
  // lower die's motion gives it.
  PetscCall(SetUpperMotion(comm, PassOptionName(pass, "die_motion").c_str(), dies.motion, tools[0]));
  // Its upper die off its press's axis (-die_offset, -pass<N>_die_offset): where it starts along its motion,
  // PressScene::PassTools (StartOffAxis).
  if (dies.offset != 0) tools[0] = Shifted(tools[0], {dies.offset, 0});
  // A later pass's dies by their own names (errors, and their outlines in the results): pass2-, pass3-, ...
  if (pass > 0)
    for (Tool &t : tools) t.name = Formatted("pass%d-", pass + 1) + t.name;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StartOnTube(MPI_Comm comm, bool say, const std::vector<SurfacePoint> &outer, std::vector<Tool> &tools,
                           std::vector<double> &back, int before)
{
  PetscFunctionBeginUser;
  std::vector<Vec2> points;
  double extent = 0;
  for (const auto &o : outer) points.push_back({o.x, o.y}), extent = std::max({extent, std::abs(o.x), std::abs(o.y)});
  back.assign(tools.size(), 0.0);
  for (size_t k = 0; k < tools.size(); ++k) {
    // (a tenth of the contact set's start tolerance: the nearest node then starts on the die, in contact)
    const double tol = 0.1 * kStartGap * (1 + extent);
    double b = ClearanceBack(tools[k], points, tol);
    PetscCheck(b >= 0, comm, PETSC_ERR_USER_INPUT,
               "the %s would start inside the tube as the %s springback left it, and cannot be moved back along "
               "its motion clear of it (a die that stays in place, fixed, is drawn where it is: -lower_die_motion, "
               "-side_motion and their passes')",
               tools[k].name.c_str(), PassOrdinal(before).c_str());
    if (b == 0 && tools[k].Unknown()) b = TouchBack(tools[k], points, tol, extent); // (ahead: < 0)
    if (b == 0) continue;
    back[k] = b;
    tools[k] = MovedBack(tools[k], b);
    if (say && b < 0)
      PetscCall(PetscPrintf(comm,
                            "tubeform: the %s starts at U = %.4g mm, where it touches the tube as the %s pass "
                            "left it (force-controlled: it presses from there)\n",
                            tools[k].name.c_str(), -b, PassOrdinal(before).c_str()));
    else if (say)
      PetscCall(PetscPrintf(comm,
                            "tubeform: the %s starts at U = %.4g mm, %.4g mm back along its motion from where it "
                            "would touch the round tube, where it touches the tube as the %s pass left it\n",
                            tools[k].name.c_str(), -b * std::hypot(tools[k].Axis()[0], tools[k].Axis()[1]),
                            b * std::hypot(tools[k].Axis()[0], tools[k].Axis()[1]), PassOrdinal(before).c_str()));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode StartOffAxis(MPI_Comm comm, bool say, const std::vector<SurfacePoint> &outer, double offset, Tool &die)
{
  std::vector<Tool> one = {die};
  std::vector<double> back;
  PetscFunctionBeginUser;
  PetscCall(StartOnTube(comm, false, outer, one, back, 0));
  die = one[0];
  if (say)
    PetscCall(PetscPrintf(comm,
                          "tubeform: the %s is %g mm off the axis; it starts %.4g mm back along its motion, "
                          "where it touches the tube\n",
                          die.name.c_str(), offset, back[0] * std::hypot(die.Axis()[0], die.Axis()[1])));
  PetscFunctionReturn(PETSC_SUCCESS);
}

TurnMap PassTurn(const Options &opt, int pass, TubePart part)
{
  const int k = PassQuarters(opt, pass), q = ((k % 4) + 4) % 4;
  if (WholeTube(part) && !QuarterTurn(opt, pass)) return TurnMap::TurnBy(-PassTurnDegrees(opt, pass) * M_PI / 180);
  if (WholeTube(part)) return TurnMap::Turn(-k);
  if (BothDies(part)) return q == 2 ? TurnMap{true, 0} : TurnMap{};
  return q % 2 ? TurnMap{true, 1} : TurnMap{};
}

PetscErrorCode CheckPressReach(MPI_Comm comm, const Options &opt, bool squaring, double deepest)
{
  PetscFunctionBeginUser;
  for (int pass = 0; pass < PassCount(opt); ++pass) {
    const PassExtent e = Extent(opt, pass);
    const std::vector<double> &path = StrokePathOf(opt, pass);
    const double deepest_of_pass = pass == 0      ? deepest
                                   : path.empty() ? e.stroke
                                                  : *std::max_element(path.begin(), path.end());
    if (!e.Forced())
      PetscCall(CheckDieReach(comm, opt, pass, DiesOfPass(opt, pass), squaring, deepest_of_pass, e.Option().c_str()));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

double DieReach(const Options &o, int pass, const DieSet &dies, bool squaring)
{
  const double ro = o.tube_ro, ri = ro - o.tube_t;
  if (squaring && !ClosedForm(o, pass, dies)) return kNever;
  if (!squaring) return ro - o.tube_t;
  const VAngle v(dies.upper.spec.angle);
  const double area = M_PI * (ro * ro - ri * ri), closed = ro * v.qs - std::sqrt(0.5 * area * (v.qs / v.qc));
  const double u_close = dies.upper.spec.u_close;
  return u_close > 0 ? std::min(closed, u_close) : closed;
}

PetscErrorCode CheckForceReach(MPI_Comm comm, const PassExtent &e, double reach, bool squaring, double stroke)
{
  PetscFunctionBeginUser;
  PetscCheck(stroke < reach, comm, PETSC_ERR_NOT_CONVERGED,
             "%s %g: the die has come down to U = %.4g mm, where %s (U = %.4g mm): the tube carries no more "
             "in this model",
             e.Option().c_str(), e.Target(), stroke,
             squaring ? "the dies close on the tube or meet" : "the ring's walls meet", reach);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckDieReach(MPI_Comm comm, const Options &o, int pass, const DieSet &dies, bool squaring,
                             double stroke, const char *option)
{
  PetscFunctionBeginUser;
  const double ro = o.tube_ro, ri = ro - o.tube_t;
  if (squaring && !ClosedForm(o, pass, dies)) {
    // A profile of one's own, side dies: no closed form of the cavity; a stroke that closes it fails in the run.
  } else if (squaring) {
    // The cavity is a rhombus of half-diagonals D = h - U and D tan(half): area 2 D^2 tan(half).
    const VAngle v(dies.upper.spec.angle);
    const double area = M_PI * (ro * ro - ri * ri), closed = ro * v.qs - std::sqrt(0.5 * area * (v.qs / v.qc));
    PetscCheck(stroke < closed, comm, PETSC_ERR_USER_INPUT,
               "%s %g: the dies would close on the tube at U = %.4g mm (the cavity between them is then "
               "smaller than the tube's cross-section of %.4g mm^2); choose a smaller stroke",
               option, stroke, closed, area);
    const double u_close = dies.upper.spec.u_close;
    PetscCheck(u_close <= 0 || stroke <= u_close, comm, PETSC_ERR_USER_INPUT,
               "%s %g: the dies' parting faces meet at -die_u_close %g mm; the stroke cannot pass it", option, stroke,
               u_close);
  } else {
    PetscCheck(stroke < ro - o.tube_t, comm, PETSC_ERR_USER_INPUT,
               "%s %g: the plate would press the ring's walls together at U = %.4g mm (Ro - t; the solver "
               "models no contact of the tube with itself); choose a smaller stroke",
               option, stroke, ro - o.tube_t);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode WarnUntouched(MPI_Comm comm, const ContactSet &contact, int pass, double stroke)
{
  PetscInt touching;
  PetscFunctionBeginUser;
  PetscCall(contact.Count(touching, false));
  if (touching == 0)
    PetscCall(PetscPrintf(comm,
                          "tubeform: warning: the %s pass's dies never touched the tube (at U = %g mm they are not "
                          "yet down to it): its shape is the last springback's\n",
                          PassOrdinal(pass).c_str(), stroke));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode NoteCornerRadius(MPI_Comm comm, double stroke, double corner_radius)
{
  return PetscPrintf(comm,
                     "tubeform: stroke %.4f mm gives an outer corner radius of %.4g mm (perimeter-conserving rounded "
                     "square)\n",
                     stroke, corner_radius);
}

} // namespace tf
