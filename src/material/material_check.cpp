// The validation of the material's constants, however they were given (the
// -material_* options, a material file, the library): each in its range, and
// in MPa (against each other: a modulus in Pa or GPa, a yield stress in Pa).
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "tubeform/core/core.hpp"
#include "tubeform/material/factory.hpp"
#include "tubeform/material/kinematic.hpp"
#include "tubeform/material/library.hpp"
#include "tubeform/material/material_options.hpp"

namespace tf {

namespace {

// Plastic strains the isotropic part of -hardening chaboche is checked up to (tube squaring stays far below).
constexpr double kKinematicCheckStrain = 2.0;
constexpr int kKinematicCheckPoints = 2000;

// -hardening chaboche: pairs of non-negative constants whose monotonic share
// stays below the flow curve (R(p) > 0), on a plastic law.
PetscErrorCode CheckKinematic(MPI_Comm comm, const MaterialParams &m)
{
  PetscFunctionBeginUser;
  if (m.hardening != HardeningRule::Chaboche) PetscFunctionReturn(PETSC_SUCCESS);
  const auto &k = m.kinematic;
  PetscCheck(m.law != FlowLaw::Elastic, comm, PETSC_ERR_USER_INPUT,
             "-hardening chaboche: needs a plastic -material_law (ludwik, swift, table), not elastic");
  PetscCheck(!k.empty() && k.size() % 2 == 0, comm, PETSC_ERR_USER_INPUT,
             "-hardening chaboche needs -material_kinematic C1,gamma1[,C2,gamma2[,C3,gamma3]] (pairs; got %d numbers)",
             (int)k.size());
  for (size_t i = 0; i < k.size(); i += 2)
    PetscCheck(k[i] > 0 && k[i + 1] >= 0 && std::isfinite(k[i]) && std::isfinite(k[i + 1]), comm, PETSC_ERR_USER_INPUT,
               "-material_kinematic: C %g, gamma %g: need C > 0 and gamma >= 0", k[i], k[i + 1]);
  const RemainderHardening rest(MakeHardening(m), Backstresses(k));
  for (int i = 0; i <= kKinematicCheckPoints; ++i) {
    const double p = kKinematicCheckStrain * i / kKinematicCheckPoints, r = rest.YieldStress(p);
    PetscCheck(r > 0, comm, PETSC_ERR_USER_INPUT,
               "-material_kinematic: the backstresses outgrow the flow curve at plastic strain %g (its isotropic "
               "part would be %g MPa): lower C or raise gamma",
               p, r);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Hill 1948: positive r-values or F, G, H, L whose quadratic form is positive on deviators; with isotropic hardening.
PetscErrorCode CheckHill(MPI_Comm comm, const MaterialParams &m)
{
  PetscFunctionBeginUser;
  PetscCheck(m.lankford.empty() || m.hill.empty(), comm, PETSC_ERR_USER_INPUT,
             "-material_r and -material_hill: give one of the two");
  PetscCheck(m.lankford.empty() || m.lankford.size() == 3, comm, PETSC_ERR_USER_INPUT,
             "-material_r: give r0,r45,r90 (got %d numbers)", (int)m.lankford.size());
  for (double r : m.lankford)
    PetscCheck(r > 0 && std::isfinite(r), comm, PETSC_ERR_USER_INPUT, "-material_r: %g: r-values must be positive", r);
  PetscCheck(m.hill.empty() || m.hill.size() == 4, comm, PETSC_ERR_USER_INPUT,
             "-material_hill: give F,G,H,L (got %d numbers)", (int)m.hill.size());
  if (m.hill.size() == 4) {
    const double f = m.hill[0], g = m.hill[1], h = m.hill[2], l = m.hill[3];
    PetscCheck(f * g + g * h + h * f > 0 && f + g > 0 && g + h > 0 && h + f > 0 && l > 0, comm, PETSC_ERR_USER_INPUT,
               "-material_hill %g,%g,%g,%g: need FG + GH + HF > 0, F + G, G + H, H + F > 0 and L > 0 (a closed yield "
               "surface)",
               f, g, h, l);
  }
  PetscCheck(!HillCoefficients(m) || m.hardening == HardeningRule::Isotropic, comm, PETSC_ERR_USER_INPUT,
             "-hardening chaboche with Hill's yield (-material_r, -material_hill): not available; use one of the two");
  PetscFunctionReturn(PETSC_SUCCESS);
}

// E / sigma_y0 of metals runs from about 100 (maraging steel 190000 / 1900 MPa, beta titanium 100000 / 1200) to
// about 3500 (annealed pure copper 117000 / 33, lead 16000 / 5): a factor of 2 beyond both, and a modulus in Pa,
// kPa or GPa where MPa is meant, or a yield stress in Pa, lies a factor of 20 or more outside.
constexpr double kMinModulusRatio = 50, kMaxModulusRatio = 5000;
// The flow stress at this plastic strain stays below E / kMinHardenedRatio: metals reach at most E / 50 (maraging
// steel's tensile strength); a Ludwik or Swift K in Pa passes E at once.
constexpr double kHardenedCheckStrain = 0.2, kMinHardenedRatio = 10;
// Mass densities (t/mm^3) from about 1e-9 (polymers, magnesium 1.74e-9) to 2.3e-8 (osmium): a factor of 10
// beyond both; kg/m^3 or g/cm^3 where t/mm^3 is meant lie orders outside.
constexpr double kMinDensity = 1e-10, kMaxDensity = 2e-7;
// No solid is stiffer than diamond (1.05e6 MPa): above this, E is not in MPa (whatever the law, the elastic one too).
constexpr double kMaxModulus = 2e6;

// A plastic law's E against its initial yield stress (in tension along each of Hill's axes): the message of a
// ratio outside kMinModulusRatio to kMaxModulusRatio, or "".
std::string ModulusAgainstYield(const MaterialParams &m, const Hardening &curve)
{
  const double sy0 = curve.YieldStress(0);
  const bool hill = HillCoefficients(m).has_value();
  const std::string from =
    std::string(m.law == FlowLaw::Table ? "the first stress of -material_table" : "-material_sy") +
    (!hill            ? ""
     : m.hill.empty() ? ", -material_r"
                      : ", -material_hill") +
    (m.name == kCustomMaterial ? std::string() : ", -material " + m.name);
  // sigma_eq of unit tension along the axes (1 axial, 2 hoop, 3 radial): Hill's sqrt(G + H), ...; von Mises 1.
  std::array<double, 3> unit = {1, 1, 1};
  if (const auto h = HillCoefficients(m))
    unit = {std::sqrt((*h)[1] + (*h)[2]), std::sqrt((*h)[0] + (*h)[2]), std::sqrt((*h)[0] + (*h)[1])};
  const char *const axis[] = {", in tension along the tube", ", in tension around it (hoop)",
                              ", in tension through the wall"};
  char msg[512] = ""; // (printf's numbers: PETSc's own %g writes 5000 as "5000.")
  for (int i = 0; i < 3 && !msg[0]; ++i) {
    const double yield = sy0 / unit[i], ratio = m.E / yield;
    if (!(ratio >= kMinModulusRatio && ratio <= kMaxModulusRatio))
      snprintf(msg, sizeof msg,
               "-material_e %g against the initial yield stress %g MPa (%s%s): E / sigma_y0 = %.4g lies outside %g "
               "to %g (metals: 100 to 3500); give both in MPa (E of aluminum 70000, of steel 210000)",
               m.E, yield, from.c_str(), hill ? axis[i] : "", ratio, kMinModulusRatio, kMaxModulusRatio);
  }
  return msg;
}

// The constants in MPa and t/mm^3: E against the law's initial yield stress, E at most kMaxModulus (the elastic law
// too, and stresses all in Pa), the flow stress at a plastic strain of kHardenedCheckStrain below E /
// kMinHardenedRatio (a K in Pa), the density.
PetscErrorCode CheckUnits(MPI_Comm comm, const MaterialParams &m)
{
  std::unique_ptr<Hardening> curve;
  std::string why;
  char msg[512] = "";
  PetscFunctionBeginUser;
  if (m.law != FlowLaw::Elastic) curve = MakeHardening(m), why = ModulusAgainstYield(m, *curve);
  if (why.empty() && m.E > kMaxModulus)
    snprintf(msg, sizeof msg,
             "-material_e %g: stiffer than any solid (diamond: 1.05e6 MPa); give E in MPa (aluminum 70000, steel "
             "210000)",
             m.E);
  const double hardened = curve ? curve->YieldStress(kHardenedCheckStrain) : 0;
  if (why.empty() && !msg[0] && !(hardened <= m.E / kMinHardenedRatio)) {
    char k[64] = "-material_table";
    if (m.law != FlowLaw::Table) snprintf(k, sizeof k, "-material_k %g", m.K);
    snprintf(msg, sizeof msg,
             "%s: the flow stress at a plastic strain of %g is %g MPa, above E / %g = %g MPa (metals stay below E / "
             "50); give it in MPa",
             k, kHardenedCheckStrain, hardened, kMinHardenedRatio, m.E / kMinHardenedRatio);
  }
  if (why.empty() && !msg[0] && !(m.density >= kMinDensity && m.density <= kMaxDensity))
    snprintf(msg, sizeof msg,
             "-material_density %g: outside %g to %g t/mm^3; give it in t/mm^3 (aluminum 2.70e-9, steel 7.85e-9: "
             "kg/m^3 x 1e-12)",
             m.density, kMinDensity, kMaxDensity);
  if (why.empty()) why = msg;
  PetscCheck(why.empty(), comm, PETSC_ERR_USER_INPUT, "%s", why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode CheckMaterial(MPI_Comm comm, const MaterialParams &m)
{
  PetscFunctionBeginUser;
  PetscCheck(m.E > 0, comm, PETSC_ERR_USER_INPUT, "-material_e %g: Young's modulus must be positive (MPa)", m.E);
  PetscCheck(m.nu > -1 && m.nu < 0.5, comm, PETSC_ERR_USER_INPUT,
             "-material_nu %g: Poisson's ratio must lie in (-1, 0.5)", m.nu);
  PetscCheck(m.sy > 0, comm, PETSC_ERR_USER_INPUT, "-material_sy %g: the yield stress must be positive (MPa)", m.sy);
  PetscCheck(m.K >= 0, comm, PETSC_ERR_USER_INPUT,
             "-material_k %g: the hardening coefficient must be non-negative (MPa)", m.K);
  PetscCheck(m.n > 0 && m.n <= 1, comm, PETSC_ERR_USER_INPUT,
             "-material_n %g: the hardening exponent must lie in (0, 1]", m.n);
  PetscCheck(m.density > 0 && std::isfinite(m.density), comm, PETSC_ERR_USER_INPUT,
             "-material_density %g: the mass density must be positive (t/mm^3; aluminum 2.70e-9)", m.density);
  if (m.law == FlowLaw::Swift)
    PetscCheck(m.K > 0, comm, PETSC_ERR_USER_INPUT, "-material_k %g: the Swift law needs K > 0", m.K);
  if (m.law == FlowLaw::Table) {
    const auto &t = m.table;
    PetscCheck(t.size() >= 2 && t.size() % 2 == 0, comm, PETSC_ERR_USER_INPUT,
               "-material_table: give pairs ep,sigma_y (at least one pair) for -material_law table");
    PetscCheck(t[0] == 0, comm, PETSC_ERR_USER_INPUT, "-material_table: the first plastic strain must be 0 (got %g)",
               t[0]);
    for (size_t i = 2; i < t.size(); i += 2) {
      PetscCheck(t[i] > t[i - 2], comm, PETSC_ERR_USER_INPUT,
                 "-material_table: plastic strains must increase (%g after %g)", t[i], t[i - 2]);
      PetscCheck(t[i + 1] >= t[i - 1], comm, PETSC_ERR_USER_INPUT,
                 "-material_table: the flow stress must not decrease (%g after %g)", t[i + 1], t[i - 1]);
    }
    PetscCheck(t[1] > 0, comm, PETSC_ERR_USER_INPUT,
               "-material_table: the initial yield stress must be positive (got %g)", t[1]);
  }
  PetscCall(CheckKinematic(comm, m));
  PetscCall(CheckHill(comm, m));
  PetscCall(CheckUnits(comm, m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
