// What a rigid tool looks like (docs/dies.md), drawn as an upper die's right half, or a plate: one kind per file
// (src/tool/shape_v.cpp, shape_flat.cpp, shape_drawing.cpp: a profile or DXF file, parsed by profile.cpp and
// dxf.cpp): the shape, the options it reads under its tool's options prefix and how it refuses their values, how
// it is drawn; each named in the registry (shape_registry.cpp). Its motion is the tool's Motion
// (tool/motion.hpp). Geometry, and PETSc only to read and check the options.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "tubeform/tool/tool.hpp"

namespace tf {

// The half-angle of a V-die of `degrees` between its flanks, with 1 / sin and
// 1 / cos of it.
struct VAngle {
  explicit VAngle(double degrees);
  double half, qs, qc;
};

// The upper V-die of the quarter model (docs/dies.md), of `angle` degrees
// between its flanks (the paper's 90 by default): the flanks touch the tube's
// outer circle, meeting on the y axis at (0, h), h = ro / sin(angle / 2),
// rounded there by an arc of radius r_apex centred at (0, h - r_apex / sin);
// the flank runs to x = 1.3 ro, or, with u_close > 0, to the parting face
// y = u_close (at stroke 0) through a convex edge fillet of radius r_edge.
// Moves down by the stroke.
// "" or why these numbers make no die (a parting face above the apex, ...), naming "the V-die".
std::string MakeVDie(double ro, double r_apex, double u_close, double r_edge, double angle, Tool &t);
// The same, throwing std::invalid_argument on an error (for tests and code that checked its numbers).
Tool BuildVDie(double ro, double r_apex, double u_close = 0, double r_edge = 0, double angle = 90);

// The paper's stroke rule: the stroke at which a rounded rhombus (a square at
// 90 degrees) of corner radius rc, its sides on the closed dies' flanks, has
// the perimeter of the tube's outer circle 2 pi ro.
double StrokeForCornerRadius(double ro, double rc, double angle = 90);

// A flat plate y = y0 from x = x0 to x1, pressing down (body below), or with
// `floor` a support with the body above it.
Tool BuildFlatPlate(double y0, double x0, double x1, bool floor = false);
// What a kind of shape is made from (each kind reads what it needs).
struct ShapeSpec {
  // v: the V-die drawn on the tube of outer radius ro (MakeVDie)
  double ro = 0, r_apex = 0, u_close = 0, r_edge = 0, angle = 90;
  // flat: a plate at y from x0 to x1; a floor (the body above it) or pressing down (BuildFlatPlate)
  double y = 0, x0 = 0, x1 = 0;
  bool floor = false;
  // profile, dxf: a file's text and its name (tool/profile.hpp)
  std::string text, file;
};

// An option of a kind: its name under a prefix (without the dash: "angle" is the upper die's -die_angle) and its
// -help text.
struct ShapeOption {
  std::string name, help;
};
// A kind's reader: its options, under the options prefix of the PetscOptionsBegin block it is called in (the
// tool's: "die_" reads -die_angle as "-angle"), into `spec`, their values as defaults; a value that is not a number
// refused in one line naming the full option. Its values' ranges are its checker's.
using ShapeReader = PetscErrorCode (*)(PetscOptionItems *PetscOptionsObject, ShapeSpec &spec);
// A kind's checker (collective): the values its reader read refused in one line naming the option -<prefix><name>
// and what it allows (against the tube of outer radius spec.ro).
using ShapeCheck = PetscErrorCode (*)(MPI_Comm comm, const char *prefix, const ShapeSpec &spec);
// A kind's factory: the tool from `spec` into `t`; "" or why not.
using ShapeFactory = std::string (*)(const ShapeSpec &spec, Tool &t);
// A kind in the registry: its name, its options (none: it reads nothing), its reader and checker (none: nothing to
// read or check) and its factory. Each kind's file defines its own (VKind(), ...; the registry lists them).
struct ShapeKind {
  const char *name;
  std::vector<ShapeOption> options;
  ShapeReader read;
  ShapeCheck check;
  ShapeFactory make;
};

// The registry: the tool of the kind named `kind` from `spec` into `tool`; "" or why not (an unknown kind names the
// known ones; a kind refuses a spec it cannot draw: a V-die whose parting face is above its apex, a profile file
// that does not parse).
std::string MakeShape(const std::string &kind, const ShapeSpec &spec, Tool &tool);
// The registered kinds, in the registry's order.
std::vector<std::string> ShapeKinds();
// The kind named `kind`, or nullptr.
const ShapeKind *FindShapeKind(const std::string &kind);
// Reads the options of the kind named `kind` (a registered one) into `spec` (ShapeReader).
PetscErrorCode ReadShape(PetscOptionItems *PetscOptionsObject, const std::string &kind, ShapeSpec &spec);
// Refuses the values of the kind named `kind` (a registered one) read under `prefix` (ShapeCheck).
PetscErrorCode CheckShape(MPI_Comm comm, const std::string &kind, const char *prefix, const ShapeSpec &spec);
// For a kind's reader: its option `o`, a number, into `value` (its default), under the block's prefix; a value
// that is not a number refused ("-die_angle abc: not a number").
PetscErrorCode ReadShapeReal(PetscOptionItems *PetscOptionsObject, const ShapeOption &o, double &value);
// The names of the V-die's kind (shape_v.cpp: the upper die's shape unless a file is named) and the flat plate's
// (shape_flat.cpp: a lower die's floor, a side die's plate), which the tools' options choose without a file.
inline constexpr const char *kVShape = "v";
inline constexpr const char *kFlatShape = "flat";
// The kind of a drawing file by its name: dxf for .dxf (.DXF), else profile (tubeform's own format).
std::string DrawingKind(const std::string &file);

} // namespace tf
