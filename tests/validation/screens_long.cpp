// Long runs of the screens (label `long`; not in CI): the macroscopic Ergun screens against the
// same screens built of explicit slats (issue 3, thesis 2.6.3.3), and the Ergun form of the
// horizontal baffles against the baffles as walls (thesis 4.3.2).
// Wall time on two threads (2026-12-02, multigrid pressure solve): the Ergun run at dp = 7 mm
// about 5 minutes, the explicit run at dp = 2.5 mm (18,448 fluid particles) about 30 minutes; at
// dp = 1.4 mm (58,486, 75,000 steps) estimated 1.5-2 hours (2026-12-07: 89 ms a step from rest on
// one thread beside two other runs).
#include <numbers>
#include <string>
#include <vector>

#include "run_support.hpp"
#include "sloshsph/analysis/filter.hpp"
#include "sloshsph/analysis/steady_state.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_at_most;
using testing::check_relative;
using testing::report;
using testing::run_case_in_memory;

struct Crest {
  double avg_max = 0.0, avg_min = 0.0;  // m, the gauge at x/L = 0.95 after the 5 Hz filter
  std::vector<double> t, gauge;
};

// Checks that no particle left the tank in the run (`duration` names it), and returns the
// averages of the last `cycles` excitation cycles of the gauge "right" after the 5 Hz
// zero-phase filter (thesis 2.6.3.1), reported under `key`.
Crest gauge_crest(const testing::RunResult& r, double omega, int cycles, const std::string& duration,
                  const std::string& key) {
  check_at_most("particles leaked from the tank in " + duration + ", " + key, static_cast<double>(r.leaked), 0.0,
                "none may leave");
  Crest c;
  c.t = r["time"];
  c.gauge = lowpass_zero_phase(r["eta:right"], c.t[1] - c.t[0], 5.0);
  const SteadyAmplitude a = steady_state_amplitude(c.t, c.gauge, 2.0 * std::numbers::pi / omega, cycles);
  c.avg_max = a.avg_max;
  c.avg_min = a.avg_min;
  report(key + "_avg_max_m", a.avg_max);
  report(key + "_avg_min_m", a.avg_min);
  report(key + "_wall_seconds", r.wall_seconds);
  return c;
}

