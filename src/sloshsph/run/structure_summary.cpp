#include "sloshsph/run/structure_summary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "sloshsph/analysis/admittance.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/io/csv_writer.hpp"
#include "sloshsph/run/structure_coupling.hpp"
#include "sloshsph/signals/time_series.hpp"

namespace sloshsph {
namespace {

constexpr double kMilliG = 1.0e-3 * kStandardGravity;  // m/s^2 (thesis 4.4.2.1: 0.001 of g)

const char* load_name(StructureLoadType t) {
  switch (t) {
    case StructureLoadType::none: return "none";
    case StructureLoadType::harmonic: return "harmonic";
    case StructureLoadType::noise: return "noise";
    case StructureLoadType::record: return "record";
    case StructureLoadType::pulse: return "pulse";
  }
  return "none";
}

// The samples at t >= skip (the start-up left out).
std::vector<double> after(const std::vector<double>& t, const std::vector<double>& x, double skip) {
  std::vector<double> out;
  for (std::size_t i = 0; i < t.size() && i < x.size(); ++i)
    if (t[i] >= skip - 1e-12) out.push_back(x[i]);
  return out;
}

// A uniform grid over the kept part of the record, at the median sample interval.
struct UniformGrid {
  double t0 = 0.0, dt = 0.0;
  std::size_t n = 0;
};

UniformGrid uniform_grid(const std::vector<double>& t, double skip) {
  std::vector<double> steps;
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    if (t[i] >= skip - 1e-12 && t[i + 1] > t[i]) steps.push_back(t[i + 1] - t[i]);
  UniformGrid g;
  if (steps.empty()) return g;
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  g.dt = steps[steps.size() / 2];
  g.t0 = std::max(skip, t.front());
  g.n = static_cast<std::size_t>(std::floor((t.back() - g.t0) / g.dt + 1e-9)) + 1;
  return g;
}

// The series linearly interpolated on the grid (TimeSeries::sample is zero outside, so the
// grid stays inside [t.front(), t.back()]).
std::vector<double> resample(const std::vector<double>& t, const std::vector<double>& x, const UniformGrid& g) {
  TimeSeries s;
  // Drop repeated times (a failed run writes its last row twice) so the series is increasing.
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!s.t.empty() && t[i] <= s.t.back()) continue;
    s.t.push_back(t[i]);
    s.value.push_back(x[i]);
  }
  std::vector<double> out(g.n);
  for (std::size_t k = 0; k < g.n; ++k) out[k] = sample(s, std::min(g.t0 + k * g.dt, s.t.back()));
  return out;
}

nlohmann::json rms_and_peak(const std::vector<double>& x, const char* unit) {
  return {{std::string("rms_") + unit, rms(x)}, {std::string("peak_") + unit, peak_abs(x)}};
}

// "displacement" and "acceleration" (RMS and peak; the acceleration also in milli-g) of a motion.
void add_motion(nlohmann::json& j, const std::vector<double>& x, const std::vector<double>& acc) {
  j["displacement"] = rms_and_peak(x, "m");
  j["acceleration"] = rms_and_peak(acc, "m_s2");
  j["acceleration"]["rms_milli_g"] = rms(acc) / kMilliG;
  j["acceleration"]["peak_milli_g"] = peak_abs(acc) / kMilliG;
}

}  // namespace

StructureSeries structure_series(const std::vector<std::string>& names, const std::vector<std::vector<double>>& columns,
                                 const std::string& gauge, const std::string& suffix) {
  auto column = [&](const std::string& name) -> const std::vector<double>* {
    for (std::size_t k = 0; k < names.size() && k < columns.size(); ++k)
      if (names[k] == name) return &columns[k];
    return nullptr;
  };
  StructureSeries s;
  for (const std::string& name : {std::string("time"), "x_s" + suffix, "a_s" + suffix, "F_e" + suffix})
    if (!column(name)) throw std::invalid_argument("structure summary: no column '" + name + "'");
  s.time = *column("time");
  s.x_s = *column("x_s" + suffix);
  s.a_s = *column("a_s" + suffix);
  s.F_e = *column("F_e" + suffix);
  if (!gauge.empty()) {
    const auto* eta = column("eta:" + gauge);
    if (!eta) throw std::invalid_argument("structure summary: no wave gauge column 'eta:" + gauge + "'");
    s.eta = *eta;
    s.eta_name = gauge;
  } else {
    for (std::size_t k = 0; k < names.size() && k < columns.size(); ++k)
      if (names[k].rfind("eta:", 0) == 0) {
        s.eta = columns[k];
        s.eta_name = names[k].substr(4);
        break;
      }
  }
  return s;
}

