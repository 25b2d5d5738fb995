#include "sloshsph/run/modes_summary.hpp"

#include <algorithm>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {
namespace {

// The tank damping ratios of the estimate: a fixed spread, the user's, and the optimum last.
std::vector<EquivalentTmdResponse> tmd_responses(const TankAsTmd& t, std::vector<double> zetas) {
  for (double z : {0.005, 0.01, 0.02, 0.03, 0.05, 0.10}) zetas.push_back(z);
  std::sort(zetas.begin(), zetas.end());
  zetas.erase(std::unique(zetas.begin(), zetas.end()), zetas.end());
  std::vector<EquivalentTmdResponse> out;
  for (double z : zetas) out.push_back(equivalent_tmd_response(t.tmd, z, t.band_low, t.band_high));
  out.push_back(optimal_equivalent_tmd(t.tmd, t.band_low, t.band_high));
  return out;
}

}  // namespace

ModesSummary modes_summary(const CaseSpec& spec, int count, const std::vector<double>& tank_damping,
                           double frequency_scale) {
  ModesSummary m;
  const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
  m.modes = sloshing_modes(tank, spec.fill.depth, spec.fluid.gravity, count);
  m.frequency_scale = frequency_scale;
  const bool coupled = spec.structure && spec.structure->tanks > 0;
  if (!coupled && (!tank_damping.empty() || frequency_scale != 1.0))
    throw InputError(spec.source, "structure",
                     "--tank-damping and --tank-frequency-scale need a case whose [structure] carries "
                     "the tanks (tanks >= 1)");
  if (coupled) {
    m.tmd = tank_as_tmd(spec);
    m.tmd->tmd.convective_omega *= frequency_scale;
    m.responses = tmd_responses(*m.tmd, tank_damping);
  }
  return m;
}

nlohmann::json modes_json(const ModesSummary& m) {
  nlohmann::json j;
  j["modes"] = nlohmann::json::array();
  for (const SloshingMode& mode : m.modes)
    j["modes"].push_back({{"omega", mode.omega},
                          {"frequency", mode.frequency},
                          {"effective_mass_fraction", mode.effective_mass_fraction}});
  if (m.tmd) {
    j["equivalent_tmd"] = equivalent_tmd_json(
        *m.tmd, std::vector<EquivalentTmdResponse>(m.responses.begin(), m.responses.end() - 1), m.responses.back());
    j["equivalent_tmd"]["frequency_scale"] = m.frequency_scale;
  }
  return j;
}

}  // namespace sloshsph
