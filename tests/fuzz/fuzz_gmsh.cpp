// libFuzzer target: the bytes as a Gmsh mesh file, read by tf::ReadGmsh and
// then checked by SerialMesh::validate, as a run reads -mesh_file. Built with
// clang by tools/fuzz (TF_FUZZ=ON); the normal build links it to
// regression_driver.cpp, which runs tests/fuzz/regressions/gmsh/* through it.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "tubeform/mesh/gmsh_reader.hpp"
#include "tubeform/mesh/serial_mesh.hpp"

namespace {
std::string path;       // the file the bytes are written to (one per process)
std::string last_error; // the verdict of the last input ("" when it was read and is valid)
} // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  const char *dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  path = std::string(dir) + "/tf_fuzz_gmsh_" + std::to_string(getpid()) + ".msh";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  FILE *f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  if (size) std::fwrite(data, 1, size, f);
  std::fclose(f);
  tf::SerialMesh mesh;
  last_error = tf::ReadGmsh(path, mesh);
  if (!last_error.empty()) return 0;
  // As the driver does (Problem::Setup): the mesh checked, its verdict naming the file.
  const std::string why = mesh.validate({tf::kBoundaryNames.begin(), tf::kBoundaryNames.end()});
  if (!why.empty()) last_error = "-mesh_file " + path + ": " + why;
  return 0;
}

extern "C" const char *TfFuzzLastError() { return last_error.c_str(); }

extern "C" void TfFuzzFinalize() { unlink(path.c_str()); }
