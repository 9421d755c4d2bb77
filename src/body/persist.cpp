// The body's state between increments, for checkpoints: written and read by
// the same lines (src/driver/checkpoint.cpp).
#include <algorithm>

#include "tubeform/body/body.hpp"

namespace tf {

PetscErrorCode Body::Persist(Archive &ar)
{
  // Per point: stress (4), ep, hslope, plastic (and the backstresses below; an elastic release's law: the
  // material's own).
  constexpr int kPerPoint = kNumStress + 3;
  std::vector<double> points(kPerPoint * state_.size());
  bool elastic_only = law_ != nullptr, releasing = releasing_;

  PetscFunctionBeginUser;
  ar.Group("/body");
  for (size_t i = 0; i < state_.size() && !ar.reading(); ++i) {
    const PointState &p = state_[i];
    double *d = &points[kPerPoint * i];
    std::copy(p.sigma.begin(), p.sigma.end(), d);
    d[kNumStress] = p.ep, d[kNumStress + 1] = p.hslope, d[kNumStress + 2] = p.plastic;
  }
  PetscCall(ar.CellData("points", points, kPerPoint * fe::kGauss));
  // Kinematic hardening: each point's backstresses (4 components each).
  const int nback = material().backstresses(), kPerBack = kNumStress * nback;
  std::vector<double> back(kPerBack * state_.size());
  for (size_t i = 0; i < state_.size() && !ar.reading(); ++i)
    for (int b = 0; b < nback; ++b)
      std::copy(state_[i].back[b].begin(), state_[i].back[b].end(), &back[kPerBack * i + kNumStress * b]);
  if (nback > 0) PetscCall(ar.CellData("backstresses", back, kPerBack * fe::kGauss));
  // Anisotropic yield: each point's material axes.
  std::vector<double> frames(material().anisotropic() ? state_.size() : 0);
  for (size_t i = 0; i < frames.size() && !ar.reading(); ++i) frames[i] = state_[i].frame;
  if (!frames.empty()) PetscCall(ar.CellData("frames", frames, fe::kGauss));
  // qm6: the incompatible modes' condensation of each cell's last tangent.
  auto &cond = cells_.condensations();
  constexpr int kPerCell = fe::kInternal * fe::kDofs;
  std::vector<double> modes(kPerCell * cond.size());
  for (size_t e = 0; e < cond.size() && !ar.reading(); ++e)
    for (int k = 0; k < fe::kInternal; ++k)
      std::copy(cond[e][k].begin(), cond[e][k].end(), &modes[kPerCell * e + fe::kDofs * k]);
  if (!cond.empty()) PetscCall(ar.CellData("qm6_condensation", modes, kPerCell));
  for (size_t e = 0; e < cond.size() && ar.reading(); ++e)
    for (int k = 0; k < fe::kInternal; ++k)
      std::copy(&modes[kPerCell * e + fe::kDofs * k], &modes[kPerCell * e + fe::kDofs * (k + 1)], cond[e][k].begin());
  PetscCall(ar.NodeData("x", x_, 2));
  PetscCall(ar.NodeData("u", u_, 2));
  PetscCall(ar.Value("elastic_only", elastic_only));
  // A release under way: where each point's yield ratio and plastic strain stood at its start.
  PetscCall(ar.Value("releasing", releasing));
  std::vector<double> start = ar.reading() ? std::vector<double>(kReleaseStart * state_.size()) : release_start_;
  if (releasing) PetscCall(ar.CellData("release_start", start, kReleaseStart * fe::kGauss));
  if (!ar.reading()) PetscFunctionReturn(PETSC_SUCCESS);
  releasing_ = releasing, release_start_ = releasing ? start : std::vector<double>{};
  ActElastic(elastic_only);
  for (size_t i = 0; i < state_.size(); ++i) {
    PointState &p = state_[i];
    const double *d = &points[kPerPoint * i];
    std::copy(d, d + kNumStress, p.sigma.begin());
    p.ep = d[kNumStress], p.hslope = d[kNumStress + 1], p.plastic = d[kNumStress + 2] != 0;
    if (!frames.empty()) p.frame = frames[i];
    for (int b = 0; b < nback; ++b)
      std::copy(&back[kPerBack * i + kNumStress * b], &back[kPerBack * i + kNumStress * (b + 1)], p.back[b].begin());
  }
  StaleAll(); // new geometry and stresses
  geometry_.valid = false;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
