// The V-die (tool/shape.hpp): the flanks of -die_angle touching the tube, the apex fillet, the parting face and
// its edge fillet, drawn as a profile (tool/profile.hpp). Its options under its tool's prefix (the upper die's:
// die_): -<prefix>angle (degrees, 60 to 150), -<prefix>r_apex (mm, below the tube's outer radius),
// -<prefix>u_close, -<prefix>r_edge (mm, >= 0).
#include <cmath>
#include <stdexcept>

#include "tubeform/tool/profile.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

namespace {
// The angle's range (degrees): the V-dies tests/check_die_angle.py presses (the flank's reach of 1.3 ro is
// beyond the squared side over it).
constexpr double kAngleMin = 60, kAngleMax = 150;

const ShapeOption kAngle{"angle", "V-die: the angle between its flanks (degrees; the paper's 90)"};
const ShapeOption kRApex{"r_apex", "V-die apex fillet radius (mm)"};
const ShapeOption kUClose{"u_close",
                          "V-die parting face at y = u_close - U: the dies close at stroke u_close (mm; 0: no parting "
                          "face)"};
const ShapeOption kREdge{"r_edge", "V-die edge fillet radius between flank and parting face (mm)"};

PetscErrorCode ReadV(PetscOptionItems *PetscOptionsObject, ShapeSpec &spec)
{
  PetscFunctionBeginUser;
  PetscCall(ReadShapeReal(PetscOptionsObject, kAngle, spec.angle));
  PetscCall(ReadShapeReal(PetscOptionsObject, kRApex, spec.r_apex));
  PetscCall(ReadShapeReal(PetscOptionsObject, kUClose, spec.u_close));
  PetscCall(ReadShapeReal(PetscOptionsObject, kREdge, spec.r_edge));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckV(MPI_Comm comm, const char *prefix, const ShapeSpec &s)
{
  PetscFunctionBeginUser;
  PetscCheck(s.angle >= kAngleMin && s.angle <= kAngleMax, comm, PETSC_ERR_USER_INPUT,
             "-%sangle %g: must lie in [%g, %g] degrees", prefix, s.angle, kAngleMin, kAngleMax);
  PetscCheck(s.r_apex >= 0 && s.r_apex < s.ro, comm, PETSC_ERR_USER_INPUT, "-%sr_apex %g: must lie in [0, -tube_ro)",
             prefix, s.r_apex);
  PetscCheck(s.u_close >= 0 && s.r_edge >= 0, comm, PETSC_ERR_USER_INPUT,
             "-%su_close %g, -%sr_edge %g: must be non-negative", prefix, s.u_close, prefix, s.r_edge);
  PetscFunctionReturn(PETSC_SUCCESS);
}
} // namespace

const ShapeKind &VKind()
{
  static const ShapeKind kind{
    kVShape, {kAngle, kRApex, kUClose, kREdge}, ReadV, CheckV, [](const ShapeSpec &s, Tool &t) {
      return MakeVDie(s.ro, s.r_apex, s.u_close, s.r_edge, s.angle, t);
    }};
  return kind;
}

VAngle::VAngle(double degrees)
{
  // At 90 degrees sqrt(2) itself and pi / 4: the paper's die without the round-off of sin and cos.
  if (degrees == 90) {
    half = M_PI / 4, qs = qc = std::sqrt(2.0);
  } else {
    half = degrees * M_PI / 360, qs = 1 / std::sin(half), qc = 1 / std::cos(half);
  }
}

std::string MakeVDie(double ro, double r_apex, double u_close, double r_edge, double angle, Tool &t)
{
  // As a profile (tool/profile.hpp), so that a profile file with these numbers is the same die to the last bit.
  const VAngle v(angle);
  const double h = ro * v.qs, half = angle / 2; // the flanks' intersection (they touch the tube); degrees
  std::vector<ProfileItem> items;
  Vec2 flank_start = {0, h};
  if (r_apex > 0) {
    const double cy = h - r_apex * v.qs;
    items.push_back({true, {0, cy, r_apex, 90, half}, 0, ""}); // walked from the apex to the flank's tangent point
    flank_start = {r_apex / v.qc, cy + r_apex / v.qs};
  }
  if (u_close > 0) {
    // The flank meets the parting face y = u_close at x = xe; a convex fillet of radius r_edge tangent to both
    // turns through 90 - half degrees, its tangent points set back from the corner by r_edge tan of half that.
    const double xe = (h - u_close) * (v.qc / v.qs);
    const double d = r_edge * std::tan((M_PI / 2 - v.half) / 2);
    items.push_back({false, {flank_start[0], flank_start[1], xe - d / v.qs, u_close + d / v.qc}, 0, ""});
    if (r_edge > 0) items.push_back({true, {xe + d, u_close + r_edge, r_edge, 180 + half, 270}, 0, ""});
    items.push_back({false, {xe + d, u_close, 2.0 * ro, u_close}, 0, ""});
  } else {
    items.push_back({false, {flank_start[0], flank_start[1], 1.3 * ro, h - 1.3 * ro * (v.qs / v.qc)}, 0, ""});
  }
  const std::string error = BuildProfile(items, "the V-die", t);
  t.name = "V-die";
  return error;
}

Tool BuildVDie(double ro, double r_apex, double u_close, double r_edge, double angle)
{
  Tool t;
  const std::string error = MakeVDie(ro, r_apex, u_close, r_edge, angle, t);
  if (!error.empty()) throw std::invalid_argument(error);
  return t;
}

double StrokeForCornerRadius(double ro, double rc, double angle)
{
  // The cavity is a rhombus of vertical half-diagonal D = h - U and sides D / cos(half); rounding each corner
  // (turning by 2 (pi/2 - half) at the top and bottom, 2 half at the sides) by rc cuts 2 rc tan(turn / 2) from
  // the sides and adds rc x turn: perimeter 4 D / cos(half) - 4 rc (cot(half) + tan(half)) + 2 pi rc = 2 pi ro.
  const VAngle v(angle);
  const double d = (2 * M_PI * ro + (4 * (v.qs / v.qc + v.qc / v.qs) - 2 * M_PI) * rc) / (4 * v.qc);
  return ro * v.qs - d;
}

} // namespace tf
