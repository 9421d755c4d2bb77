// The upper die's shape, its own options block under its prefix die_ (include/tubeform/scenes/tool_options.hpp): the
// V-die of the shape registry (tool/shape.hpp) unless -die_profile names a file, a drawing of the registry's kind
// for the file's name (DrawingKind; its text read when the die is drawn). The V kind reads its own options,
// -die_angle, -die_r_apex, -die_u_close, -die_r_edge, with a file too (a scene file's V-die stays allowed under a
// -die_profile given after it), and its checker refuses their values (CheckToolSceneOptions); a later pass's own V
// numbers likewise under its prefix pass<N>_die_ (ReadPassShapes).
// The lower die's and the side dies' shapes, each its own block: a word (-lower_die, -side_die) choosing mirror (the
// upper die's shape, a relation between the tools), flat (the flat kind), none (no side dies), a shape of its own (a
// kind of the registry that reads options, v: its numbers read by the kind in a block under the die's prefix,
// -lower_die_angle, -side_die_r_apex, -pass2_lower_die_angle, ...: ReadDieShapeOptions) or a file (its kind by its
// name). The scenes place, size and draw them (scenes/die.cpp).
#include <algorithm>
#include <cmath>

#include "tubeform/core/core.hpp"
#include "tubeform/scenes/tool_options.hpp"

