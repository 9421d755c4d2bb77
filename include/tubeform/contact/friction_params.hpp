// The tools' contact and friction parameters as the options give them (docs/theory.md, section 6): the tanh-Coulomb
// law's coefficient and quasi-stick slip, the friction iterations' tolerance and r6's bounds. Options holds one (so
// that they travel with the run's options to its levels and companions); the contact layer reads and checks them
// (contact/friction_options.hpp), and the scenes with tools hand them to the contact set as its ContactParams
// (scenes/contact_params.hpp).
#pragma once

#include "tubeform/contact/contact.hpp"

namespace tf {

struct FrictionParams {
  double mu = 0.05;                            // Coulomb coefficient (-friction_mu)
  double vcri = 0;                             // quasi-stick slip (mm); 0: 2 % of the circumferential element size
  double tol = ContactParams{}.tol;            // friction iterations: change of f_l / (mu f_n) between iterates
  double rmin_dphi = ContactParams{}.dphi_max; // r6: largest fall of f_l / (mu f_n) towards stick in an increment
  double rmin_dphi_rise = ContactParams{}.dphi_rise; // r6: largest rise of |f_l / (mu f_n)| (stick to slide)
};

} // namespace tf
