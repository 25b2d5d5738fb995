#include "sloshsph/run/sweep.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph {
namespace fs = std::filesystem;
namespace {

double parse_ratio(const std::string& text, const std::string& where) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw InputError(where, "--beta", "'" + text + "' is not a number (expected A:B:N, a list a,b,c, or one number)");
  if (!(v > 0.0) || !std::isfinite(v)) throw InputError(where, "--beta", "frequency ratios must be positive, got " + text);
  return v;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.emplace_back();
  return parts;
}

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::optional<nlohmann::json> read_summary(const std::string& directory) {
  std::ifstream in(fs::path(directory) / "summary.json");
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

// summary.response.steady_state.<column>.<field>, or nan.
double steady(const nlohmann::json& summary, const std::string& column, const char* field) {
  const auto r = summary.find("response");
  if (r == summary.end() || !r->contains("steady_state")) return std::numeric_limits<double>::quiet_NaN();
  const nlohmann::json& s = (*r)["steady_state"];
  if (!s.contains(column)) return std::numeric_limits<double>::quiet_NaN();
  return s[column].value(field, std::numeric_limits<double>::quiet_NaN());
}

double number(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::vector<double> parse_beta_range(const std::string& text, const std::string& where) {
  const std::vector<std::string> range = split(text, ':');
  if (range.size() == 3) {
    const double a = parse_ratio(range[0], where), b = parse_ratio(range[1], where);
    std::size_t used = 0;
    long n = 0;
    try {
      n = std::stol(range[2], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != range[2].size() || n < 1 || n > 10000)
      throw InputError(where, "--beta", "the point count N in A:B:N must be a whole number from 1 to 10000, got '" +
                                            range[2] + "'");
    if (n == 1) return {a};
    std::vector<double> betas;
    for (long k = 0; k < n; ++k) betas.push_back(a + (b - a) * static_cast<double>(k) / static_cast<double>(n - 1));
    return betas;
  }
  if (range.size() != 1) throw InputError(where, "--beta", "expected A:B:N, a list a,b,c, or one number, got '" + text + "'");
  std::vector<double> betas;
  for (const std::string& part : split(text, ',')) betas.push_back(parse_ratio(part, where));
  return betas;
}

std::vector<SweepPoint> plan_sweep(const CaseSpec& spec, const std::vector<double>& betas,
                                   const std::string& sweep_dir) {
  const ExcitationType type = spec.excitation.type;
  if (type != ExcitationType::harmonic && type != ExcitationType::pitch)
    throw InputError(spec.where("excitation.type"), "excitation.type",
                     "a frequency sweep needs a harmonic or pitch excitation");
  const double omega_ref = reference_omega(spec);
  std::vector<SweepPoint> points;
  for (double beta : betas) {
    SweepPoint p;
    p.beta = beta;
    p.label = format("beta_%.4f", beta);
    p.directory = (fs::path(sweep_dir) / p.label).string();
    // Set the key the case uses: a case may give only one of beta, frequency and omega.
    if (spec.excitation.beta) p.override_text = "excitation.beta=" + format("%.17g", beta);
    else if (spec.locations.count("excitation.omega"))
      p.override_text = "excitation.omega=" + format("%.17g", beta * omega_ref);
    else p.override_text = "excitation.frequency=" + format("%.17g", beta * omega_ref / (2.0 * std::numbers::pi));
    for (const SweepPoint& q : points)
      if (q.label == p.label)
        throw InputError("--beta", "--beta", "two points round to the same ratio " + p.label + "; use fewer points");
    points.push_back(p);
  }
  return points;
}

std::string point_status(const std::string& directory) {
  const std::optional<nlohmann::json> s = read_summary(directory);
  if (!s || !s->contains("status") || !(*s)["status"].is_string()) return "";
  return (*s)["status"].get<std::string>();
}

std::string frequency_response_csv(const CaseSpec& spec, const std::vector<SweepPoint>& points) {
  std::string out = "beta,omega,eta_max,eta_min,F_sw_max,F_sw_min,energy_per_cycle,status,normalised_energy,F_w_max,F_w_min";
  for (const GaugeSpec& g : spec.gauges) out += ",eta_max:" + g.name + ",eta_min:" + g.name;
  out += ",wall_time_s,run_dir\n";
  const std::string first_gauge = spec.gauges.empty() ? "" : "eta:" + spec.gauges.front().name;
  auto cell = [](double v) { return "," + format("%.9g", v); };
  for (const SweepPoint& p : points) {
    const nlohmann::json s = read_summary(p.directory).value_or(nlohmann::json::object());
    const std::string status = s.contains("status") && s["status"].is_string() ? s["status"].get<std::string>() : "missing";
    const nlohmann::json response = s.value("response", nlohmann::json::object());
    out += format("%.6g", p.beta);
    out += cell(number(s, "excitation_omega_rad_s"));
    out += cell(steady(s, first_gauge, "avg_max")) + cell(steady(s, first_gauge, "avg_min"));
    out += cell(steady(s, "F_sw", "avg_max")) + cell(steady(s, "F_sw", "avg_min"));
    out += cell(number(response, "energy_per_cycle_J_per_m"));
    out += "," + status;
    out += cell(number(response, "normalised_energy"));
    out += cell(steady(s, "F_w", "avg_max")) + cell(steady(s, "F_w", "avg_min"));
    for (const GaugeSpec& g : spec.gauges)
      out += cell(steady(s, "eta:" + g.name, "avg_max")) + cell(steady(s, "eta:" + g.name, "avg_min"));
    out += cell(number(s, "wall_time_s")) + "," + p.label + "\n";
  }
  return out;
}

}  // namespace sloshsph
