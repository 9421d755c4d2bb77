#include "tubeform/scenes/registry.hpp"

#include "tubeform/core/option_reader.hpp"
#include "tubeform/scenes/scene_params.hpp"
#include "tubeform/scenes/tool_options.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace tf {

// One factory per scene file.
std::unique_ptr<Scene> MakeSquaringScene(const Options &opt);
std::unique_ptr<Scene> MakeFlatteningScene(const Options &opt);
std::unique_ptr<Scene> MakePressureScene(const Options &opt);
std::unique_ptr<Scene> MakeShearScene(const Options &opt);
std::unique_ptr<Scene> MakeRotationScene(const Options &opt);
std::unique_ptr<Scene> MakeColumnScene(const Options &opt);
std::unique_ptr<Scene> MakeTensionScene(const Options &opt);
std::unique_ptr<Scene> MakeBendingScene(const Options &opt);
std::unique_ptr<Scene> MakeSlideScene(const Options &opt);
std::unique_ptr<Scene> MakeArcSlideScene(const Options &opt);
// The readers and checkers of the scenes' own options, each in its scene's file.
#define TF_SCENE_OPTIONS(Name)                                                                                         \
  PetscErrorCode Read##Name##Options(PetscOptionItems *PetscOptionsObject, OptionReader &read, Name##Params &own);     \
  PetscErrorCode Check##Name##Options(MPI_Comm comm, const Name##Params &own);
TF_SCENE_OPTIONS(Pressure)
TF_SCENE_OPTIONS(Shear)
TF_SCENE_OPTIONS(Rotation)
TF_SCENE_OPTIONS(Column)
TF_SCENE_OPTIONS(Tension)
TF_SCENE_OPTIONS(Bending)
TF_SCENE_OPTIONS(Slide)
#undef TF_SCENE_OPTIONS

