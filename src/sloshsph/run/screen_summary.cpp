#include "sloshsph/run/screen_summary.hpp"

namespace sloshsph {

namespace {

// The keys shared by the two macroscopic closures: how the element is discretised.
void add_screen_particles(nlohmann::json& j, const ScreenElement& e) {
  j["screen_particles"] = e.count;
  j["spacing_m"] = e.spacing;
  j["interaction_radius_m"] = e.smoothing_length;
  j["velocity"] = e.shepard_velocity ? "shepard" : "thesis";
  if (e.spacing_across > 0.0) {  // 3D: extruded over the breadth (or, in the plane y = plane_y, the length)
    j["rows_across"] = e.count_across;
    j["spacing_across_m"] = e.spacing_across;
  }
  if (e.plane_y) j["plane_y_m"] = *e.plane_y;  // from, to: its vertical column, repeated along x
  if (e.plan) {  // from, to: its vertical column, repeated along the plan segment
    j["plan_from_m"] = {e.plan->first.x, e.plan->first.y};
    j["plan_to_m"] = {e.plan->second.x, e.plan->second.y};
  }
}

}  // namespace

nlohmann::json screens_summary(const std::vector<ScreenElement>& elements) {
  nlohmann::json out = nlohmann::json::array();
  for (const ScreenElement& e : elements) {
    nlohmann::json j = {{"name", e.name},
                        {"model", screen_model_name(e.model)},
                        {"solidity", e.solidity},
                        {"porosity", e.porosity},
                        {"from", {e.from.x, e.from.y}},
                        {"to", {e.to.x, e.to.y}},
                        {"length_m", e.length},
                        {"thickness_m", e.thickness}};
    if (e.solidity > 0.0) j["slat_screen_loss_coefficient"] = slat_screen_loss_coefficient(e.solidity);
    if (e.model == ScreenModel::ergun) {
      add_screen_particles(j, e);
      j["grain_diameter_m"] = e.nominal_spacing;  // D_c = dp_sc (thesis 2.5.2)
      j["permeability_m2"] = e.permeability;
      j["equivalent_loss_coefficient"] = ergun_inertial_loss_coefficient(e.permeability, e.porosity, e.thickness);
    } else if (e.model == ScreenModel::morison) {
      add_screen_particles(j, e);
      j["loss_coefficient"] = e.loss_coefficient;
    }
    out.push_back(j);
  }
  return out;
}

}  // namespace sloshsph