namespace tf {

namespace {
// The word of `option` (its help `help`) in its own block titled `title`, its shape into `shape`.
PetscErrorCode ReadWordShape(MPI_Comm comm, OptionReader &read, const char *option, const char *help, const char *title,
                             bool none, DieChoice &shape)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, title, "tubeform");
  OptionsBlock block(PetscOptionsObject);
  PetscCall(ReadDieChoice(PetscOptionsObject, read, option, help, none, shape));
  block.Release();
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The first of the numbers of the shape kind `k` given under `prefix` into `given` ("" none), each noted (for -help's
// hints and the check of unknown options) with the help `help_of(option)` in the block titled `title`.
template <class Help>
PetscErrorCode NoteShapeNumbers(OptionReader &read, const std::string &prefix, const std::string &title,
                                const ShapeKind &k, Help help_of, std::string &given)
{
  PetscFunctionBeginUser;
  given.clear();
  for (const ShapeOption &o : k.options) {
    const std::string option = "-" + prefix + o.name;
    PetscBool set;
    PetscCall(PetscOptionsHasName(nullptr, prefix.c_str(), ("-" + o.name).c_str(), &set));
    if (set && given.empty()) given = option;
    read.Note(option.c_str(), help_of(o).c_str(), title.c_str());
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The numbers of the shape kind `kind` over `spec`, read by the kind in their own block under `prefix` titled `title`.
PetscErrorCode ReadShapeBlock(MPI_Comm comm, const std::string &prefix, const std::string &title,
                              const std::string &kind, ShapeSpec &spec)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, prefix.c_str(), title.c_str(), "tubeform");
  OptionsBlock block(PetscOptionsObject);
  PetscCall(ReadShape(PetscOptionsObject, kind, spec));
  block.Release();
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}
} // namespace

PetscErrorCode ReadDieShapeOptions(MPI_Comm comm, OptionReader &read, const DieOwnShape &die, const DieChoice *first,
                                   DieChoice &shape)
{
  const DieChoice &as = shape.Given() || !first ? shape : *first; // (a later pass's not given: the first pass's)
  PetscFunctionBeginUser;
  for (const std::string &name : ShapeKinds()) {
    const ShapeKind *k = FindShapeKind(name);
    const bool own = as.Is(DieFrom::Shape) && as.kind == name;
    std::string given;
    PetscCall(NoteShapeNumbers(
      read, die.prefix, die.title, *k, [&](const ShapeOption &o) { return die.word + " " + name + ": " + o.help; },
      given));
    if (!own && !given.empty() && shape.stray.empty()) // (refused by CheckDieShapes, in a press)
      shape.stray = given + ": a number of a " + name + " die of its own; give " + die.word + " " + name;
    const bool read_own = own && (shape.Given() || !given.empty());
    if (k->options.empty() || !(read_own || die.list)) continue; // (-help lists a pass's first block of each kind)
    // (its numbers from the first pass's where that die is of this kind, as the upper die's; else the paper's die)
    const bool from_first = first && first->Is(DieFrom::Shape) && first->kind == name;
    ShapeSpec spec = from_first ? first->spec : own ? shape.spec : PaperVDie();
    PetscCall(ReadShapeBlock(comm, die.prefix, die.title, name, spec));
    if (!read_own) continue;
    if (!shape.Given()) shape = *first; // (its own numbers on the first pass's shape)
    shape.spec = spec;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckDieShapes(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  if (!PressesWithTools(opt)) PetscFunctionReturn(PETSC_SUCCESS); // (their names refused, or let go: -allow_unused)
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const DieSet &dies = ToolsOf(opt).passes[pass].dies;
    for (const DieChoice *shape : {&dies.lower, &dies.side}) {
      PetscCheck(shape->stray.empty(), comm, PETSC_ERR_USER_INPUT, "%s", shape->stray.c_str());
      if (!shape->Is(DieFrom::Shape)) continue;
      ShapeSpec spec = shape->spec;
      spec.ro = opt.tube_ro;
      const std::string prefix = PassOptionName(pass, shape == &dies.lower ? "lower_die_" : "side_die_").substr(1);
      PetscCall(CheckShape(comm, shape->kind, prefix.c_str(), spec));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadDieChoice(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *option,
                             const char *help, bool none, DieChoice &shape)
{
  std::string word = ShapeWord(shape);
  PetscFunctionBeginUser;
  PetscCall(read.String(PetscOptionsObject, option, help, word));
  if (word != ShapeWord(shape)) shape = ShapeChoice(word, none);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadDrawingChoice(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *option,
                                 const char *help, DieShape &shape)
{
  std::string file = shape.spec.file;
  PetscFunctionBeginUser;
  PetscCall(read.String(PetscOptionsObject, option, help, file));
  if (file != shape.spec.file) shape.kind = DrawingChoice(file).kind, shape.spec.file = file;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadUpperDieShape(MPI_Comm comm, OptionReader &read, Options &opt)
{
  DieShape &die = ToolsOf(opt).passes[0].dies.upper;
  const ShapeKind *v = FindShapeKind(kVShape);
  std::string help = "squaring: the upper die's right half from a DXF file (*.dxf) or a text profile of lines and arcs "
                     "(docs/dies.md) in place of the V-die of ";
  for (size_t k = 0; k < v->options.size(); ++k) help += (k == 0 ? "-die_" : ", -die_") + v->options[k].name;
  char file[PETSC_MAX_PATH_LEN];
  PetscBool set;

  PetscFunctionBeginUser;
  const char *title = "tubeform: upper die shape";
  read.Note("-die_profile", help.c_str(), title);
  for (const ShapeOption &o : v->options) read.Note(("-die_" + o.name).c_str(), o.help.c_str(), title);
  PetscOptionsBegin(comm, "die_", title, "tubeform");
  OptionsBlock block(PetscOptionsObject);
  PetscCall(PetscStrncpy(file, die.spec.file.c_str(), sizeof(file)));
  PetscCall(PetscOptionsString("-profile", help.c_str(), "tubeform", file, file, sizeof(file), &set));
  if (set) die.spec.file = file;
  PetscCall(ReadShape(PetscOptionsObject, kVShape, die.spec));
  block.Release();
  PetscOptionsEnd();
  die.kind = die.spec.file.empty() ? kVShape : DrawingChoice(die.spec.file).kind;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadPassShapes(MPI_Comm comm, OptionReader &read, Options &opt)
{
  const ShapeKind *v = FindShapeKind(kVShape);
  PetscFunctionBeginUser;
  for (int pass = 1; pass < kMaxPasses; ++pass) {
    DieShape &die = ToolsOf(opt).passes[pass].dies.upper;
    const std::string prefix = Formatted("pass%d_die_", pass + 1);
    const std::string title = Formatted("tubeform: pass %d upper die shape", pass + 1);
    std::string given;
    PetscCall(NoteShapeNumbers(
      read, prefix, title, *v, [](const ShapeOption &o) { return "squaring: the pass's V-die, as -die_" + o.name; },
      given));
    if (given.empty() && pass > 1) continue;    // (pass 2's listed by -help always; a later one's where given)
    ShapeSpec spec = FirstDies(opt).upper.spec; // (the first pass's numbers its defaults)
    PetscCall(ReadShapeBlock(comm, prefix, title, kVShape, spec));
    if (!given.empty() && die.kind.empty()) die.kind = kVShape, die.spec = spec; // (a -pass<N>_die_profile: the file's)
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadPassOwnShapes(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  for (int pass = 1; pass < kMaxPasses; ++pass) {
    DieSet &dies = ToolsOf(opt).passes[pass].dies;
    for (const bool lower : {true, false}) {
      const char *what = lower ? "lower_die" : "side_die";
      const DieOwnShape own{
        Formatted("pass%d_%s_", pass + 1, what),
        Formatted("tubeform: pass %d %s shape of its own", pass + 1, lower ? "lower die" : "side die"),
        PassOptionName(pass, what), opt.help && pass == 1};
      const DieSet &first = FirstDies(opt);
      PetscCall(
        ReadDieShapeOptions(comm, read, own, lower ? &first.lower : &first.side, lower ? dies.lower : dies.side));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadLowerDieShape(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  DieChoice &lower = ToolsOf(opt).passes[0].dies.lower;
  PetscCall(ReadWordShape(comm, read, "-lower_die",
                          "tool scenes: the lower die: mirror (of the upper one), flat (a floor at y = -Ro), v (a "
                          "V-die of its own: -lower_die_angle, ...), or a profile file (*.dxf or text) drawn as an "
                          "upper die, mirrored below the tube",
                          "tubeform: lower die shape", false, lower));
  PetscCall(ReadDieShapeOptions(
    comm, read, {"lower_die_", "tubeform: lower die shape of its own", "-lower_die", opt.help == PETSC_TRUE}, nullptr,
    lower));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadSideDieShape(MPI_Comm comm, OptionReader &read, Options &opt)
{
  DieSet &dies = ToolsOf(opt).passes[0].dies;

  PetscFunctionBeginUser;
  PetscCall(ReadWordShape(comm, read, "-side_die",
                          "tool scenes: side dies pressing towards the tube's centre as -side_motion says (by default "
                          "by the stroke U): none, mirror (the upper die turned to the side), flat (a plate), v (a "
                          "V-die of its own: -side_die_angle, ...), or a profile file drawn as an upper die "
                          "(docs/dies.md)",
                          "tubeform: side die shape", true, dies.side)); // (as a later pass's -pass<N>_side_die)
  PetscCall(ReadDieShapeOptions(
    comm, read, {"side_die_", "tubeform: side die shape of its own", "-side_die", opt.help == PETSC_TRUE}, nullptr,
    dies.side));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckSideMotion(MPI_Comm comm, const Options &opt, int pass)
{
  const DieSet dies = DiesOfPass(opt, pass);
  const std::string side = PassOptionName(pass, "side_die") + (pass > 0 ? " (or -side_die)" : "");
  // (named by the option given: a force by its number, the old spelling's, another motion by its word)
  const std::string name =
    dies.SideForce() > 0 ? Formatted("%s %g", PassOptionName(pass, "side_force").c_str(), dies.SideForce())
                         : PassOptionName(pass, "side_motion") + " " + FindMotionKind(dies.side_motion.kind)->side_word;
  // (a motion with kinks within the pass's strokes in turn, a path's points, a pulse's half periods, follows the
  // stroke as it rises: its kinks end increments where the stroke first reaches them, not where a stroke that backs
  // off passes them again)
  const std::vector<double> &path = StrokePathOf(opt, pass);
  MotionSpec in = dies.side_motion.spec;
  in.direction = {-1.0, 0.0};
  MotionHandle motion;
  const bool kinks = !path.empty() && MakeMotion(dies.side_motion.kind, in, motion).empty() &&
                     !motion->Kinks(*std::max_element(path.begin(), path.end())).empty();
  PetscFunctionBeginUser;
  PetscCheck(DieMoves(dies.side_motion, kStrokeMotion) || !dies.side.Is(DieFrom::None), comm, PETSC_ERR_USER_INPUT,
             "%s: side dies on a motion of their own need the pass's side dies, %s (mirror, flat or a file)",
             name.c_str(), side.c_str());
  PetscCheck(!kinks, comm, PETSC_ERR_USER_INPUT,
             "%s: the side dies follow their motion as the stroke rises: not with %s", name.c_str(),
             PassOptionName(pass, "stroke_path").c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckSideDieOptions(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckSideDies(comm, opt, 0, "-side_die", FirstDies(opt).side)); // (passes_check.cpp)
  PetscCall(CheckSideMotion(comm, opt, 0));
  // Every pass's side dies pressed by a force where the tube's two sides meet them alike (each travels its own way,
  // the run follows one), named by the option that gives the force (a later pass's own, or the first pass's).
  const ModelChoice model = ModelOf(opt);
  for (int pass = 0; pass < PassCount(opt); ++pass) {
    const DieSet dies = DiesOfPass(opt, pass);
    PetscCheck(dies.side.Is(DieFrom::None) || dies.SideForce() == 0 || model.SidesAlike(pass), comm,
               PETSC_ERR_USER_INPUT,
               "%s %g: side dies pressing by a force in the %s pass, whose two sides of the tube differ (a die off "
               "the axis in it or before it; a turn that brings a pass not mirrored top to bottom to the sides): "
               "each would travel its own way, and the run follows one; press them by the stroke",
               PassOptionName(pass, "side_force").c_str(), dies.SideForce(), PassOrdinal(pass).c_str());
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
