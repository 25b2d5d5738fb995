#include "sloshsph/run/probe_summary.hpp"

#include <algorithm>

#include "sloshsph/analysis/impact_peak.hpp"

namespace sloshsph {
namespace {

const std::vector<double>* find_column(const std::vector<std::string>& names,
                                       const std::vector<std::vector<double>>& columns, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return nullptr;
  const auto k = static_cast<std::size_t>(it - names.begin());
  return k < columns.size() ? &columns[k] : nullptr;
}

nlohmann::json impact_peak_json(const std::vector<double>* time, const std::vector<double>* pressure) {
  if (!time || !pressure) return nullptr;
  const std::optional<ImpactPeak> peak = first_impact_peak(*time, *pressure);
  if (!peak) return nullptr;
  return {{"baseline_Pa", peak->baseline}, {"peak_Pa", peak->value},          {"peak_time_s", peak->time},
          {"rise_start_s", peak->rise_start}, {"rise_end_s", peak->rise_end}, {"rise_time_s", peak->rise_time},
          {"end_s", peak->end},               {"impulse_Pa_s", peak->impulse}};
}

}  // namespace

template <int D>
nlohmann::json pressure_probes_summary(const std::vector<PressureProbeSpec>& probes,
                                       const std::vector<BasicPressureSensor<D>>& sensors,
                                       const std::vector<std::string>& names,
                                       const std::vector<std::vector<double>>& columns) {
  nlohmann::json out = nlohmann::json::array();
  const std::vector<double>* time = find_column(names, columns, "time");
  auto point = [](Vec<D> q) {
    nlohmann::json a = nlohmann::json::array();
    for (int k = 0; k < D; ++k) a.push_back(component(q, k));
    return a;
  };
  for (std::size_t k = 0; k < probes.size() && k < sensors.size(); ++k) {
    const BasicPressureSensor<D>& s = sensors[k];
    const std::string column = "p:" + probes[k].name;
    out.push_back({{"name", probes[k].name},
                   {"column", column},
                   {"from", point(s.from)},
                   {"to", point(s.to)},
                   {"face_length_m", s.face ? norm(s.to - s.from) : 0.0},
                   {"impact_peak", impact_peak_json(time, find_column(names, columns, column))}});
  }
  return out;
}

template nlohmann::json pressure_probes_summary<2>(const std::vector<PressureProbeSpec>&,
                                                   const std::vector<BasicPressureSensor<2>>&,
                                                   const std::vector<std::string>&,
                                                   const std::vector<std::vector<double>>&);
template nlohmann::json pressure_probes_summary<3>(const std::vector<PressureProbeSpec>&,
                                                   const std::vector<BasicPressureSensor<3>>&,
                                                   const std::vector<std::string>&,
                                                   const std::vector<std::vector<double>>&);

}  // namespace sloshsph
