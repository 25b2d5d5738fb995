#include "sloshsph/run/tank_as_tmd.hpp"

#include <exception>
#include <numbers>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/cylinder_tank.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/linear/modal.hpp"
#include "sloshsph/run/structure_coupling.hpp"

namespace sloshsph {

namespace {

// Throws unless the structure's tanks act on it.
void require_tanks(const CaseSpec& spec, const StructureSpec& s) {
  if (s.tanks < 1)
    throw InputError(spec.where("structure.tanks"), "structure.tanks",
                     "tanks = 0: the liquid does not act on the structure, so it has no equivalent TMD");
}

// The TMD of `liquid` kg whose first mode holds `fraction` of it at `omega`, on the structure `s`,
// with `rigid` kg more moving rigidly with the tank; the area method's band is the noise load's,
// or 0.01-10 f_n.
TankAsTmd liquid_as_tmd(const StructureSpec& s, double liquid, double fraction, double omega, double rigid) {
  TankAsTmd t;
  t.liquid_mass = liquid;
  t.convective_fraction = fraction;
  t.tmd.structure = sdof_spec(s);
  t.tmd.convective_mass = fraction * liquid;
  t.tmd.rigid_mass = (1.0 - fraction) * liquid + rigid;
  t.tmd.convective_omega = omega;
  t.band_from_load = s.load.type == StructureLoadType::noise;
  const double fn = t.tmd.structure.natural_frequency();
  t.band_low = t.band_from_load ? s.load.band_low : 0.01 * fn;
  t.band_high = t.band_from_load ? s.load.band_high : 10.0 * fn;
  return t;
}

}  // namespace

TankAsTmd cylinder_as_tmd(const CaseSpec& spec, bool along_y) {
  const std::string key = along_y ? "structure.y" : "structure";
  const std::optional<StructureSpec>& mode = along_y ? spec.structure_y : spec.structure;
  if (!mode) throw InputError(spec.source, key, "the case has no [" + key + "]");
  require_tanks(spec, *mode);
  const double R = spec.tank.radius, h = spec.fill.depth, tanks = mode->tanks;
  return liquid_as_tmd(*mode, spec.fluid.density * std::numbers::pi * R * R * h * tanks,
                       cylinder_convective_mass_fraction(R, h), cylinder_first_sloshing_omega(R, h, spec.fluid.gravity),
                       mode->rigid_mass * tanks);
}

TankAsTmd tank_as_tmd(const CaseSpec& spec) {
  if (!spec.structure) throw InputError(spec.source, "structure", "the case has no [structure] to put a TMD on");
  const StructureSpec& s = *spec.structure;
  require_tanks(spec, s);
  const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
  const SloshingMode mode = sloshing_modes(tank, spec.fill.depth, spec.fluid.gravity, 1).front();
  const double width = s.tank_width * s.tanks;
  return liquid_as_tmd(s, spec.fluid.density * still_water_area(tank, spec.fill.depth) * width,
                       mode.effective_mass_fraction, mode.omega, s.rigid_mass * width);
}

nlohmann::json equivalent_tmd_json(const TankAsTmd& t, const std::vector<EquivalentTmdResponse>& responses,
                                   const EquivalentTmdResponse& optimum) {
  const SdofSpec& s = t.tmd.structure;
  nlohmann::json j = {{"liquid_mass_kg", t.liquid_mass},
                      {"convective_mass_fraction", t.convective_fraction},
                      {"convective_mass_kg", t.tmd.convective_mass},
                      {"rigid_mass_kg", t.tmd.rigid_mass},
                      {"mass_ratio", t.tmd.convective_mass / s.mass},
                      {"convective_frequency_Hz", t.tmd.convective_omega / (2.0 * std::numbers::pi)},
                      {"structure_frequency_Hz", s.natural_frequency()},
                      {"structure_damping_ratio", s.damping_ratio()},
                      {"tuning_ratio", t.tmd.convective_omega / s.angular_frequency()},
                      {"band_Hz", {t.band_low, t.band_high}},
                      {"band_from_load", t.band_from_load}};
  auto row = [](const EquivalentTmdResponse& r) {
    return nlohmann::json{{"tank_damping_ratio", r.zeta_tank},
                          {"effective_damping_ratio", r.effective_damping},
                          {"displacement_rms_ratio", r.displacement_rms_ratio},
                          {"acceleration_rms_ratio", r.acceleration_rms_ratio}};
  };
  j["responses"] = nlohmann::json::array();
  for (const EquivalentTmdResponse& r : responses) j["responses"].push_back(row(r));
  j["optimum"] = row(optimum);
  return j;
}

CaseSpec sway_section_case(const CaseSpec& spec, bool along_y) {
  const std::string key = along_y ? "structure.y" : "structure";
  if (spec.tank.shape == "cylinder")
    throw InputError(spec.where(key), key, "a cylinder has no 2D section for the linear estimate");
  if (along_y && spec.tank.shape != "rectangle")
    throw InputError(spec.where(key), key, "the linear estimate across the breadth needs a box (shape = \"rectangle\")");
  const std::optional<StructureSpec>& mode = along_y ? spec.structure_y : spec.structure;
  if (!mode) throw InputError(spec.source, key, "the case has no [" + key + "]");
  CaseSpec s = spec;
  s.tank.dimensions = 2;
  const double across = along_y ? spec.tank.length : spec.tank.breadth;  // the tank's other extent
  if (along_y) s.tank.length = spec.tank.breadth;
  s.structure = mode;
  s.structure->tank_width = across;
  s.structure->rigid_mass = mode->rigid_mass / across;
  s.structure_y.reset();
  s.excitation_y.reset();
  return s;
}

nlohmann::json equivalent_tmd_summary(const CaseSpec& spec, std::optional<double> measured_effective_damping,
                                      bool along_y) {
  try {
    const TankAsTmd t = spec.tank.shape == "cylinder" ? cylinder_as_tmd(spec, along_y)
                        : tank_as_tmd(spec.tank.dimensions == 3 ? sway_section_case(spec, along_y) : spec);
    nlohmann::json j = equivalent_tmd_json(t, {}, optimal_equivalent_tmd(t.tmd, t.band_low, t.band_high));
    j["method"] = "linear: mode 1 as a mass on a spring (structure/equivalent_tmd.hpp); screens and floors ignored";
    j["tank_damping_for_measured_effective_damping"] = nullptr;
    if (measured_effective_damping)
      if (const auto z = tank_damping_for_effective_damping(t.tmd, *measured_effective_damping, t.band_low, t.band_high))
        j["tank_damping_for_measured_effective_damping"] = *z;
    return j;
  } catch (const std::exception& e) {
    return {{"note", std::string("no linear estimate: ") + e.what()}};
  }
}

}  // namespace sloshsph
