// Faltinsen et al. (2000) tank, Shao et al. (2012) 3.1 (issue: the classic sloshing validations
// of both schemes): cases/faltinsen2000.toml (ISPH) and faltinsen2000_wcsph.toml, surge
// A cos(2 pi t / T), A = 0.032 m, T = 1.5 s, depth 0.6 m, dp = 20 mm, run to 40 s.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "run_support.hpp"
#include "sloshsph/analysis/spectrum.hpp"
#include "sloshsph/analysis/steady_state.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_at_most;
using testing::check_relative;
using testing::report;

struct GaugeResponse {
  double period = 0.0;   // s, dominant period of the gauge over 10-40 s
  double eta_max = 0.0;  // m, average of the last 10 cycles' crests
  std::vector<double> t, eta;  // the gauge over 10-40 s
};

// The left gauge of `case_name` with `overrides`, run to `end`, from 10 s on: its dominant period
// and the average of its last 10 cycles' crests at the excitation period `period`.
GaugeResponse respond(const std::string& case_name, std::vector<std::string> overrides = {}, double period = 1.5,
                      double end = 40.0, const std::string& label = "") {
  overrides.push_back("time.end=" + std::to_string(end));
  overrides.push_back("output.snapshot_interval=0");
  const auto r = testing::run_case_in_memory(case_name, overrides);
  const std::string name = case_name + label;
  check_at_most("particles leaked from the tank in " + std::to_string(static_cast<int>(end)) + " s, " + name,
                static_cast<double>(r.leaked), 0.0, "none may leave");
  std::printf("  %s: %zu steps in %.0f s\n", name.c_str(), r.steps, r.wall_seconds);
  std::vector<double> t, eta;
  for (std::size_t i = 0; i < r["time"].size(); ++i)
    if (r["time"][i] >= 10.0) {
      t.push_back(r["time"][i]);
      eta.push_back(r["eta:left"][i]);
    }
  GaugeResponse g;
  g.period = 1.0 / dominant_frequency_fft(eta, t[1] - t[0]);
  g.eta_max = steady_state_amplitude(t, eta, period, 10).avg_max;
  g.t = std::move(t);
  g.eta = std::move(eta);
  return g;
}

// References (issue): once steady, the gauge's dominant period equals the excitation period T
// within 2%; ISPH and WCSPH agree on the average maximum elevation within 15%. "Steady" here:
// after 10 s (6.7 periods); the free sloshing at 1.668 s excited by the start decays with the
// schemes' numerical damping (zeta about 1.5%, time constant about 18 s), so the 30 s window
// still holds some of it.
// Measured (docs/validation.md, 675f5ac): passes; periods +0.21% (ISPH), +0.17% (WCSPH), crests 0.193 / 0.171 m.
// Before 85fbac0 the WCSPH run went non-finite at 32.1 s (coincident particles in a corner:
// the artificial viscosity divided 0 by 0).
TEST(ValidationLong, FaltinsenTankBothSchemes) {
  const GaugeResponse isph = respond("faltinsen2000.toml");
  const GaugeResponse wcsph = respond("faltinsen2000_wcsph.toml");
  report("faltinsen_period_isph_s", isph.period);
  report("faltinsen_period_wcsph_s", wcsph.period);
  report("faltinsen_eta_max_isph_m", isph.eta_max);
  report("faltinsen_eta_max_wcsph_m", wcsph.eta_max);
  const std::string excitation = "the excitation period T = 1.5 s (Faltinsen et al. 2000, Shao et al. 2012, 3.1)";
  check_relative("dominant period of the left gauge, 10-40 s, ISPH", isph.period, 1.5, 0.02, excitation, "s");
  check_relative("dominant period of the left gauge, 10-40 s, WCSPH", wcsph.period, 1.5, 0.02, excitation, "s");
  check_relative("average crest of the left gauge, last 10 cycles, WCSPH", wcsph.eta_max, isph.eta_max, 0.15,
                 "the same measure in the ISPH run (the schemes agree)", "m");
  testing::record_curve({"gauge", "Faltinsen tank, left gauge, 10-40 s", "time (s)", "eta (m)", isph.t, isph.eta,
                         "WCSPH (same case)", wcsph.t, wcsph.eta, false});
}

