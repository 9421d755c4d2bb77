// Isotropic hardening laws: the flow stress sigma_y as a function of the
// equivalent plastic strain ep (METHOD.md section 1, Materials).
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace tf {

class Hardening {
public:
  virtual ~Hardening() = default;
  virtual double YieldStress(double ep) const = 0;
  // (sigma_y(ep + dep) - sigma_y(ep)) / dep: the hardening modulus H' over a
  // finite plastic strain step. Finite for dep > 0 even where H'(ep) is not
  // (Ludwik with n < 1 at ep = 0), and H' itself as dep -> 0.
  double SecantSlope(double ep, double dep) const { return (YieldStress(ep + dep) - YieldStress(ep)) / dep; }
};

// sigma_y = sy0 + K ep^n (the default; n = 1 is linear hardening, K = 0 perfect plasticity).
class LudwikHardening : public Hardening {
public:
  LudwikHardening(double sy0, double k, double n);
  double YieldStress(double ep) const override;

private:
  double sy0_, k_, n_, unyielded_; // unyielded_: the stress at ep = 0
  // The last ep and its stress: a point's checks of one increment ask for the
  // same ep several times in a row, and pow was 9 % of a default run's time.
  mutable double memo_ep_ = std::numeric_limits<double>::quiet_NaN(), memo_sy_ = 0;
};

// sigma_y = K (ep0 + ep)^n with ep0 = (sy0 / K)^(1/n), so that sigma_y(0) = sy0.
class SwiftHardening : public Hardening {
public:
  SwiftHardening(double sy0, double k, double n);
  double YieldStress(double ep) const override;

private:
  double k_, n_, ep0_;
  mutable double memo_ep_ = std::numeric_limits<double>::quiet_NaN(), memo_sy_ = 0; // as Ludwik's
};

// Piecewise linear through (ep_i, sigma_i), ep_0 = 0, constant past the last point.
class TableHardening : public Hardening {
public:
  TableHardening(std::vector<double> ep, std::vector<double> sy) : ep_(std::move(ep)), sy_(std::move(sy)) {}
  double YieldStress(double ep) const override;

private:
  std::vector<double> ep_, sy_;
};

} // namespace tf
