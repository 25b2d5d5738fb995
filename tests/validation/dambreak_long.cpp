// Dam-break validations that take long or that we do not pass (label `long`; see
// docs/validation.md for the measured numbers). Both schemes each.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dambreak_support.hpp"
#include "run_support.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_at_most;
using testing::check_relative;
using testing::report;

std::vector<testing::Sample> read_csv_pairs(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<testing::Sample> out;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    testing::Sample s;
    if (row >> s.t >> s.x) out.push_back(s);
  }
  return out;
}

std::string refdata(const std::string& file) { return std::string(SLOSHSPH_SOURCE_DIR) + "/data/refdata/" + file; }

// Buchner (2002) wall pressure at P1 (0.16 m up the impact wall), p/(rho g H) against
// t sqrt(g/H), H = 0.6 m (data/refdata/buchner_2002_dambreak_pressure). cases/dambreak_buchner
// at its dp = 10 mm (H/dp = 60). The bar: the first peak (the impact, data: 0.687 at
// t* = 2.77; taken as the maximum before t* = 4.5, before the plateau ends) within 25% in value and
// 10% in time. Measured (docs/validation.md): both schemes rise at t* = 2.8 but only to
// 0.45 (ISPH) and 0.43 (WCSPH) by t* = 4.2-4.5: this test fails.
TEST(ValidationLong, DamBreakWallPressureBuchner) {
  const auto data = read_csv_pairs(refdata("buchner_2002_dambreak_pressure/exp_pressure_sensor_P1.csv"));
  const double H = 0.6, g = 9.81, rho = 1000.0, scale = std::sqrt(g / H);
  const std::string source =
      "Buchner (2002), sensor P1, data/refdata/buchner_2002_dambreak_pressure/exp_pressure_sensor_P1.csv: "
      "first peak 0.687 at t sqrt(g/H) = 2.77";
  testing::Sample peak_data{0.0, -1.0};
  for (const auto& d : data)
    if (d.t < 4.5 && d.x > peak_data.x) peak_data = d;
  for (const std::string scheme : {"isph", "wcsph"}) {
    const auto r = testing::run_case_in_memory(scheme == "isph" ? "dambreak_buchner.toml" : "dambreak_buchner_wcsph.toml",
                                               {"output.snapshot_interval=0"});
    const std::string label = scheme == "isph" ? "ISPH" : "WCSPH";
    testing::Sample peak{0.0, -1.0};
    std::vector<double> t_star, p_star;
    for (std::size_t i = 0; i < r["time"].size(); ++i) {
      const double t = r["time"][i] * scale, p = r["p:P1"][i] / (rho * g * H);
      t_star.push_back(t);
      p_star.push_back(p);
      if (t < 4.5 && p > peak.x) peak = {t, p};
    }
    report("buchner_p1_first_peak_" + scheme, peak.x);
    report("buchner_p1_first_peak_time_" + scheme, peak.t);
    check_relative("first pressure peak at P1, p/(rho g H), maximum before t sqrt(g/H) = 4.5, " + label, peak.x,
                   peak_data.x, 0.25, source);
    check_relative("time of that peak, t sqrt(g/H), " + label, peak.t, peak_data.t, 0.10, source);
    std::vector<double> data_t, data_p;
    for (const auto& d : data) {
      data_t.push_back(d.t);
      data_p.push_back(d.x);
    }
    testing::record_curve({"p1_" + scheme, "Dam-break wall pressure at P1 (0.16 m up the impact wall), " + label,
                           "t sqrt(g/H)", "p / (rho g H)", t_star, p_star, "Buchner (2002), experiment", data_t, data_p});
  }
}

// Martin & Moyce (1952) surge front, x/a against T = t sqrt(2 g / a) for the column of height
// 2a (their n^2 = 2; Koshizuka & Oka's geometry, cases/dambreak_koshizuka*, a = 1 m), dp = 20 mm.
// The data's time convention is not stated by its source (data/refdata/martin_moyce_1952_surge_
// front/SOURCE.md); this is the classic one. Bar: RMS of x/a within 0.05 (5% of the width).
// Measured: 0.28 (ISPH): the data run ahead of the simulation late in the surge; fails.
TEST(ValidationLong, DamBreakFrontMartinMoyce) {
  const auto data = read_csv_pairs(refdata("martin_moyce_1952_surge_front/exp_surge_front.csv"));
  const double scale = std::sqrt(2.0 * 9.81 / 1.0);
  std::vector<testing::Sample> nondimensional;
  for (const auto& d : data) nondimensional.push_back({d.t / scale, d.x});  // to seconds, x in units of a = 1 m
  for (const std::string scheme : {"isph", "wcsph"}) {
    const auto r = testing::run_case_in_memory(
        scheme == "isph" ? "dambreak_koshizuka.toml" : "dambreak_koshizuka_wcsph.toml",
        {"time.end=0.8", "output.sample_interval=0.005", "output.snapshot_interval=0"});
    std::vector<testing::Sample> run;
    for (std::size_t i = 0; i < r["time"].size(); ++i) run.push_back({r["time"][i], r["front:tip"][i]});
    const double rms = testing::front_rms(run, nondimensional, 0.0);
    report("martin_moyce_rms_" + scheme, rms);
    const std::string label = scheme == "isph" ? "ISPH" : "WCSPH";
    check_at_most("RMS error of the surge front x/a, a = 1 m, " + label, rms, 0.05,
                  "Martin & Moyce (1952), n^2 = 2, data/refdata/martin_moyce_1952_surge_front/exp_surge_front.csv, "
                  "T = t sqrt(2 g / a); bar 5% of the width");
    std::vector<double> t, x, data_t, data_x;
    for (const testing::Sample& s : run) {
      t.push_back(s.t);
      x.push_back(s.x);
    }
    for (const testing::Sample& d : nondimensional) {
      data_t.push_back(d.t);
      data_x.push_back(d.x);
    }
    testing::record_curve({"front_" + scheme, "Dam-break surge front, " + label + ", a = 1 m, dp = 20 mm", "time (s)",
                           "front position x (m) = x/a", t, x,
                           "Martin & Moyce (1952), experiment, T = t sqrt(2 g / a)", data_t, data_x});
  }
}

}  // namespace
}  // namespace sloshsph
