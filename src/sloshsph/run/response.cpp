#include "sloshsph/run/response.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "sloshsph/analysis/filter.hpp"
#include "sloshsph/analysis/steady_state.hpp"

namespace sloshsph {
namespace {

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

bool analysed_column(const std::string& name) {
  return starts_with(name, "eta:") || starts_with(name, "p:") || starts_with(name, "F_screen:") || name == "F_w" ||
         name == "F_sw" || name == "F_sw_y";
}

int column_index(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<int>(k);
  return -1;
}

}  // namespace

ResponseOptions response_options(const CaseSpec& spec, double water_mass, bool whole_tank) {
  const ExcitationSpec& e = spec.excitation;
  ResponseOptions o;
  o.period = 2.0 * std::numbers::pi / e.omega;
  o.cycles = spec.output.response_cycles;
  o.cutoff_hz = spec.output.lowpass_hz;
  o.water_mass = water_mass;
  o.amplitude = e.amplitude;
  o.energy = e.type == ExcitationType::harmonic;
  o.whole_tank = whole_tank;
  return o;
}

const ResponseValue* Response::find(const std::string& name) const {
  for (const ResponseValue& v : values)
    if (v.name == name) return &v;
  return nullptr;
}

Response steady_state_response(const std::vector<std::string>& names, const std::vector<std::string>& units,
                               const std::vector<std::vector<double>>& columns, const ResponseOptions& options) {
  Response r;
  r.whole_tank = options.whole_tank;
  const std::vector<double>& t = columns.front();
  if (!(options.period > 0.0) || t.size() < 3 || t.back() - t.front() < options.period) {
    r.note = "the record is shorter than one excitation period";
    return r;
  }
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  r.cutoff_hz = (options.cutoff_hz > 0.0 && options.cutoff_hz < 0.5 / dt) ? options.cutoff_hz : 0.0;
  for (std::size_t k = 1; k < names.size(); ++k) {
    if (!analysed_column(names[k])) continue;
    const SteadyAmplitude a = steady_state_amplitude(t, lowpass_if_resolved(columns[k], dt, r.cutoff_hz), options.period,
                                                     options.cycles);
    r.values.push_back({names[k], units[k], a.avg_max, a.avg_min});
    r.cycles = a.cycles;
  }
  // eq. 4.28 from the per-step work sum W_base when the run has it (exact pairing of force and
  // displacement, steady_state.hpp), else from the sampled F_w and x_base.
  const int work = column_index(names, "W_base");
  const int force = column_index(names, "F_w"), base = column_index(names, "x_base");
  std::optional<CycleEnergy> e;
  if (options.energy && work > 0) e = energy_per_cycle_from_work(t, columns[work], options.period, options.cycles);
  else if (options.energy && force > 0 && base > 0)
    e = energy_per_cycle(t, lowpass_if_resolved(columns[force], dt, r.cutoff_hz), columns[base], options.period, options.cycles);
  if (e) {
    r.energy_per_cycle = e->energy;
    if (options.water_mass > 0.0 && options.amplitude > 0.0)
      r.normalised_energy =
          normalised_energy(e->energy, options.water_mass, options.amplitude, 2.0 * M_PI / options.period);
  }
  return r;
}

nlohmann::json response_json(const Response& r) {
  nlohmann::json j;
  if (!r.note.empty()) {
    j["note"] = r.note;
    return j;
  }
  j["cycles"] = r.cycles;
  j["lowpass_cutoff_hz"] = r.cutoff_hz;
  nlohmann::json values = nlohmann::json::object();
  for (const ResponseValue& v : r.values) values[v.name] = {{"avg_max", v.avg_max}, {"avg_min", v.avg_min}, {"unit", v.unit}};
  j["steady_state"] = values;
  if (r.energy_per_cycle) j[r.whole_tank ? "energy_per_cycle_J" : "energy_per_cycle_J_per_m"] = *r.energy_per_cycle;
  if (r.normalised_energy) j["normalised_energy"] = *r.normalised_energy;
  return j;
}

std::string response_csv(const Response& r) {
  std::string out = "quantity,unit,avg_max,avg_min,value\n";
  char line[256];
  for (const ResponseValue& v : r.values) {
    std::snprintf(line, sizeof line, "%s,%s,%.9g,%.9g,\n", v.name.c_str(), v.unit.c_str(), v.avg_max, v.avg_min);
    out += line;
  }
  if (r.energy_per_cycle) {
    std::snprintf(line, sizeof line, "energy_per_cycle,%s,,,%.9g\n", r.whole_tank ? "J" : "J/m", *r.energy_per_cycle);
    out += line;
  }
  if (r.normalised_energy) {
    std::snprintf(line, sizeof line, "normalised_energy,1,,,%.9g\n", *r.normalised_energy);
    out += line;
  }
  return out;
}

}  // namespace sloshsph
