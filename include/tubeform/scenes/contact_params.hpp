// Contact parameters of the tool scenes from the options.
#pragma once

#include "tubeform/contact/contact.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// default_vcri is used when -friction_vcri is 0 (automatic).
inline ContactParams MakeContactParams(const Options &opt, double default_vcri)
{
  ContactParams prm;
  prm.mu = opt.friction.mu;
  prm.vcri = opt.friction.vcri > 0 ? opt.friction.vcri : default_vcri;
  prm.dphi_max = opt.friction.rmin_dphi;
  prm.dphi_rise = opt.friction.rmin_dphi_rise;
  prm.tol = opt.friction.tol;
  prm.group_tol = opt.driver.rmin_group_tol;
  prm.turn_max = opt.driver.rmin_domega; // (a tool's turn taken linear in a step as the body's rotations are)
  return prm;
}

} // namespace tf