namespace {
// A scene's reader and checker of its own parameters' struct P, as the registry hands them to ReadOptions: P's
// built-in values changed by the options given, kept in `own`.
template <class P, PetscErrorCode (*Read)(PetscOptionItems *, OptionReader &, P &)>
PetscErrorCode ReadOwn(PetscOptionItems *PetscOptionsObject, OptionReader &read, std::any &own)
{
  P params;
  PetscFunctionBeginUser;
  PetscCall(Read(PetscOptionsObject, read, params));
  own = params;
  PetscFunctionReturn(PETSC_SUCCESS);
}
template <class P, PetscErrorCode (*Check)(MPI_Comm, const P &)>
PetscErrorCode CheckOwn(MPI_Comm comm, const std::any &own)
{
  PetscFunctionBeginUser;
  PetscCall(Check(comm, std::any_cast<const P &>(own)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
#define TF_OWN(Name) ReadOwn<Name##Params, Read##Name##Options>, CheckOwn<Name##Params, Check##Name##Options>

// The squaring scene's upper die's, a V-die or a profile, and its offset, in every pass (the flattening scene's
// plate has neither).
#define TF_V_DIE_OPTIONS                                                                                               \
  "-die_angle -die_r_apex -die_profile -die_u_close -die_r_edge -die_offset -pass<N>_die_angle -pass<N>_die_r_apex "   \
  "-pass<N>_die_profile -pass<N>_die_u_close -pass<N>_die_r_edge -pass<N>_die_offset"
// The tube's and its mesh's options (io/options.cpp): read where the body is a tube or a ring (a block's cells are
// -mesh_nt and -mesh_ntheta alone).
#define TF_TUBE_OPTIONS "-tube_ro -tube_t -mesh_density -mesh_wall_strain -mesh_nt_min -mesh_file"
// The contact's and friction's options (contact/friction_options.cpp): read where something touches.
#define TF_CONTACT_OPTIONS "-friction_mu -friction_vcri -friction_tol -rmin_dphi -rmin_dphi_rise"
// The error estimate's and the accuracy's options (driver/driver_options.cpp): read where the estimate runs.
#define TF_ESTIMATE_OPTIONS                                                                                            \
  "-error_estimate -error_estimate_factorization -target_load -target_c_over_t -expect_load -expect_c_over_t "         \
  "-target_levels -target_time"

std::unique_ptr<Scene> MakeAnySlideScene(const Options &opt)
{
  return OwnParams<SlideParams>(opt).tool == SlideTool::Arc ? MakeArcSlideScene(opt) : MakeSlideScene(opt);
}
} // namespace

const std::vector<SceneEntry> &SceneRegistry()
{
  // The options only some scenes read (`reads`): the V-die's, the tube's where the body is one, friction's where
  // something touches, the stroke, the punch speed and the output by stroke where something moves by it
  // (-dynamics_time in the scenes without tools), the release's and the stroke's path where tools let the tube go,
  // the error estimate's and the accuracy's where it runs (the tool scenes: main.cpp), each scene's own.
  static const std::vector<SceneEntry> scenes = {
    {"squaring", "quarter tube pressed by the upper 90-degree V-die (the paper's process)", MakeSquaringScene,
     ScenePress::Die,
     "-stroke -punch_speed -output_stroke -unload -springback -stroke_path -stroke_corner_radius " TF_V_DIE_OPTIONS
     " " TF_TUBE_OPTIONS " " TF_CONTACT_OPTIONS " " TF_ESTIMATE_OPTIONS},
    {"flattening", "quarter ring crushed by a flat plate", MakeFlatteningScene, ScenePress::Plate,
     "-stroke -punch_speed -output_stroke -unload -springback -stroke_path " TF_TUBE_OPTIONS " " TF_CONTACT_OPTIONS
     " " TF_ESTIMATE_OPTIONS},
    {"pressure", "quarter thick cylinder under internal pressure (Lame, Hill)", MakePressureScene, ScenePress::None,
     "-pressure_ -dynamics_time " TF_TUBE_OPTIONS, TF_OWN(Pressure)},
    {"shear", "simple shear of a block (Jaumann objectivity)", MakeShearScene, ScenePress::None,
     "-shear_ -dynamics_time", TF_OWN(Shear)},
    {"rotation", "a stressed block turned rigidly (objectivity)", MakeRotationScene, ScenePress::None,
     "-rotation_ -dynamics_time", TF_OWN(Rotation)},
    {"column", "a bowed strip shortened past its Euler load (geometric stiffness)", MakeColumnScene, ScenePress::None,
     "-column_ -dynamics_time -stroke -output_stroke", TF_OWN(Column)},
    {"tension", "plane-strain tension or compression of a block (flow curve)", MakeTensionScene, ScenePress::None,
     "-tension_ -dynamics_time", TF_OWN(Tension)},
    {"bending", "pure bending and unbending of a plane-strain strip (springback)", MakeBendingScene, ScenePress::None,
     "-bending_ -dynamics_time -springback", TF_OWN(Bending)},
    {"slide", "a block pushed along a floor, or a ring turned in a cylinder (-slide_tool arc): Coulomb friction",
     MakeAnySlideScene, ScenePress::None, "-slide_ -dynamics_time " TF_TUBE_OPTIONS " " TF_CONTACT_OPTIONS,
     TF_OWN(Slide)},
  };
  return scenes;
}
#undef TF_OWN
#undef TF_ESTIMATE_OPTIONS
#undef TF_CONTACT_OPTIONS
#undef TF_TUBE_OPTIONS
#undef TF_V_DIE_OPTIONS

std::vector<std::string> SceneNames()
{
  std::vector<std::string> names;
  for (const auto &s : SceneRegistry()) names.push_back(s.name);
  return names;
}

SceneOptionReaders SceneReaders()
{
  SceneOptionReaders readers;
  for (const auto &s : SceneRegistry()) readers.scenes.push_back({s.name, s.press, s.read, s.check});
  readers.tools = {ReadToolSceneOptions, CheckToolSceneOptions};
  readers.refuse_foreign = RefuseForeignOptions;
  return readers;
}

namespace {
// Whether the space-separated list `reads` names `option` (a name ending in '_' as a prefix; "<N>" in a name: any
// later pass's number, 2 to 9).
bool Lists(const std::string &reads, const std::string &option)
{
  std::istringstream words(reads);
  for (std::string w; words >> w;) {
    const size_t n = w.find("<N>");
    if (n != std::string::npos && option.size() == w.size() - 2 && option[n] >= '2' && option[n] <= '9')
      w.replace(n, 3, 1, option[n]);
    if (w.back() == '_' ? option.compare(0, w.size(), w) == 0 : option == w) return true;
  }
  return false;
}
} // namespace

std::string ReadersOf(const std::string &option, const std::vector<KnownOption> &known)
{
  std::string listed;
  for (const auto &s : SceneRegistry())
    if (Lists(s.reads, option)) listed += (listed.empty() ? "" : " ") + std::string(s.name);
  if (!listed.empty()) return listed;
  const auto k = std::find_if(known.begin(), known.end(), [&](const KnownOption &o) { return o.name == option; });
  return k == known.end() ? "" : k->scenes;
}

std::string ForeignOption(const std::string &scene, const std::string &option, const std::vector<KnownOption> &known)
{
  std::vector<std::string> readers;
  std::istringstream words(ReadersOf(option, known));
  for (std::string w; words >> w;) {
    if (w == scene) return "";
    readers.push_back(w);
  }
  if (readers.empty()) return "";
  std::string names;
  for (size_t k = 0; k < readers.size(); ++k)
    names += (k == 0 ? "" : k + 1 == readers.size() ? " and " : ", ") + readers[k];
  return "read by the " + names + (readers.size() > 1 ? " scenes" : " scene") + ", not by this run's " + scene +
         " scene (docs/scenes.md)";
}

PetscErrorCode RefuseForeignOptions(MPI_Comm comm, const Options &opt)
{
  char *all;
  PetscFunctionBeginUser;
  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::istringstream words(all);
  PetscCall(PetscFree(all));
  for (std::string w; words >> w;) {
    if (w.size() < 2 || w[0] != '-' || !std::isalpha((unsigned char)w[1])) continue; // (a value)
    for (char &c : w) c = (char)std::tolower((unsigned char)c);                      // (PETSc's names ignore case)
    const std::string why = ForeignOption(opt.scene, w, opt.known);
    if (!why.empty() && opt.allow_unused)
      PetscCall(
        PetscPrintf(comm, "tubeform: warning: %s: %s; -allow_unused: the run goes on\n", w.c_str(), why.c_str()));
    else
      PetscCheck(why.empty(), comm, PETSC_ERR_USER_INPUT, "%s: %s; -allow_unused runs anyway", w.c_str(), why.c_str());
  }
  // The cells a tube's mesh takes from its wall (-mesh_nt 0, -mesh_ntheta 0) ask for the tube's rules, which a block's
  // scene does not read: its cells are given.
  const bool tube = ForeignOption(opt.scene, "-mesh_wall_strain", opt.known).empty();
  PetscCheck(tube || (opt.mesh_nt > 0 && opt.mesh_ntheta > 0), comm, PETSC_ERR_USER_INPUT,
             "-mesh_nt %d, -mesh_ntheta %d: 0 takes a tube's cells from its wall (-mesh_wall_strain, -mesh_density); "
             "the %s scene's body is a block: give its cells (1 or more)",
             (int)opt.mesh_nt, (int)opt.mesh_ntheta, opt.scene.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

namespace {
// The titles of the -help blocks of `known` that only some scenes read, `scene` among them (every option of the
// block read by some scenes only, one of them by `scene`), in their order ("tubeform: " dropped), separated by "; ".
std::string OwnBlocks(const std::string &scene, const std::vector<KnownOption> &known)
{
  std::vector<std::string> titles, shared;
  for (const auto &k : known) {
    if (k.reader.empty()) continue;
    const std::string readers = ReadersOf(k.name, known);
    if (readers.empty()) shared.push_back(k.reader);
    if ((" " + readers + " ").find(" " + scene + " ") != std::string::npos &&
        std::find(titles.begin(), titles.end(), k.reader) == titles.end())
      titles.push_back(k.reader);
  }
  std::string joined;
  const std::string own = "tubeform: ";
  for (const auto &t : titles)
    if (std::find(shared.begin(), shared.end(), t) == shared.end())
      joined += (joined.empty() ? "" : "; ") + (t.rfind(own, 0) == 0 ? t.substr(own.size()) : t);
  return joined;
}
} // namespace

PetscErrorCode PrintSceneHelp(MPI_Comm comm, const std::vector<KnownOption> &known)
{
  PetscFunctionBeginUser;
  PetscCall((*PetscHelpPrintf)(comm, "tubeform: scenes:\n"));
  for (const auto &s : SceneRegistry()) {
    const std::string blocks = OwnBlocks(s.name, known);
    PetscCall((*PetscHelpPrintf)(comm, "  scene %s: %s; reads also: %s%s%s\n", s.name, s.what, s.reads,
                                 blocks.empty() ? "" : "; and the blocks: ", blocks.c_str()));
  }
  PetscCall((*PetscHelpPrintf)(comm, "----------------------------------------\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::unique_ptr<Scene> CreateScene(const Options &opt)
{
  for (const auto &s : SceneRegistry())
    if (opt.scene == s.name) return s.make(opt);
  return nullptr;
}

} // namespace tf
