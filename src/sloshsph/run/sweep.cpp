#include "sloshsph/run/sweep.hpp"

#include <cctype>
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

// `text` read whole as a number; nullopt if it is not one (or has anything after it).
std::optional<double> whole_number(const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size()) return std::nullopt;
  return v;
}

double parse_ratio(const std::string& text, const std::string& where) {
  const std::optional<double> v = whole_number(text);
  if (!v)
    throw InputError(where, "--beta", "'" + text + "' is not a number (expected A:B:N, a list a,b,c, or one number)");
  if (!(*v > 0.0) || !std::isfinite(*v))
    throw InputError(where, "--beta", "frequency ratios must be positive, got " + text);
  return *v;
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

// A CSV field: quoted (quotes doubled) when it holds a comma, a quote or a line break.
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A TOML string value without its quotes ("ergun" -> ergun); other values as they are.
std::string unquoted(const std::string& value) {
  if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') && value.back() == value.front())
    return value.substr(1, value.size() - 2);
  return value;
}

// N of "A:B:N": a whole number from 1 to 10000; InputError(where, key) otherwise.
long point_count(const std::string& text, const std::string& where, const std::string& key) {
  std::size_t used = 0;
  long n = 0;
  try {
    n = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || n < 1 || n > 10000)
    throw InputError(where, key,
                     "the point count N in A:B:N must be a whole number from 1 to 10000, got '" + text + "'");
  return n;
}

// N values from a to b inclusive, evenly spaced (a alone for N = 1).
std::vector<double> evenly_spaced(double a, double b, long n) {
  if (n == 1) return {a};
  std::vector<double> values;
  for (long k = 0; k < n; ++k) values.push_back(a + (b - a) * static_cast<double>(k) / static_cast<double>(n - 1));
  return values;
}

}  // namespace

std::vector<double> parse_beta_range(const std::string& text, const std::string& where) {
  const std::vector<std::string> range = split(text, ':');
  if (range.size() == 3) {
    const double a = parse_ratio(range[0], where), b = parse_ratio(range[1], where);
    return evenly_spaced(a, b, point_count(range[2], where, "--beta"));
  }
  if (range.size() != 1) throw InputError(where, "--beta", "expected A:B:N, a list a,b,c, or one number, got '" + text + "'");
  std::vector<double> betas;
  for (const std::string& part : split(text, ',')) betas.push_back(parse_ratio(part, where));
  return betas;
}

namespace {

// "A:B:N" with numbers A, B and a whole N from 1 to 10000 -> N texts; otherwise nullopt.
std::optional<std::vector<std::string>> numeric_range(const std::string& key, const std::string& value) {
  const std::vector<std::string> parts = split(value, ':');
  if (parts.size() != 3) return std::nullopt;
  double ends[2];
  for (int k = 0; k < 2; ++k) {
    const std::optional<double> v = whole_number(parts[k]);
    if (!v || !std::isfinite(*v)) return std::nullopt;
    ends[k] = *v;
  }
  std::vector<std::string> values;
  for (double v : evenly_spaced(ends[0], ends[1], point_count(parts[2], "--set", key)))
    values.push_back(format("%.10g", v));
  return values;
}

// The parts of "a,b,c" split at the commas outside [], {} and quotes (one part: not a list).
std::vector<std::string> top_level_items(const std::string& value) {
  std::vector<std::string> items(1);
  int depth = 0;
  char quote = 0;
  for (char c : value) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      items.emplace_back();
      continue;
    }
    items.back() += c;
  }
  for (std::string& item : items) {
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    item = first == std::string::npos ? "" : item.substr(first, last - first + 1);
  }
  return items;
}

// A file-name-safe form of a key or value for the point's directory name.
std::string label_part(const std::string& text) {
  std::string out;
  for (char c : text) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') ? c : '_';
  return out.substr(0, 40);
}

}  // namespace

SweepSets split_sweep_sets(const std::vector<std::string>& sets) {
  SweepSets out;
  for (const std::string& set : sets) {
    const auto eq = set.find('=');
    if (eq == std::string::npos || eq == 0) {
      out.fixed.push_back(set);  // the case reader reports the malformed --set
      continue;
    }
    const std::string key = set.substr(0, eq), value = set.substr(eq + 1);
    std::optional<std::vector<std::string>> values = numeric_range(key, value);
    if (!values) {
      std::vector<std::string> items = top_level_items(value);
      if (items.size() > 1) values = std::move(items);
    }
    if (!values) {
      out.fixed.push_back(set);
      continue;
    }
    for (const std::string& v : *values)
      if (v.empty()) throw InputError("--set", key, "an empty value in the list '" + value + "'");
    for (const SweepAxis& a : out.axes)
      if (a.key == key) throw InputError("--set", key, "swept twice; give one range or list per key");
    out.axes.push_back({key, *values});
  }
  return out;
}

double excitation_beta(const CaseSpec& spec) {
  const ExcitationType type = spec.excitation.type;
  if ((type != ExcitationType::harmonic && type != ExcitationType::pitch) || is_pitch_record(spec.excitation))
    return std::numeric_limits<double>::quiet_NaN();
  return spec.excitation.omega / reference_omega(spec);
}