StructureAloneResponse structure_alone_response(const StructureSeries& s, const StructureSpec& spec) {
  StructureAloneResponse out;
  if (s.time.empty()) return out;
  const bool ground = !s.ground_acceleration.empty();
  auto ground_at = [&](std::size_t k) { return ground ? s.ground_acceleration[k] : 0.0; };
  Sdof sdof(sdof_spec(spec));
  sdof.set_state(spec.initial_displacement, spec.initial_velocity, s.F_e[0], ground_at(0));
  const double max_substep = 0.01 / sdof.spec().angular_frequency();
  auto record = [&] {
    out.x.push_back(sdof.displacement());
    out.a.push_back(sdof.absolute_acceleration());
  };
  record();
  for (std::size_t k = 1; k < s.time.size(); ++k) {
    const double interval = s.time[k] - s.time[k - 1];
    if (interval > 0.0) {  // a repeated row (the last of a failed run) adds no step
      const int substeps = std::max(1, static_cast<int>(std::ceil(interval / max_substep)));
      for (int j = 1; j <= substeps; ++j) {
        const double w = static_cast<double>(j) / substeps;  // Newmark takes the load at the step's end
        sdof.step(interval / substeps, (1.0 - w) * s.F_e[k - 1] + w * s.F_e[k],
                  (1.0 - w) * ground_at(k - 1) + w * ground_at(k));
      }
    }
    record();
  }
  return out;
}

std::optional<StructureAdmittance> structure_admittance(const StructureSeries& s, const StructureSpec& spec,
                                                        const StructureSummaryOptions& o) {
  if (spec.load.type != StructureLoadType::noise) return std::nullopt;
  const UniformGrid g = uniform_grid(s.time, o.skip_seconds);
  if (g.n < 8) return std::nullopt;
  const double duration = (g.n - 1) * g.dt;
  const double segment = o.segment_seconds > 0.0 ? o.segment_seconds : std::min(600.0, 0.25 * duration);
  const auto length = static_cast<std::size_t>(std::llround(segment / g.dt));
  if (length < 4 || length > g.n) return std::nullopt;

  StructureAdmittance a;
  a.f_lo = spec.load.band_low;
  a.f_hi = spec.load.band_high;
  a.natural_frequency = sdof_spec(spec).natural_frequency();
  a.structure_damping_ratio = sdof_spec(spec).damping_ratio();
  a.force_level = noise_load_level(spec).psd_level;
  a.segment_seconds = length * g.dt;
  // The Welch bins are 1 / segment apart: a band with fewer than two whole bins in it has no
  // area to measure (a run of a few seconds), so it has no admittance either.
  if (a.segment_seconds * (a.f_hi - a.f_lo) < 2.0) return std::nullopt;
  const std::vector<double> x = resample(s.time, s.x_s, g);
  a.force_psd = welch_psd(resample(s.time, s.F_e, g), g.dt, length);
  a.displacement_psd = welch_psd(x, g.dt, length);
  a.displacement = mechanical_admittance(a.displacement_psd, a.force_level, spec.stiffness);  // thesis eq. 4.30
  if (!s.eta.empty()) {
    a.wave = mechanical_admittance(welch_psd(resample(s.time, s.eta, g), g.dt, length), a.force_level, spec.stiffness);
    a.eta_name = s.eta_name;
  }
  // Vickery et al. (1983): the SDOF with the structure's f_n and the same area under |H|^2.
  // The area of the whole record's periodogram over the band is K^2 sigma_x^2 / S0 (Parseval:
  // the force has no power outside the band, so neither has the linear response), so
  //   zeta_eff = pi f_n / (4 area) = pi f_n S0 / (4 K^2 sigma_x^2).
  const double variance = std::pow(standard_deviation(x), 2);
  if (!(variance > 0.0)) return std::nullopt;  // a structure that does not move has no admittance
  a.effective_damping = std::numbers::pi * a.natural_frequency * a.force_level /
                        (4.0 * spec.stiffness * spec.stiffness * variance);
  a.effective_damping_welch = effective_damping_ratio(a.displacement, a.natural_frequency, a.f_lo, a.f_hi);
  return a;
}

namespace {

// summary.json "structure_without_tank", and the run's ratios to it in j's "displacement" and
// "acceleration" (filled before this is called).
nlohmann::json without_tank_summary(const StructureSeries& s, const StructureSpec& spec, const StructureSummaryOptions& o,
                                    nlohmann::json& j) {
  StructureSeries alone = s;
  const StructureAloneResponse r = structure_alone_response(s, spec);
  alone.x_s = r.x;
  alone.a_s = r.a;
  alone.eta.clear();
  const std::vector<double> x = after(s.time, alone.x_s, o.skip_seconds);
  const std::vector<double> acc = after(s.time, alone.a_s, o.skip_seconds);
  nlohmann::json w;
  w["method"] = "the structure alone under this run's recorded load, Newmark average acceleration";
  add_motion(w, x, acc);
  if (const auto a = structure_admittance(alone, spec, o)) w["effective_damping_ratio"] = a->effective_damping;
  // Ratios only where the structure alone moves (a zero load leaves nothing to compare with).
  auto ratio = [](double run, double without) { return without > 0.0 ? nlohmann::json(run / without) : nlohmann::json(); };
  for (const auto& [quantity, unit] : {std::pair{"displacement", "m"}, std::pair{"acceleration", "m_s2"}}) {
    const std::string rms_key = std::string("rms_") + unit, peak_key = std::string("peak_") + unit;
    j[quantity]["rms_ratio_to_without_tank"] =
        ratio(j[quantity][rms_key].get<double>(), w[quantity][rms_key].get<double>());
    j[quantity]["peak_ratio_to_without_tank"] =
        ratio(j[quantity][peak_key].get<double>(), w[quantity][peak_key].get<double>());
  }
  return w;
}

}  // namespace

