// Runs the inputs a fuzzer found (tests/fuzz/regressions/<target>/) through
// the fuzz target's LLVMFuzzerTestOneInput in the normal build, without
// libFuzzer: reliability_fuzz_* in tests/CMakeLists.txt.
//   regression_driver [--expect-error] DIR|FILE...
// Fails when there is no input, or with --expect-error when an input is
// accepted or its message is not one line. A crash fails the test by itself.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv);
extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern "C" const char *TfFuzzLastError();
extern "C" void TfFuzzFinalize();

int main(int argc, char **argv)
{
  bool expect_error = false;
  std::vector<std::string> inputs;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--expect-error") == 0) {
      expect_error = true;
      continue;
    }
    if (std::filesystem::is_directory(argv[k])) {
      for (const auto &e : std::filesystem::directory_iterator(argv[k]))
        if (e.is_regular_file()) inputs.push_back(e.path().string());
    } else
      inputs.emplace_back(argv[k]);
  }
  std::sort(inputs.begin(), inputs.end());
  if (inputs.empty()) {
    std::fprintf(stderr, "no input given\n");
    return 1;
  }
  if (LLVMFuzzerInitialize(&argc, &argv)) return 1;
  int bad = 0;
  for (const auto &name : inputs) {
    std::ifstream in(name, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t *>(bytes.data()), bytes.size());
    const std::string why = TfFuzzLastError();
    const bool ok = !expect_error || (!why.empty() && why.find_first_of("\r\n") == std::string::npos);
    std::printf("%s %s: %s\n", ok ? "ok  " : "FAIL", name.c_str(), why.empty() ? "(accepted)" : why.c_str());
    bad += !ok;
  }
  TfFuzzFinalize();
  std::printf("%zu passed, %d failed\n", inputs.size() - bad, bad);
  return bad ? 1 : 0;
}
