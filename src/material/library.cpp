#include "tubeform/material/library.hpp"

#include <dirent.h>

#include <algorithm>
#include <sstream>

#include "tubeform/core/text_file.hpp"

namespace tf {

namespace {

constexpr const char *kSuffix = ".opts";

bool EndsWith(const std::string &s, const std::string &tail)
{
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The options object of one file, destroyed however the reading ends.
struct FileOptions {
  PetscOptions o = nullptr;
  ~FileOptions() { (void)PetscOptionsDestroy(&o); }
};

// The options of `path` as rank 0 reads them (comments dropped), on every rank; `ok` false where it cannot. Read
// here rather than by PetscOptionsInsertFile, which stops on rank 0 alone at a malformed line (the others hang).
PetscErrorCode ReadText(MPI_Comm comm, const std::string &path, bool &ok, std::string &text)
{
  std::string raw;
  PetscFunctionBeginUser;
  PetscCall(ReadTextOnRoot(comm, path, ok, raw));
  text.clear();
  std::istringstream in(raw);
  std::string line;
  while (std::getline(in, line)) text += line.substr(0, line.find('#')) + " ";
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RequireReal(MPI_Comm comm, PetscOptions o, const std::string &file, const char *key, double &value)
{
  PetscReal v;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetReal(o, nullptr, key, &v, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT,
             "-material %s: the file does not set %s (a material file sets E, nu, "
             "sy, density, the law and its constants)",
             file.c_str(), key);
  value = v;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Reads the constants of the material file `file`, whose options are `text`, into `p`.
PetscErrorCode ReadFile(MPI_Comm comm, const std::string &file, const std::string &text, MaterialParams &p)
{
  FileOptions f;
  PetscBool set;
  char word[64] = "ludwik";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsCreate(&f.o));
  PetscCall(PetscOptionsInsertString(f.o, text.c_str()));
  PetscCall(PetscOptionsGetString(f.o, nullptr, "-material_law", word, sizeof word, &set));
  const auto law = std::find_if(std::begin(kFlowLawWords), std::end(kFlowLawWords),
                                [&](const char *w) { return std::string(w) == word; });
  std::string allowed;
  for (const char *w : kFlowLawWords) allowed += (allowed.empty() ? "" : ", ") + std::string(w);
  PetscCheck(law != std::end(kFlowLawWords), comm, PETSC_ERR_USER_INPUT,
             "-material %s: -material_law %s: allowed are %s", file.c_str(), word, allowed.c_str());
  p.law = static_cast<FlowLaw>(law - std::begin(kFlowLawWords));
  PetscCall(RequireReal(comm, f.o, file, "-material_e", p.E));
  PetscCall(RequireReal(comm, f.o, file, "-material_nu", p.nu));
  PetscCall(RequireReal(comm, f.o, file, "-material_density", p.density));
  if (p.law != FlowLaw::Elastic) PetscCall(RequireReal(comm, f.o, file, "-material_sy", p.sy));
  if (p.law == FlowLaw::Ludwik || p.law == FlowLaw::Swift) {
    PetscCall(RequireReal(comm, f.o, file, "-material_k", p.K));
    PetscCall(RequireReal(comm, f.o, file, "-material_n", p.n));
  }
  p.table.clear();
  if (p.law == FlowLaw::Table) {
    PetscReal table[kMaxTableNumbers];
    PetscInt n = kMaxTableNumbers;
    PetscCall(PetscOptionsGetRealArray(f.o, nullptr, "-material_table", table, &n, &set));
    PetscCheck(set && n >= 2, comm, PETSC_ERR_USER_INPUT, "-material %s: -material_law table needs -material_table",
               file.c_str());
    p.table.assign(table, table + n);
  }
  // Backstresses of the material (used with -hardening chaboche).
  PetscReal pairs[2 * kMaxBackstresses];
  PetscInt npairs = 2 * kMaxBackstresses;
  PetscCall(PetscOptionsGetRealArray(f.o, nullptr, "-material_kinematic", pairs, &npairs, &set));
  p.kinematic.assign(pairs, pairs + (set ? npairs : 0));
  // Hill's anisotropic yield (r-values, or F, G, H, L).
  PetscReal r[3], fghl[4];
  PetscInt nr = 3, nh = 4;
  PetscCall(PetscOptionsGetRealArray(f.o, nullptr, "-material_r", r, &nr, &set));
  p.lankford.assign(r, r + (set ? nr : 0));
  PetscCall(PetscOptionsGetRealArray(f.o, nullptr, "-material_hill", fghl, &nh, &set));
  p.hill.assign(fghl, fghl + (set ? nh : 0));
  // Whatever the file set that was not read above is not a material constant.
  PetscInt left;
  char **names, **values;
  PetscCall(PetscOptionsLeftGet(f.o, &left, &names, &values));
  const std::string stray = left > 0 ? std::string("-") + names[0] : "";
  PetscCall(PetscOptionsLeftRestore(f.o, &left, &names, &values));
  PetscCheck(stray.empty(), comm, PETSC_ERR_USER_INPUT,
             "-material %s: %s is not a constant of its -material_law %s (a material file sets -material_e, _nu, "
             "_density, _law, the law's _sy, _k, _n or _table, and _kinematic, _r or _hill)",
             file.c_str(), stray.c_str(), word);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

std::string MaterialLibraryDir(const std::string &dir) { return dir.empty() ? TF_MATERIAL_DIR : dir; }

std::vector<std::string> LibraryMaterials(const std::string &dir)
{
  std::vector<std::string> names;
  if (DIR *d = opendir(dir.c_str())) {
    while (const dirent *e = readdir(d)) {
      const std::string file = e->d_name;
      if (EndsWith(file, kSuffix) && file.size() > std::string(kSuffix).size())
        names.push_back(file.substr(0, file.size() - std::string(kSuffix).size()));
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

PetscErrorCode LoadMaterial(MPI_Comm comm, const std::string &name, const std::string &dir, MaterialParams &p)
{
  PetscFunctionBeginUser;
  if (name == kCustomMaterial) {
    p.name = name;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const bool path = name.find('/') != std::string::npos || EndsWith(name, kSuffix);
  const std::string file = path ? name : dir + "/" + name + kSuffix;
  bool ok = false;
  std::string text;
  PetscCall(ReadText(comm, file, ok, text));
  if (!ok && !path) {
    std::string list;
    for (const auto &m : LibraryMaterials(dir)) list += (list.empty() ? "" : ", ") + m;
    SETERRQ(comm, PETSC_ERR_USER_INPUT,
            "-material %s: not in the material library %s (it has: %s); or custom, or a file path (a .opts file)",
            name.c_str(), dir.c_str(), list.empty() ? "nothing readable" : list.c_str());
  }
  PetscCheck(ok, comm, PETSC_ERR_USER_INPUT, "-material %s: no such file or not readable", name.c_str());
  PetscCall(ReadFile(comm, file, text, p));
  p.name = name;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
