#include "tubeform/material/factory.hpp"

#include "tubeform/material/hardening.hpp"
#include "tubeform/material/hill.hpp"
#include "tubeform/material/j2.hpp"
#include "tubeform/material/kinematic.hpp"

namespace tf {

std::unique_ptr<Hardening> MakeHardening(const MaterialParams &m)
{
  std::unique_ptr<Hardening> h;
  if (m.law == FlowLaw::Ludwik)
    h = std::make_unique<LudwikHardening>(m.sy, m.K, m.n);
  else if (m.law == FlowLaw::Swift)
    h = std::make_unique<SwiftHardening>(m.sy, m.K, m.n);
  else {
    std::vector<double> ep, sy;
    for (size_t i = 0; i + 1 < m.table.size(); i += 2) ep.push_back(m.table[i]), sy.push_back(m.table[i + 1]);
    h = std::make_unique<TableHardening>(ep, sy);
  }
  return h;
}

std::optional<std::array<double, 4>> HillCoefficients(const MaterialParams &m)
{
  std::array<double, 4> fghl{0.5, 0.5, 0.5, 1.5}; // von Mises
  if (m.hill.size() == 4)
    fghl = {m.hill[0], m.hill[1], m.hill[2], m.hill[3]};
  else if (m.lankford.size() == 3)
    fghl = HillFromR(m.lankford[0], m.lankford[2]);
  if (fghl == std::array<double, 4>{0.5, 0.5, 0.5, 1.5}) return std::nullopt;
  return fghl;
}

LawKind LawOf(const MaterialParams &m)
{
  if (m.law == FlowLaw::Elastic) return LawKind::Elastic;
  if (m.hardening == HardeningRule::Chaboche && !m.kinematic.empty()) return LawKind::KinematicJ2;
  return HillCoefficients(m) ? LawKind::Hill : LawKind::IsotropicJ2;
}

std::unique_ptr<Material> MakeMaterial(const MaterialParams &m, double dep_ref, bool drift_correction,
                                       PlasticUpdate update)
{
  const LawKind kind = LawOf(m);
  if (kind == LawKind::Elastic) return std::make_unique<Elastic>(m.E, m.nu);
  std::unique_ptr<Hardening> h = MakeHardening(m);
  if (kind == LawKind::KinematicJ2) {
    std::vector<Backstress> back = Backstresses(m.kinematic);
    h = std::make_unique<RemainderHardening>(std::move(h), back);
    return std::make_unique<KinematicJ2>(m.E, m.nu, std::move(h), std::move(back), dep_ref, drift_correction);
  }
  if (kind == LawKind::Hill)
    return std::make_unique<HillPlasticity>(m.E, m.nu, std::move(h), *HillCoefficients(m), dep_ref, drift_correction);
  return std::make_unique<J2Plasticity>(m.E, m.nu, std::move(h), dep_ref, drift_correction, update);
}

PlasticUpdate UpdateFor(PlasticUpdate asked, LawKind law, bool equilibrium)
{
  if (asked != PlasticUpdate::Auto) return asked;
  return law == LawKind::IsotropicJ2 && equilibrium ? PlasticUpdate::Radial : PlasticUpdate::Tangent;
}

} // namespace tf
