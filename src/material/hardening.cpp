#include "tubeform/material/hardening.hpp"

#include <algorithm>
#include <cmath>

namespace tf {

LudwikHardening::LudwikHardening(double sy0, double k, double n)
    : sy0_(sy0), k_(k), n_(n), unyielded_(sy0 + k * std::pow(0.0, n))
{}

double LudwikHardening::YieldStress(double ep) const
{
  if (ep <= 0) return unyielded_; // (never yielded: most points of a run)
  return memo_.Get(ep, [this](double e) { return sy0_ + k_ * std::pow(e, n_); });
}

SwiftHardening::SwiftHardening(double sy0, double k, double n) : k_(k), n_(n), ep0_(std::pow(sy0 / k, 1.0 / n)) {}

double SwiftHardening::YieldStress(double ep) const
{
  const double e = std::max(ep, 0.0);
  return memo_.Get(e, [this](double x) { return k_ * std::pow(ep0_ + x, n_); });
}

double TableHardening::YieldStress(double ep) const
{
  if (ep <= ep_.front()) return sy_.front();
  if (ep >= ep_.back()) return sy_.back();
  const size_t i = std::upper_bound(ep_.begin(), ep_.end(), ep) - ep_.begin(); // ep_[i-1] <= ep < ep_[i]
  const double w = (ep - ep_[i - 1]) / (ep_[i] - ep_[i - 1]);
  return (1 - w) * sy_[i - 1] + w * sy_[i];
}

} // namespace tf
