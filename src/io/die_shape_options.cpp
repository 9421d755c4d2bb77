// The upper die's shape, its own options block under its prefix die_ (include/tubeform/io/tool_options.hpp): the
// V-die of the shape registry (tool/shape.hpp) unless -die_profile names a file, a drawing of the registry's kind
// for the file's name (DrawingKind; its text read when the die is drawn). The V kind reads its own options,
// -die_angle, -die_r_apex, -die_u_close, -die_r_edge, with a file too (a scene file's V-die stays allowed under a
// -die_profile given after it), and its checker refuses their values (CheckOptions).
#include "tubeform/io/tool_options.hpp"

namespace tf {

PetscErrorCode ReadUpperDieShape(MPI_Comm comm, OptionReader &read, Options &opt)
{
  DieShape &die = opt.die_shape;
  const ShapeKind *v = FindShapeKind("v");
  std::string help = "squaring: the upper die's right half from a DXF file (*.dxf) or a text profile of lines and arcs "
                     "(docs/dies.md) in place of the V-die of ";
  for (size_t k = 0; k < v->options.size(); ++k) help += (k == 0 ? "-die_" : ", -die_") + v->options[k].name;
  char file[PETSC_MAX_PATH_LEN];
  PetscBool set;

  PetscFunctionBeginUser;
  read.Note("-die_profile", help.c_str());
  for (const ShapeOption &o : v->options) read.Note(("-die_" + o.name).c_str(), o.help.c_str());
  PetscOptionsBegin(comm, "die_", "tubeform: upper die shape", "tubeform");
  OptionsBlock block(PetscOptionsObject);
  PetscCall(PetscStrncpy(file, die.spec.file.c_str(), sizeof(file)));
  PetscCall(PetscOptionsString("-profile", help.c_str(), "tubeform", file, file, sizeof(file), &set));
  if (set) die.spec.file = file;
  PetscCall(ReadShape(PetscOptionsObject, "v", die.spec));
  block.Release();
  PetscOptionsEnd();
  die.kind = die.spec.file.empty() ? "v" : DrawingKind(die.spec.file);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
