#include "tubeform/io/options_files.hpp"

#include <dirent.h>

#include <fstream>
#include <sstream>
#include <vector>

#include "tubeform/core/option_reader.hpp"

namespace tf {

namespace {

// Options files naming each other deeper than this are taken as a loop.
constexpr int kMaxNesting = 16;
// A name this many edits from a file in the same folder is offered as a typo.
constexpr size_t kNearEdits = 2;

// A file in the folder of `path` whose name is within kNearEdits of its name.
std::string NearName(const std::string &path)
{
  const size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  std::string best;
  size_t best_d = kNearEdits + 1;
  if (DIR *d = opendir(dir.empty() ? "/" : dir.c_str())) {
    while (const dirent *e = readdir(d)) {
      const size_t dist = EditDistance(base, e->d_name);
      if (dist < best_d) best_d = dist, best = e->d_name;
    }
    closedir(d);
  }
  if (best.empty()) return "";
  return slash == std::string::npos ? best : dir + "/" + best;
}

// Checks `path` (named by `from`, or on the command line if empty) and the files it names.
std::string Check(const std::string &path, const std::string &from, int depth)
{
  const std::string where = from.empty() ? "" : " (named in " + from + ")";
  if (depth > kMaxNesting) return "-options_file " + path + where + ": options files name each other in a loop";
  std::ifstream in(path);
  if (!in.good()) {
    std::string msg = "-options_file " + path + where + ": no such file or not readable";
    const std::string near = NearName(path);
    if (!near.empty()) msg += "; did you mean " + near + "?";
    if (!from.empty())
      msg += " (options files name others relative to the working directory: run from the "
             "repository root)";
    return msg;
  }
  std::string line;
  while (std::getline(in, line)) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string word, next;
    while (words >> word)
      if (word == "-options_file" && words >> next) {
        const std::string err = Check(next, path, depth + 1);
        if (!err.empty()) return err;
      }
  }
  return "";
}

} // namespace

std::string CheckOptionsFiles(int argc, char **argv)
{
  for (int k = 1; k < argc; ++k) {
    if (std::string(argv[k]) != "-options_file") continue;
    if (k + 1 >= argc) return "-options_file: needs a file name";
    const std::string err = Check(argv[k + 1], "", 0);
    if (!err.empty()) return err;
  }
  return "";
}

} // namespace tf
