// The registry of tool shapes: each kind's name, the options it reads, its reader, checker and factory (a
// ShapeKind, defined in the kind's own file). A new shape is its own file (shape_*.cpp) and a line here.
#include <cstdlib>

#include "tubeform/tool/shape.hpp"

namespace tf {

const ShapeKind &VKind();       // shape_v.cpp
const ShapeKind &FlatKind();    // shape_flat.cpp
const ShapeKind &ProfileKind(); // shape_drawing.cpp
const ShapeKind &DxfKind();     // shape_drawing.cpp

namespace {
const ShapeKind &(*const kKinds[])() = {VKind, FlatKind, ProfileKind, DxfKind};
} // namespace

const ShapeKind *FindShapeKind(const std::string &kind)
{
  for (const auto &k : kKinds)
    if (kind == k().name) return &k();
  return nullptr;
}

std::string MakeShape(const std::string &kind, const ShapeSpec &spec, Tool &tool)
{
  if (const ShapeKind *k = FindShapeKind(kind)) return k->make(spec, tool);
  std::string known;
  for (const std::string &k : ShapeKinds()) known += (known.empty() ? "" : ", ") + k;
  return "no shape '" + kind + "' (known: " + known + ")";
}

std::vector<std::string> ShapeKinds()
{
  std::vector<std::string> kinds;
  for (const auto &k : kKinds) kinds.push_back(k().name);
  return kinds;
}

PetscErrorCode ReadShape(PetscOptionItems *PetscOptionsObject, const std::string &kind, ShapeSpec &spec)
{
  PetscFunctionBeginUser;
  const ShapeKind *k = FindShapeKind(kind);
  Tool none;
  PetscCheck(k, PetscOptionsObject->comm, PETSC_ERR_PLIB, "%s", MakeShape(kind, spec, none).c_str());
  if (k->read) PetscCall(k->read(PetscOptionsObject, spec));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckShape(MPI_Comm comm, const std::string &kind, const char *prefix, const ShapeSpec &spec)
{
  PetscFunctionBeginUser;
  const ShapeKind *k = FindShapeKind(kind);
  Tool none;
  PetscCheck(k, comm, PETSC_ERR_PLIB, "%s", MakeShape(kind, spec, none).c_str());
  if (k->check) PetscCall(k->check(comm, prefix, spec));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadShapeReal(PetscOptionItems *PetscOptionsObject, const ShapeOption &o, double &value)
{
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
  const std::string name = "-" + o.name;
  char buf[256];
  PetscBool set;
  PetscReal v = value;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, prefix, name.c_str(), buf, sizeof(buf), &set));
  char *end = nullptr;
  if (set) (void)std::strtod(buf, &end);
  PetscCheck(!set || (buf[0] && end && *end == 0), PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%s%s %s: not a number", prefix, o.name.c_str(), buf);
  PetscCall(PetscOptionsReal(name.c_str(), o.help.c_str(), "tubeform", v, &v, nullptr));
  value = v;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