// cases/tait2005_screens.toml at the largest amplitude of Tait et al. (2005), X0/L = 0.031
// (X0 = 29.9 mm), beta = 1.01, 30 s; averages of the last 8 excitation cycles (15.5-30 s) of the
// gauge after the 5 Hz zero-phase filter (thesis 2.6.3.1).
Crest tait_at_x0l_0031(const std::string& label, const std::vector<std::string>& extra) {
  std::vector<std::string> overrides = {"time.end=30", "output.snapshot_interval=0", "excitation.amplitude=0.029946"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  double omega = 0.0;
  const auto r = run_case_in_memory("tait2005_screens.toml", overrides,
                                    [&](const Simulation& s) { omega = s.spec().excitation.omega; });
  return gauge_crest(r, omega, 8, "30 s", "tait_x0l0031_" + label);
}

// Reference: the explicit slats (5 mm slats, 7 mm gaps, 1 mm thick, as rigid wall particles) stand
// for the real screens; the Ergun screens at the case's dp = 7 mm must give the same average maximum
// wave height within 15% (issue 3). The minimum is reported beside it. The slats at dp = 1.4 mm (issue
// 29, "then use the speed", item 3: at least 5 particle spacings across each 7 mm gap; until
// 2026-12-07 the test ran them at 2.5 mm, under 3 spacings a gap, docs/validation/notes.md): 58,486
// fluid particles, the slats one particle thick (the reader's warning), dt = 0.4 ms (the case's 0.5 ms
// is above the bound 0.4 dp / sqrt(g h) = 0.45 ms at this dp), the scheme's defaults as the Ergun run's.
TEST(ValidationLong, TaitErgunScreensAgainstExplicitSlatsAtX0L0031) {
  const Crest ergun = tait_at_x0l_0031("ergun_dp7mm", {});
  const Crest slats = tait_at_x0l_0031("explicit_dp1.4mm", {"screens.0.model=\"explicit\"", "screens.1.model=\"explicit\"",
                                                           "particles.dp=0.0014", "time.dt=0.0004"});
  check_relative("average maximum wave height at x/L = 0.95, last 8 cycles, Ergun (dp = 7 mm)", ergun.avg_max,
                 slats.avg_max, 0.15, "the same screens as explicit slats at dp = 1.4 mm (issue 3; issue 29 item 3)", "m");
  report("tait_x0l0031_ergun_over_explicit_avg_min", ergun.avg_min / slats.avg_min);
  testing::record_curve({"gauge", "Tait tank at X0/L = 0.031, gauge at x/L = 0.95 (5 Hz low-pass)", "time (s)", "eta (m)",
                         ergun.t, ergun.gauge, "explicit slats, dp = 1.4 mm", slats.t, slats.gauge, false});
}

// cases/biswal_baffles*.toml (thesis 4.3.2, Biswal et al. 2006): L = 1 m, depth 0.5 m, baffles
// from both end walls at 0.1 m above the floor, L_b/L = 0.6, X0 = 2 mm, beta = 0.995, 15 s (12.6
// cycles); the gauge at the right wall (x = 0.995 m) after the 5 Hz zero-phase filter, averages
// over the last 10 cycles (the response still grows at resonance: the two forms are compared
// over the same build-up).
Crest biswal(const std::string& file, const std::string& label, const std::vector<std::string>& extra) {
  std::vector<std::string> overrides = {"output.snapshot_interval=0"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  double omega = 0.0;
  const auto r = run_case_in_memory(file, overrides, [&](const Simulation& s) { omega = s.spec().excitation.omega; });
  return gauge_crest(r, omega, 10, "15 s", "biswal_" + label);
}

// Reference: the baffles as rigid wall particles (the thesis's "MM" model, dp = 5 mm); the Ergun
// line across the tank (the thesis's "ER" model, dp = 10 mm, porosity = the open fraction
// 1 - L_b/L = 0.4) must give the same average crest at the wall within 15% (issue 3). Recorded,
// not asserted: the Ergun line with the porosity the thesis prints, n_w = L_b/L = 0.6.
// Wall time, one thread beside one other job (2026-12-03): 527 s for each Ergun run, 2,768 s for
// the explicit one.
TEST(ValidationLong, BiswalBafflesErgunAgainstExplicit) {
  const Crest explicit_baffles = biswal("biswal_baffles_explicit.toml", "explicit_dp5mm", {});
  const Crest ergun = biswal("biswal_baffles.toml", "ergun_dp10mm", {});
  const Crest thesis_porosity = biswal("biswal_baffles.toml", "ergun_dp10mm_porosity_0.6", {"screens.0.solidity=0.4"});
  check_relative("average crest at the right wall, last 10 cycles, Ergun line (dp = 10 mm, porosity 0.4)",
                 ergun.avg_max, explicit_baffles.avg_max, 0.15,
                 "the baffles as rigid wall particles at dp = 5 mm (thesis 4.3.2 MM model; issue 3)", "m");
  testing::check(testing::Check{
      .quantity = "average crest at the right wall, last 10 cycles, Ergun line with the thesis's n_w = L_b/L = 0.6",
      .unit = "m",
      .measured = thesis_porosity.avg_max,
      .kind = testing::Tolerance::relative,
      .reference = explicit_baffles.avg_max,
      .tolerance = 0.15,
      .source = "the baffles as rigid wall particles at dp = 5 mm (thesis 4.3.2 prints n_w = L_b/L)",
      .asserted = false});
  report("biswal_ergun_over_explicit_avg_max", ergun.avg_max / explicit_baffles.avg_max);
  report("biswal_ergun_over_explicit_avg_min", ergun.avg_min / explicit_baffles.avg_min);
  testing::record_curve({"wall_gauge", "Biswal baffled tank, L_b/L = 0.6, wave at the right wall (5 Hz low-pass)",
                         "time (s)", "eta (m)", ergun.t, ergun.gauge, "explicit baffles, dp = 5 mm",
                         explicit_baffles.t, explicit_baffles.gauge, false});
}

}  // namespace
}  // namespace sloshsph
