// Isotropic hardening laws: the flow stress sigma_y as a function of the
// equivalent plastic strain ep (docs/theory.md, section 1).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace tf {

// The flow stress at recently seen plastic strains. Each point's ep is asked
// for several times an increment (scan, trial forces, commit), between the
// other points' asks, and pow was 9 % of a default run's time. Direct-mapped
// on the bits of ep: a hit returns the value the law computed for that very
// ep, so the results are the law's own, bit for bit.
class FlowMemo {
public:
  FlowMemo() { ep_.fill(std::numeric_limits<double>::quiet_NaN()); }
  template <class Law>
  double Get(double ep, const Law &law) const
  {
    std::uint64_t bits;
    std::memcpy(&bits, &ep, sizeof bits);
    const std::size_t slot = (bits * 0x9E3779B97F4A7C15ull) >> (64 - kSlotBits);
    if (ep_[slot] != ep) ep_[slot] = ep, sy_[slot] = law(ep);
    return sy_[slot];
  }

private:
  // 4096 slots (64 kB): a default run's 2,080 points and their trial strains, few collisions.
  static constexpr int kSlotBits = 12;
  mutable std::array<double, std::size_t(1) << kSlotBits> ep_, sy_;
};

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
  FlowMemo memo_;
};

// sigma_y = K (ep0 + ep)^n with ep0 = (sy0 / K)^(1/n), so that sigma_y(0) = sy0.
class SwiftHardening : public Hardening {
public:
  SwiftHardening(double sy0, double k, double n);
  double YieldStress(double ep) const override;

private:
  double k_, n_, ep0_;
  FlowMemo memo_;
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
