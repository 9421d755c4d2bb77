#include "tubeform/scenes/die.hpp"

#include <fstream>
#include <sstream>

#include "tubeform/tool/profile.hpp"

namespace tf {

PetscErrorCode BuildDie(MPI_Comm comm, const Options &opt, Die &die)
{
  PetscFunctionBeginUser;
  if (opt.die_profile.empty()) {
    const std::string error =
      MakeVDie(opt.tube_ro, opt.die_r_apex, opt.die_u_close, opt.die_r_edge, opt.die_angle, die.tool);
    PetscCheck(error.empty(), comm, PETSC_ERR_USER_INPUT,
               "-die_angle %g, -die_r_apex %g, -die_u_close %g, -die_r_edge %g make no die: %s", opt.die_angle,
               opt.die_r_apex, opt.die_u_close, opt.die_r_edge, error.c_str());
    die.flank = opt.die_r_apex > 0 ? 1 : 0;
    die.apex = die.flank - 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // Rank 0 reads the file; every rank parses the same text, so each reaches the same verdict.
  PetscMPIInt rank;
  long size = -1;
  std::string text;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::ifstream in(opt.die_profile);
    if (in) {
      std::ostringstream all;
      all << in.rdbuf();
      text = all.str();
      size = (long)text.size();
    }
  }
  PetscCallMPI(MPI_Bcast(&size, 1, MPI_LONG, 0, comm));
  PetscCheck(size >= 0, comm, PETSC_ERR_USER_INPUT, "-die_profile %s: cannot read the file", opt.die_profile.c_str());
  text.resize(size);
  if (size > 0) PetscCallMPI(MPI_Bcast(&text[0], (PetscMPIInt)size, MPI_CHAR, 0, comm));
  std::string error;
  const std::string &f = opt.die_profile;
  const bool dxf = f.size() > 4 && (f.compare(f.size() - 4, 4, ".dxf") == 0 || f.compare(f.size() - 4, 4, ".DXF") == 0);
  if (dxf) {
    std::vector<ProfileItem> items;
    error = DxfProfile(text, f, items);
    if (error.empty()) error = BuildProfile(items, f, die.tool);
  } else {
    error = ParseProfile(text, f, die.tool);
  }
  PetscCheck(error.empty(), comm, PETSC_ERR_USER_INPUT, "-die_profile %s", error.c_str());
  die.flank = LongestLine(die.tool);
  PetscCheck(die.flank >= 0, comm, PETSC_ERR_USER_INPUT,
             "-die_profile %s: no straight segment (C/t is measured against the profile's longest line)",
             opt.die_profile.c_str());
  die.apex = die.flank > 0 && die.tool.segments[die.flank - 1].kind == Segment::Arc ? die.flank - 1 : -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
