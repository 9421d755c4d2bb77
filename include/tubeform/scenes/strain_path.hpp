// A piecewise linear path of one prescribed strain in the load parameter:
// first[0] at lambda 0, first[1] at lambda 1, then each further value one unit
// of lambda later (the tension scene's strain, the bending scene's outer
// fibre). The stages' ends are breakpoints, so that an increment's motion
// stays linear in its length.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "tubeform/scenes/scene.hpp"

namespace tf {

// Reversals -tension_cycle and -bending_cycle take at most.
constexpr PetscInt kMaxStrainCycle = 16;

class StrainPath {
public:
  StrainPath(double first, const std::vector<double> &then) : targets_{0.0, first}
  {
    targets_.insert(targets_.end(), then.begin(), then.end());
  }
  LoadPath Path(double duration) const
  {
    LoadPath path{(double)targets_.size() - 1, duration, {}, {}};
    for (size_t k = 1; k + 1 < targets_.size(); ++k) path.breakpoints.push_back((double)k);
    return path;
  }
  // The change of the strain over the increment lambda -> lambda + dlambda
  // (an increment stays within a stage: its end may be the stage's breakpoint).
  double Change(double lambda, double dlambda) const
  {
    const size_t k = std::min((size_t)(lambda + 0.5 * dlambda), targets_.size() - 2);
    return dlambda * (targets_[k + 1] - targets_[k]);
  }
  // The history's stage at lambda: 0 up to lambda 1 (the first strain), k in (k, k + 1].
  static double Stage(double lambda) { return lambda > 1 + kLambdaTol ? std::ceil(lambda - kLambdaTol) - 1 : 0; }
  double At(double lambda) const
  {
    const size_t k = std::min((size_t)std::max(lambda, 0.0), targets_.size() - 2);
    return targets_[k] + (lambda - (double)k) * (targets_[k + 1] - targets_[k]);
  }

private:
  std::vector<double> targets_; // the strain at lambda = 0, 1, 2, ...
};

} // namespace tf
