#pragma once
// The porous elements of a run as summary.json reports them (key `screens`): where each is, the
// parameters of its closure, and the loss coefficient it stands for, so that an Ergun screen, a
// Morison screen and the real slat screen can be compared by one number (docs/physics.md,
// "Porous screens").
#include <nlohmann/json.hpp>

#include "sloshsph/physics/porous.hpp"

namespace sloshsph {

// One object per element of `screens.elements`, in case order (explicit slats included):
//   every model: name, model ("ergun", "morison", "explicit"), solidity, porosity, from, to
//                ([x, y], m, clipped to the section), length_m, thickness_m, and
//                slat_screen_loss_coefficient (Baines & Peterson's C_l for the solidity; absent
//                when the solidity is 0, a Morison element given only its loss_coefficient);
//   ergun:       screen_particles, spacing_m, grain_diameter_m (D_c), interaction_radius_m,
//                permeability_m2 (K_P), velocity, equivalent_loss_coefficient
//                (ergun_inertial_loss_coefficient);
//   morison:     screen_particles, spacing_m, interaction_radius_m, velocity, loss_coefficient.
// In 3D (issue 31) also `rows_across` and `spacing_across_m` of each extruded element.
nlohmann::json screens_summary(const std::vector<ScreenElement>& elements);

}  // namespace sloshsph