nlohmann::json structure_summary(const StructureSeries& s, const StructureSpec& spec,
                                 const StructureSummaryOptions& o) {
  const SdofSpec sdof = sdof_spec(spec);
  nlohmann::json j;
  j["mass_kg"] = spec.mass;
  j["damping_N_s_per_m"] = spec.damping;
  j["stiffness_N_per_m"] = spec.stiffness;
  j["natural_frequency_Hz"] = sdof.natural_frequency();
  j["damping_ratio"] = sdof.damping_ratio();
  j["tanks"] = spec.tanks;
  j["tank_width_m"] = spec.tank_width;
  j["rigid_mass_kg_per_m"] = spec.rigid_mass;
  j["skip_s"] = o.skip_seconds;

  const std::vector<double> x = after(s.time, s.x_s, o.skip_seconds);
  const std::vector<double> acc = after(s.time, s.a_s, o.skip_seconds);
  const std::vector<double> f = after(s.time, s.F_e, o.skip_seconds);
  if (x.empty()) {
    j["note"] = "no samples after skip_s";
    return j;
  }
  add_motion(j, x, acc);
  j["load"] = {{"type", load_name(spec.load.type)}, {"rms_N", rms(f)}, {"peak_N", peak_abs(f)}};
  j["structure_without_tank"] = without_tank_summary(s, spec, o, j);

  if (spec.load.type == StructureLoadType::noise) {
    const NoiseLoadLevel level = noise_load_level(spec);
    j["load"]["band_Hz"] = {spec.load.band_low, spec.load.band_high};
    j["load"]["psd_level_N2_per_Hz"] = level.psd_level;
    if (level.scaling) {
      // The structure alone under this load (random vibration theory, white_noise.hpp).
      const NoiseScaling& n = *level.scaling;
      j["load"]["target_peak_milli_g"] = *spec.load.target_peak_mg;
      j["structure_alone"] = {{"rms_acceleration_m_s2", n.sigma_acceleration},
                              {"rms_acceleration_milli_g", n.sigma_acceleration / kMilliG},
                              {"mean_peak_acceleration_milli_g", n.mean_peak / kMilliG},
                              {"peak_factor", n.peak_factor},
                              {"upcrossing_rate_Hz", n.upcrossing_rate},
                              {"peak_duration_s", spec.load.peak_duration}};
      j["acceleration"]["rms_normalised_by_structure_alone"] = rms(acc) / n.sigma_acceleration;
    }
    if (const auto a = structure_admittance(s, spec, o)) {
      std::size_t peak = 0;
      for (std::size_t k = 0; k < a->displacement.value.size(); ++k)
        if (a->displacement.value[k] > a->displacement.value[peak]) peak = k;
      nlohmann::json m = {{"effective_damping_ratio", a->effective_damping},
                          {"effective_damping_ratio_welch_area", a->effective_damping_welch},
                          {"force_psd_level_N2_per_Hz", a->force_level},
                          {"natural_frequency_Hz", a->natural_frequency},
                          {"band_Hz", {a->f_lo, a->f_hi}},
                          {"segment_s", a->segment_seconds},
                          {"df_Hz", a->displacement.df},
                          {"peak_H2_displacement", a->displacement.value[peak]},
                          {"peak_frequency_Hz", a->displacement.f[peak]}};
      if (a->wave) {
        std::size_t wp = 0;
        for (std::size_t k = 0; k < a->wave->value.size(); ++k)
          if (a->wave->value[k] > a->wave->value[wp]) wp = k;
        m["wave_gauge"] = a->eta_name;
        m["peak_H2_wave"] = a->wave->value[wp];
        m["peak_wave_frequency_Hz"] = a->wave->f[wp];
      }
      j["admittance"] = m;
    } else {
      j["admittance"] = {{"note", "record too short for a spectrum"}};
    }
  }
  return j;
}

std::string admittance_csv(const StructureAdmittance& a) {
  std::ostringstream out;
  out << "f_Hz,H2_displacement";
  if (a.wave) out << ",H2_wave";
  out << ",H2_structure_alone,S_force_N2_per_Hz,S_displacement_m2_per_Hz\n";
  for (std::size_t k = 0; k < a.displacement.f.size(); ++k) {
    const double fk = a.displacement.f[k];
    if (fk > 2.0 * a.f_hi) break;
    out << format_number(fk) << ',' << format_number(a.displacement.value[k]);
    if (a.wave) out << ',' << format_number(a.wave->value[k]);
    out << ',' << format_number(sdof_admittance(fk, a.natural_frequency, a.structure_damping_ratio)) << ','
        << format_number(a.force_psd.value[k]) << ',' << format_number(a.displacement_psd.value[k]) << '\n';
  }
  return out.str();
}

}  // namespace sloshsph
