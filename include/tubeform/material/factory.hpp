// The constitutive law of a run from its material parameters.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "tubeform/material/elastic.hpp"
#include "tubeform/material/hardening.hpp"

namespace tf {

// Hill 1948's F, G, H, L of the material (material/hill.hpp), none for von Mises.
std::optional<std::array<double, 4>> HillCoefficients(const MaterialParams &m);

// The flow curve of a plastic law ("ludwik", "swift", "table").
std::unique_ptr<Hardening> MakeHardening(const MaterialParams &m);

// law "elastic": linear elastic; "ludwik", "swift", "table": J2 plasticity
// with that flow curve. `dep_ref` is the plastic strain step over which H' is
// taken as a secant before a point has yielded once (the strain-limit step,
// -rmin_deps); `drift_correction` scales plastic stresses back onto the yield
// surface after each update. With hardening "chaboche" the backstresses of
// m.kinematic take their share of the flow curve (material/kinematic.hpp). `update`: the isotropic J2 law's
// plastic update, tangent or radial (the kinematic and Hill laws have the tangent update only: the options refuse
// radial with them); auto is resolved before (UpdateFor).
std::unique_ptr<Material> MakeMaterial(const MaterialParams &m, double dep_ref, bool drift_correction,
                                       PlasticUpdate update = PlasticUpdate::Tangent);
// The law MakeMaterial builds for `m`: the one place that tells them apart.
enum class LawKind { Elastic, KinematicJ2, Hill, IsotropicJ2 };
LawKind LawOf(const MaterialParams &m);
// The update a run asks for (-plastic_update) as MakeMaterial takes it: auto is the radial return for the isotropic
// J2 law with increments in equilibrium, the tangent update elsewhere (no return for the other laws; with the
// paper's forward increments K linearizes the tangent update: docs/theory.md, section 1, "Radial return").
PlasticUpdate UpdateFor(PlasticUpdate asked, LawKind law, bool equilibrium);

} // namespace tf
