// Dam-break validations that take long or that we did not pass (label `long`; see
// docs/validation.md for the measured numbers). Both schemes each.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "dambreak_support.hpp"
#include "sloshsph/analysis/impact_peak.hpp"
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
// at its dp = 10 mm (H/dp = 60), each scheme with its case's walls. The bar: the first
// peak (the impact) within 25% in value and 10% in time. The impact peak is the maximum within
// 0.5 of t sqrt(g/H) after the signal first exceeds 0.1 (data: 0.687 at 2.77, the same as the
// maximum before the re-impact); a later fluctuation of the simulated plateau does not count.
// Asserted on P1, the experiment's transducer: a 9 mm face centred at 0.16 m (issue 30, section 3;
// the size and its source in the cases). Recorded beside it, not asserted: the point probe
// P1_point at 0.16 m (what was asserted before the faces), and the face P1_face from 0.07 to
// 0.16 m, the lowered sensor of Greco / Adami et al. (2012) as the cases explain. Also reported:
// the first impact peak of analysis/impact_peak.hpp (rise time 10-90%, impulse) of the data and
// of each probe. Measured (docs/validation.md).
struct WindowPeak {
  double time = NAN;   // t sqrt(g/H)
  double value = NAN;  // p / (rho g H)
};

WindowPeak impact_peak(const std::vector<double>& t, const std::vector<double>& p) {
  constexpr double kRise = 0.1, kWindow = 0.5;
  WindowPeak peak;
  double t_rise = NAN;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::isnan(t_rise) && p[i] > kRise) t_rise = t[i];
    if (std::isnan(t_rise) || t[i] > t_rise + kWindow) continue;
    if (std::isnan(peak.value) || p[i] > peak.value) peak = {t[i], p[i]};
  }
  return peak;
}

// The first impact peak by analysis/impact_peak.hpp (as summary.json gives it), nondimensional:
// value, time, rise time (10-90%) and impulse, reported for docs/validation.md, not asserted.
void report_first_impact_peak(const std::string& prefix, const std::string& suffix, const std::vector<double>& t,
                              const std::vector<double>& p) {
  const std::optional<ImpactPeak> peak = first_impact_peak(t, p);
  if (!peak) return;
  report(prefix + "_first_peak_" + suffix, peak->value);
  report(prefix + "_first_peak_time_" + suffix, peak->time);
  report(prefix + "_rise_time_" + suffix, peak->rise_time);
  report(prefix + "_impulse_" + suffix, peak->impulse);
}

TEST(ValidationLong, DamBreakWallPressureBuchner) {
  const auto data = read_csv_pairs(refdata("buchner_2002_dambreak_pressure/exp_pressure_sensor_P1.csv"));
  const double H = 0.6, g = 9.81, rho = 1000.0, scale = std::sqrt(g / H);
  std::vector<double> data_t, data_p;
  for (const auto& d : data) {
    data_t.push_back(d.t);
    data_p.push_back(d.x);
  }
  const WindowPeak reference = impact_peak(data_t, data_p);
  report_first_impact_peak("buchner_P1", "data", data_t, data_p);
  std::ostringstream source;
  source << "Buchner (2002), sensor P1 (centre 0.16 m), data/refdata/buchner_2002_dambreak_pressure/"
            "exp_pressure_sensor_P1.csv: impact peak "
         << reference.value << " at t sqrt(g/H) = " << reference.time;
  for (const std::string scheme : {"isph", "wcsph"}) {
    const auto r = testing::run_case_in_memory(scheme == "isph" ? "dambreak_buchner.toml" : "dambreak_buchner_wcsph.toml",
                                               {"output.snapshot_interval=0"});
    const std::string label = scheme == "isph" ? "ISPH" : "WCSPH";
    check_at_most("particles leaked from the tank by 2 s, " + label, static_cast<double>(r.leaked), 0.0, "none may leave");
    for (const std::string probe : {"P1", "P1_point", "P1_face"}) {
      const bool asserted = probe == "P1";
      std::vector<double> t_star, p_star;
      for (std::size_t i = 0; i < r["time"].size(); ++i) {
        t_star.push_back(r["time"][i] * scale);
        p_star.push_back(r["p:" + probe][i] / (rho * g * H));
      }
      const WindowPeak peak = impact_peak(t_star, p_star);
      const std::string where = probe == "P1"         ? "9 mm face at 0.16 m (the transducer)"
                                : probe == "P1_point" ? "point probe at 0.16 m"
                                                      : "face 0.07-0.16 m (Greco's lowered sensor)";
      report("buchner_" + probe + "_impact_peak_" + scheme, peak.value);
      report("buchner_" + probe + "_impact_peak_time_" + scheme, peak.time);
      report_first_impact_peak("buchner_" + probe, scheme, t_star, p_star);
      testing::check({"impact peak at P1, p/(rho g H), " + where + ", " + label, "", peak.value,
                      testing::Tolerance::relative, reference.value, 0.25, source.str(), asserted});
      testing::check({"time of the impact peak, t sqrt(g/H), " + where + ", " + label, "", peak.time,
                      testing::Tolerance::relative, reference.time, 0.10, source.str(), asserted});
      const std::string curve = probe == "P1" ? "p1_" : probe == "P1_point" ? "p1_point_" : "p1_face_";
      testing::record_curve({curve + scheme, "Dam-break wall pressure at P1, " + where + ", " + label,
                             "t sqrt(g/H)", "p / (rho g H)", t_star, p_star, "Buchner (2002), experiment", data_t,
                             data_p});
    }
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
