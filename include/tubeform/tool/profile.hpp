// A die of one's own: the working surface of the upper die's right half as a
// chain of lines and arcs read from a short text file (docs/dies.md), checked
// and turned into a Tool. Pure geometry, no PETSc.
//
//   # comments
//   line X0 Y0 X1 Y1          a straight segment walked from (X0, Y0) to (X1, Y1)
//   arc CX CY R A0 A1         an arc of centre (CX, CY), radius R, walked from angle A0 to A1 (degrees)
//
// In mm, in the tube's frame at stroke 0 (its centre at the origin). The chain
// starts on the axis x = 0 and is walked outward with the tube on its right
// (so a V walked from its apex down the flank); the die's left half and the
// lower die are its mirrors, and the quarter model stays exact.
#pragma once

#include <string>
#include <vector>

#include "tubeform/tool/tool.hpp"

namespace tf {

// A segment's end this close to the next one's start (mm) joins them; more is a gap.
constexpr double kProfileGap = 1e-6;
// An arc whose direction at a joint differs from its neighbour's by more (radians) is not tangent to it.
constexpr double kProfileTangency = 1e-4;

// One segment of a profile as written: a line (X0 Y0 X1 Y1) or an arc (CX CY R A0 A1, degrees).
struct ProfileItem {
  bool arc = false;
  std::vector<double> v;
  int line = 0;      // of the file (0: built in code)
  std::string where; // where the errors say it is, if not at `line` (a DXF entity)
};

// Parses `text` (the contents of `file`, named in the errors) into `tool`; returns "" or a one-line error
// naming the file and line.
std::string ParseProfile(const std::string &text, const std::string &file, Tool &tool);
// The tool of a chain of segments, checked (gaps, tangency of arcs, the start on the axis, the tube's side):
// "" or the error. The V-die is built through here too, so that a profile file of it is the same die.
std::string BuildProfile(const std::vector<ProfileItem> &items, const std::string &file, Tool &tool);

// The chain of a DXF file's LINE, ARC and LWPOLYLINE (or POLYLINE) entities (`text`, the file's contents),
// in any order and either orientation, walked from the entity on the axis x = 0 outward (tool/dxf.cpp):
// "" or a one-line error naming the file and the entity.
std::string DxfProfile(const std::string &text, const std::string &file, std::vector<ProfileItem> &items);

// The longest straight segment of a tool (the side the collapse C/t is measured against), -1 if none.
int LongestLine(const Tool &tool);

} // namespace tf
