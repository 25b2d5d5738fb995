// Dam-break validations that take long or that we did not pass (label `long`; see
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

// Martin & Moyce (1952) surge front, x/a for the column of height 2a (their n^2 = 2; Koshizuka
// & Oka's geometry, cases/dambreak_koshizuka*, a = 1 m), dp = 20 mm, 0.8 s.
// The data's time: its source does not state the convention (data/refdata/martin_moyce_1952_
// surge_front/SOURCE.md). Read as T = t sqrt(2 g / a), the classic one, the data run ahead of the
// Koshizuka & Oka experiment (the same geometry) by a factor sqrt(2) in time; read as
// T = t sqrt(g / a), the two experiments agree within 0.03 of x/a up to x/a = 2.1 (1.43 / 1.44,
// 1.64 / 1.67, 1.88 / 1.89, 2.12 / 2.11 at the data's times). So the file holds t sqrt(g / a).
// The checks are those of the Koshizuka & Oka front (dambreak_validation.cpp): the RMS after the
// best shift of the experiment's time origin (0 to 0.06 s, a gate delay) within 5% of a, that
// shift within 0 to 0.06 s, and the unshifted RMS against the 5%, recorded.
TEST(ValidationLong, DamBreakFrontMartinMoyce) {
  const auto data = read_csv_pairs(refdata("martin_moyce_1952_surge_front/exp_surge_front.csv"));
  ASSERT_EQ(data.size(), 10u);
  const double scale = std::sqrt(9.81 / 1.0);  // T = t sqrt(g / a), a = 1 m
  const std::string source =
      "Martin & Moyce (1952), n^2 = 2, data/refdata/martin_moyce_1952_surge_front/exp_surge_front.csv, "
      "T = t sqrt(g / a); bar 5% of the width a";
  std::vector<testing::Sample> nondimensional;
  for (const auto& d : data) nondimensional.push_back({d.t / scale, d.x});  // to seconds, x in units of a = 1 m
  for (const std::string scheme : {"isph", "wcsph"}) {
    std::vector<std::string> set = {"time.end=0.8", "output.sample_interval=0.005", "output.snapshot_interval=0"};
    if (scheme == "wcsph") set.push_back("scheme.walls=adami");  // as in the Koshizuka & Oka test
    const auto r =
        testing::run_case_in_memory(scheme == "isph" ? "dambreak_koshizuka.toml" : "dambreak_koshizuka_wcsph.toml", set);
    std::vector<testing::Sample> run;
    for (std::size_t i = 0; i < r["time"].size(); ++i) run.push_back({r["time"][i], r["front:tip"][i]});
    const std::string label = scheme == "isph" ? "ISPH" : "WCSPH";
    const double unshifted = testing::front_rms(run, nondimensional, 0.0);
    const testing::Shift best = testing::best_shift(run, nondimensional, 0.0, 0.1);
    report("martin_moyce_rms_" + scheme, unshifted);
    report("martin_moyce_shift_s_" + scheme, best.shift);
    report("martin_moyce_rms_after_shift_" + scheme, best.rms);
    check_at_most("RMS error of the surge front x/a after the best time shift, " + label, best.rms, 0.05, source);
    testing::check_between("best shift of the experiment's time origin, " + label, best.shift, 0.0, 0.06,
                           "gate delay of the experiment: the data may lag, never lead", "s");
    testing::check(testing::Check{.quantity = "RMS error of the surge front x/a, unshifted, " + label,
                                  .unit = "",
                                  .measured = unshifted,
                                  .kind = testing::Tolerance::at_most,
                                  .reference = 0.05,
                                  .tolerance = NAN,
                                  .source = source + " (the time origin of the release is not stated)",
                                  .asserted = false});
    testing::record_front_curve("front_" + scheme, "Dam-break surge front, " + label + ", a = 1 m, dp = 20 mm",
                                "front position x (m) = x/a", run, nondimensional,
                                "Martin & Moyce (1952), experiment, T = t sqrt(g / a)");
  }
}

}  // namespace
}  // namespace sloshsph