// Issue 30, section 4: two particles never reach one point. The closest pair of fluid particles
// (column closest_pair, a fraction of dp) over the first 12 s of both Faltinsen cases at their
// defaults, which keep pairs apart (scheme.pair_contact, physics/pair_contact.hpp). Without that
// step (measured 2026-12-06 with --set scheme.pair_contact=false, the same binary): WCSPH 1.8e-10 dp
// at 9.61 s (two particles 7 mm from the right wall, 0.24 m up, pressed there by Shao's repulsive
// walls; 6e-5 dp apart half a second later), ISPH 0.029 dp at 7.54 s. The bar, a tenth of dp, is
// what "at one point" means here: the step parts pairs to dp/8 and stops approach within dp/4.
TEST(ValidationLong, FaltinsenNoTwoParticlesAtOnePoint) {
  for (const char* name : {"faltinsen2000.toml", "faltinsen2000_wcsph.toml"}) {
    const auto r = testing::run_case_in_memory(name, {"time.end=12", "output.snapshot_interval=0"});
    const std::vector<double>& closest = r["closest_pair"];
    const auto least = std::min_element(closest.begin(), closest.end());
    const double when = r["time"][static_cast<std::size_t>(least - closest.begin())];
    std::printf("  %s: closest pair %.4g dp at %.2f s; %g pair contacts in %zu steps\n", name, *least, when,
                r["pair_contacts"].back(), r.steps);
    testing::check_at_least(std::string("closest pair of fluid particles over 0-12 s, ") + name, *least, 0.1,
                            "a tenth of dp (issue 30 section 4: two particles never at one point)", "dp");
    check_at_most(std::string("particles leaked from the tank in 12 s, ") + name, static_cast<double>(r.leaked), 0.0,
                  "none may leave");
  }
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// The variants of issue 30, section 6 that the test above does not run: the same tank at
// T = 1.3 s (depth 0.6 m), and at depth 0.5 m (T = 1.5 s); both schemes, 30 s each (10-30 s:
// 15-23 periods). The same references and tolerances as above.
void check_variant(const std::vector<std::string>& overrides, double period, const std::string& tag) {
  const std::string label = ", " + tag;
  const GaugeResponse isph = respond("faltinsen2000.toml", overrides, period, 30.0, label);
  const GaugeResponse wcsph = respond("faltinsen2000_wcsph.toml", overrides, period, 30.0, label);
  report("faltinsen_period_isph_s" + label, isph.period);
  report("faltinsen_period_wcsph_s" + label, wcsph.period);
  report("faltinsen_eta_max_isph_m" + label, isph.eta_max);
  report("faltinsen_eta_max_wcsph_m" + label, wcsph.eta_max);
  const std::string excitation =
      "the excitation period (Faltinsen et al. 2000 tank, issue 30 variant " + tag + ")";
  check_relative("dominant period of the left gauge, 10-30 s, ISPH, " + tag, isph.period, period, 0.02, excitation,
                 "s");
  check_relative("dominant period of the left gauge, 10-30 s, WCSPH, " + tag, wcsph.period, period, 0.02,
                 excitation, "s");
  check_relative("average crest of the left gauge, last 10 cycles, WCSPH, " + tag, wcsph.eta_max, isph.eta_max, 0.15,
                 "the same measure in the ISPH run (the schemes agree)", "m");
  std::string name = tag;
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
  testing::record_curve({"gauge_" + name, "Faltinsen tank, left gauge, 10-30 s, " + tag, "time (s)", "eta (m)", isph.t,
                         isph.eta, "WCSPH (same case)", wcsph.t, wcsph.eta, false});
}

TEST(ValidationLong, FaltinsenTankPeriod13BothSchemes) {
  check_variant({"excitation.frequency=0.7692307692307693"}, 1.3, "T = 1.3 s");
}

TEST(ValidationLong, FaltinsenTankDepth05BothSchemes) { check_variant({"fill.depth=0.5"}, 1.5, "depth 0.5 m"); }

}  // namespace
}  // namespace sloshsph
