// libFuzzer target: the bytes as an options file (-options_file), inserted
// into a fresh PETSc options database and read by tf::ReadOptions with the
// scene registry's names, as a run does. When they are accepted, the scene is
// made and the material law is built from them (-material_table: the table
// flow curve) and driven through a few plastic updates. A PETSc error code is
// a clean outcome; only crashes, sanitizer reports and hangs are findings.
// Built with clang by tools/fuzz (TF_FUZZ=ON); the normal build links it to
// regression_driver.cpp, which runs tests/fuzz/regressions/options/* through it.
#include <dirent.h>
#include <petscsys.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tubeform/driver/driver_options.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/material/factory.hpp"
#include "tubeform/scenes/registry.hpp"

namespace {
std::string path;       // the options file the bytes are written to (one per process)
std::string last_error; // PETSc's message for the last input ("" when it was accepted)

PetscErrorCode Quiet(MPI_Comm, const char[], ...) { return 0; }
PetscErrorCode QuietError(const char[], ...) { return 0; }

bool Contains(const uint8_t *data, size_t size, const char *word)
{
  const size_t n = std::strlen(word);
  for (size_t i = 0; i + n <= size; ++i)
    if (std::memcmp(data + i, word, n) == 0) return true;
  return false;
}

// The accepted options made into what a run makes of them first: the scene
// and its load path, the material law, a point pulled past yield.
void UseOptions(const tf::Options &opt)
{
  auto scene = tf::CreateScene(opt);
  if (scene) {
    (void)scene->BoundarySets();
    (void)scene->Path(opt);
    (void)scene->ToolStroke(0.5);
  }
  auto law = tf::MakeMaterial(opt.material, opt.driver.rmin_deps, opt.driver.drift_correction);
  if (!law->plastic_law()) return;
  for (double ep : opt.material.table) (void)law->YieldStress(ep), (void)law->YieldStress(0.5 * ep);
  tf::PointState s;
  const double step = 2 * opt.material.sy / opt.material.E;
  for (int k = 0; k < 8; ++k) {
    const tf::Voigt deps = {step, -0.5 * step, 0, 0.1 * step};
    s.plastic = law->Loading(s, deps);
    (void)law->Update(s, deps);
  }
}

// PETSc 3.18's PetscOptionsInsertFile leaves the file open when it refuses a line (an error
// returned from inside its reading loop): close what it left, or the fuzzer runs out of descriptors.
void CloseLeftOpen()
{
  DIR *d = opendir("/proc/self/fd");
  if (!d) return;
  std::vector<int> left;
  char link[4096];
  for (dirent *e; (e = readdir(d));) {
    const std::string fd = std::string("/proc/self/fd/") + e->d_name;
    const ssize_t n = readlink(fd.c_str(), link, sizeof(link) - 1);
    if (n > 0 && std::string(link, n) == path) left.push_back(std::atoi(e->d_name));
  }
  closedir(d);
  for (int fd : left) close(fd);
}

PetscErrorCode ReadOnce()
{
  tf::Options opt;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInsertFile(PETSC_COMM_WORLD, nullptr, path.c_str(), PETSC_TRUE));
  PetscCall(tf::ReadOptions(PETSC_COMM_WORLD, tf::DriverOptions(), tf::SceneReaders(), opt));
  if (!opt.help) UseOptions(opt);
  PetscFunctionReturn(PETSC_SUCCESS);
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  // PETSc sees none of the fuzzer's arguments; its signal handler would hide the sanitizers' reports.
  static char name[] = "fuzz_options", nosig[] = "-no_signal_handler";
  static char *args[] = {name, nosig, nullptr};
  int n = 2;
  char **a = args;
  if (PetscInitialize(&n, &a, nullptr, nullptr)) return 1;
  (void)PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  PetscHelpPrintf = Quiet; // -help in the input: ReadOptions lists the options
  PetscErrorPrintf = QuietError;
  const char *dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  path = std::string(dir) + "/tf_fuzz_options_" + std::to_string(getpid()) + ".opts";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  last_error.clear();
  // PETSc reads files named in an options file (-options_file, YAML): not the parser under test, and a
  // file naming itself recurses without end.
  if (Contains(data, size, "options_file") || Contains(data, size, "yaml")) return 0;
  FILE *f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  if (size) std::fwrite(data, 1, size, f);
  std::fclose(f);
  PetscOptions db;
  if (PetscOptionsCreate(&db) || PetscOptionsPush(db)) return 0;
  const PetscErrorCode ierr = ReadOnce();
  if (ierr) {
    const char *text = nullptr;
    char *specific = nullptr;
    (void)PetscErrorMessage(ierr, &text, &specific);
    last_error = specific && specific[0] ? specific : (text ? text : "error");
  }
  (void)PetscOptionsPop();
  (void)PetscOptionsDestroy(&db);
  CloseLeftOpen();
  return 0;
}

extern "C" const char *TfFuzzLastError() { return last_error.c_str(); }

extern "C" void TfFuzzFinalize()
{
  unlink(path.c_str());
  (void)PetscFinalize();
}