std::vector<SweepPoint> plan_sweep(const CaseSpec& spec, const std::vector<double>& betas,
                                   const std::vector<SweepAxis>& axes, const std::string& sweep_dir) {
  if (betas.empty() && axes.empty())
    throw InputError("--beta", "--beta", "nothing to sweep: give --beta A:B:N, or a --set KEY=A:B:N or KEY=a,b,c");
  std::vector<SweepPoint> frequencies;
  if (betas.empty()) {
    SweepPoint p;
    p.beta = std::numeric_limits<double>::quiet_NaN();
    frequencies.push_back(p);
  } else {
    const ExcitationType type = spec.excitation.type;
    if (type != ExcitationType::harmonic && type != ExcitationType::pitch)
      throw InputError(spec.where("excitation.type"), "excitation.type",
                       "a frequency sweep needs a harmonic or pitch excitation");
    if (is_pitch_record(spec.excitation))
      throw InputError(spec.where("excitation.file"), "excitation.file",
                       "a frequency sweep needs a harmonic pitch, not a pitch from a file");
    const double omega_ref = reference_omega(spec);
    for (double beta : betas) {
      SweepPoint p;
      p.beta = beta;
      p.label = format("beta_%.4f", beta);
      // Set the key the case uses: a case may give only one of beta, frequency and omega.
      if (spec.excitation.beta) p.overrides.push_back("excitation.beta=" + format("%.17g", beta));
      else if (spec.locations.count("excitation.omega"))
        p.overrides.push_back("excitation.omega=" + format("%.17g", beta * omega_ref));
      else p.overrides.push_back("excitation.frequency=" + format("%.17g", beta * omega_ref / (2.0 * std::numbers::pi)));
      frequencies.push_back(p);
    }
  }
  // The Cartesian product: the first axis varies slowest, beta slowest of all.
  std::vector<SweepPoint> points = frequencies;
  for (const SweepAxis& axis : axes) {
    std::vector<SweepPoint> next;
    for (const SweepPoint& base : points)
      for (const std::string& value : axis.values) {
        SweepPoint p = base;
        p.label += (p.label.empty() ? "" : "__") + label_part(axis.key) + "_" + label_part(value);
        p.overrides.push_back(axis.key + "=" + value);
        p.axis_values.push_back(value);
        next.push_back(p);
      }
    points = std::move(next);
  }
  if (points.size() > 10000) throw InputError("--set", "", "more than 10000 sweep points; sweep fewer values");
  for (std::size_t k = 0; k < points.size(); ++k) {
    points[k].directory = (fs::path(sweep_dir) / points[k].label).string();
    for (std::size_t j = 0; j < k; ++j)
      if (points[j].label == points[k].label)
        throw InputError("--beta", "--beta", "two points have the same name " + points[k].label + "; use fewer points");
  }
  return points;
}

std::string point_status(const std::string& directory) {
  const std::optional<nlohmann::json> s = read_summary(directory);
  if (!s || !s->contains("status") || !(*s)["status"].is_string()) return "";
  return (*s)["status"].get<std::string>();
}

bool point_finished(const SweepPoint& p, bool retry_failed, const std::function<std::string()>& expected_case_toml) {
  const std::string status = point_status(p.directory);
  if (status != "completed" && !(status == "failed" && !retry_failed)) return false;
  std::ifstream in(std::filesystem::path(p.directory) / "case.toml", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str() != expected_case_toml())
    throw InputError(p.directory, "", "this point was run from a different case or --set values; use another --out");
  return true;
}

bool point_resumable(const SweepPoint& p) {
  std::error_code ec;
  return point_status(p.directory) == "interrupted" &&
         std::filesystem::exists(std::filesystem::path(p.directory) / "checkpoint.bin", ec);
}

std::string frequency_response_csv(const CaseSpec& spec, const std::vector<SweepAxis>& axes,
                                   const std::vector<SweepPoint>& points) {
  std::string out = "beta,omega,eta_max,eta_min,F_sw_max,F_sw_min,energy_per_cycle,status,normalised_energy,F_w_max,F_w_min";
  for (const GaugeSpec& g : spec.gauges) out += ",eta_max:" + g.name + ",eta_min:" + g.name;
  for (const SweepAxis& a : axes) (out += ',') += csv_cell("set:" + a.key);
  out += ",wall_time_s,run_dir\n";
  const std::string first_gauge = spec.gauges.empty() ? "" : "eta:" + spec.gauges.front().name;
  auto cell = [](double v) {
    std::string c = ",";  // appended, not "," + ...: gcc 12 warns (-Wrestrict, falsely) on the temporary
    return c += format("%.9g", v);
  };
  for (const SweepPoint& p : points) {
    const nlohmann::json s = read_summary(p.directory).value_or(nlohmann::json::object());
    const std::string status = s.contains("status") && s["status"].is_string() ? s["status"].get<std::string>() : "missing";
    const nlohmann::json response = s.value("response", nlohmann::json::object());
    out += format("%.6g", p.beta);
    out += cell(number(s, "excitation_omega_rad_s"));
    out += cell(steady(s, first_gauge, "avg_max")) + cell(steady(s, first_gauge, "avg_min"));
    out += cell(steady(s, "F_sw", "avg_max")) + cell(steady(s, "F_sw", "avg_min"));
    out += cell(number(response, spec.tank.dimensions == 3 ? "energy_per_cycle_J" : "energy_per_cycle_J_per_m"));
    out += "," + status;
    out += cell(number(response, "normalised_energy"));
    out += cell(steady(s, "F_w", "avg_max")) + cell(steady(s, "F_w", "avg_min"));
    for (const GaugeSpec& g : spec.gauges)
      out += cell(steady(s, "eta:" + g.name, "avg_max")) + cell(steady(s, "eta:" + g.name, "avg_min"));
    for (const std::string& v : p.axis_values) (out += ',') += csv_cell(unquoted(v));
    out += cell(number(s, "wall_time_s")) + "," + p.label + "\n";
  }
  return out;
}

}  // namespace sloshsph
