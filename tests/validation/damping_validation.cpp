// The scheme's own damping of a clean rectangular tank (issue 30, section 5): the free decay of
// cases/clean_tank_free_decay.toml and the forced response from rest of cases/clean_tank_forced.toml
// at 30 particles over the depth, against linear theory: omega1, the laminar boundary-layer damping
// (0.053% of critical) and the linear modal solution from rest (linear/forced_response.hpp). The
// issue's bars: zeta at most 0.5%, the response at the walls within 8% of the linear envelope
// over 8 periods (measured as half the crest-to-trough height of each period: analysis/envelope.hpp). At the default kernel ratio 1.4 the ISPH scheme misses both (recorded, not
// asserted; docs/validation/notes.md "Numerical damping"); at kernel_ratio = 2.0 its free decay
// meets the damping bar, and that is asserted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "run_support.hpp"
#include "sloshing_support.hpp"
#include "sloshsph/analysis/envelope.hpp"
#include "sloshsph/analysis/free_decay.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/linear/forced_response.hpp"
#include "sloshsph/run/linear_case.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::Check;
using testing::Tolerance;

constexpr double kDampingBar = 0.005;   // issue 30, section 5
constexpr double kEnvelopeBar = 0.08;   // issue 30, section 5
constexpr double kFreeFrom = 2.6;       // s: one period after the excitation stops (1.67 s)

// A check recorded with its verdict; asserted only when `assert_it`.
void check_bar(const std::string& quantity, double measured, double bar, const std::string& source, bool assert_it,
               const std::string& unit = "") {
  testing::check(Check{.quantity = quantity,
                       .unit = unit,
                       .measured = measured,
                       .kind = Tolerance::at_most,
                       .reference = bar,
                       .tolerance = NAN,
                       .source = source,
                       .asserted = assert_it});
}

// Free decay: zeta and omega of each gauge from kFreeFrom on.
void check_free_decay(const std::vector<std::string>& overrides, const std::string& label, bool assert_damping) {
  const auto r = testing::run_case_in_memory("clean_tank_free_decay.toml", overrides);
  const double omega1 = rectangular_sloshing_omega(0.5, 0.25, 9.81);
  const double physical = rectangular_boundary_layer_damping(0.5, 0.25, 9.81, 1e-6);
  for (const char* gauge : {"eta:left", "eta:right"}) {
    const auto [t, y] = testing::window(r, gauge, kFreeFrom, 12.0);
    const FreeDecayFit fit = fit_free_decay(t, y);
    const std::string name = std::string(gauge + 4) + ", " + label;
    testing::report("clean_tank_zeta_" + std::string(gauge + 4), fit.zeta);
    testing::report("clean_tank_omega_error_" + std::string(gauge + 4), fit.omega / omega1 - 1.0);
    char physical_text[160];
    std::snprintf(physical_text, sizeof physical_text,
                  "issue 30 bar 0.5%% of critical; the tank's own laminar damping is %.3f%% (boundary layers, "
                  "linear/forced_response.hpp)",
                  100.0 * physical);
    check_bar("free-decay damping ratio (log decrement of " + std::to_string(fit.cycles) + " cycles), gauge " + name,
              fit.zeta, kDampingBar, physical_text, assert_damping);
    testing::check(Check{.quantity = "free-decay angular frequency, gauge " + name,
                         .unit = "rad/s",
                         .measured = fit.omega,
                         .kind = Tolerance::relative,
                         .reference = omega1,
                         .tolerance = 0.01,
                         .source = "linear theory omega1 = sqrt(pi g / L tanh(pi h / L)); 1%",
                         .asserted = assert_damping});
  }
  testing::check_at_most("particles leaked from the tank, " + label, static_cast<double>(r.leaked), 0.0,
                         "none may leave");
}

// Forced from rest: each gauge's amplitude (half the crest-to-trough height) in each of the first 8
// excitation periods against the linear modal solution's (10 modes, boundary-layer damping), both
// low-passed at the case's 5 Hz. Half heights, because the fill's still level is not the nominal one
// to a fraction of dp (+0.6-0.7 mm at h = 2 dp, a constant that is not sloshing).
void check_forced(const std::vector<std::string>& overrides, const std::string& label) {
  const auto r = testing::run_case_in_memory("clean_tank_forced.toml", overrides);
  const CaseSpec spec = resolve_case(read_case_file(testing::case_path("clean_tank_forced.toml"), overrides));
  const LinearCase linear = linear_case_response(spec, LinearCaseOptions{});
  const double period = 2.0 * std::numbers::pi / spec.excitation.omega;
  for (std::size_t g = 0; g < linear.gauge_names.size(); ++g) {
    const std::string column = "eta:" + linear.gauge_names[g];
    const EnvelopeComparison c = compare_envelopes(linear.response.time, linear.response.elevation[g],
                                                         r["time"], r[column], 0.0, period, 8,
                                                         spec.output.lowpass_hz);
    testing::report("clean_tank_forced_envelope_" + linear.gauge_names[g], c.worst_deviation);
    check_bar("largest deviation of the amplitude of a period from the linear one (8 periods, / largest linear amplitude), "
              "gauge " + linear.gauge_names[g] + ", " + label,
              c.worst_deviation, kEnvelopeBar,
              "issue 30 bar 8%; linear modal solution from rest, 10 modes, boundary-layer damping; both 5 Hz low-passed",
              false);
    testing::record_curve({"forced_" + linear.gauge_names[g],
                           "Clean tank forced from rest (beta 0.9, X0/L = 0.002), gauge " + linear.gauge_names[g] +
                               ", " + label,
                           "time (s)", "eta (m)", r["time"], r[column], "linear modal solution from rest",
                           linear.response.time, linear.response.elevation[g], false});
  }
}

TEST(Validation, CleanTankDampingAtTheDefaults) {
  check_free_decay({}, "ISPH, defaults (kernel ratio 1.4)", false);
  check_forced({}, "ISPH, defaults (kernel ratio 1.4)");
}

TEST(Validation, CleanTankDampingAtKernelRatio2) {
  check_free_decay({"particles.kernel_ratio=2.0"}, "ISPH, kernel ratio 2.0", true);
  check_forced({"particles.kernel_ratio=2.0"}, "ISPH, kernel ratio 2.0");
}

// The position predictor's own damping (scheme.predictor, docs/physics.md "The position
// predictor"). With r* = r + dt u* (thesis eq. 2.11) the pressure acts on the velocity as a force
// taken at the step's end, and with the trapezoidal position update of eq. 2.15 an oscillator
// x'' = -w^2 x is advanced by a matrix of determinant 1 - (w dt)^2 / 2: a damping ratio of w dt / 4.
// With r* = r + (dt/2) u* the determinant is 1. The clean tank at 15 particles over the depth and
// h = 2 dp (where the kernel's own damping is smallest), with the density term's relaxation time
// fixed so that only the predictor changes with the step; dt = 4 ms is just inside the case
// reader's bound 0.4 dp / sqrt(g h).
double mean_free_decay_zeta(const std::vector<std::string>& overrides) {
  std::vector<std::string> o = {"particles.dp=0.016666666666666666", "particles.kernel_ratio=2.0",
                                "scheme.density_relaxation_time=0.1"};
  o.insert(o.end(), overrides.begin(), overrides.end());
  const auto r = testing::run_case_in_memory("clean_tank_free_decay.toml", o);
  double sum = 0.0;
  for (const char* gauge : {"eta:left", "eta:right"}) {
    const auto [t, y] = testing::window(r, gauge, kFreeFrom, 12.0);
    sum += fit_free_decay(t, y).zeta;
  }
  std::string run;
  for (const std::string& o : overrides) run += " " + o;
  testing::check_at_most("particles leaked from the tank," + run, static_cast<double>(r.leaked), 0.0, "none may leave");
  return 0.5 * sum;
}

TEST(Validation, MidpointPredictorRemovesTheStepDamping) {
  const double euler_4ms = mean_free_decay_zeta({"scheme.predictor=euler", "time.dt=0.004"});
  const double midpoint_4ms = mean_free_decay_zeta({"scheme.predictor=midpoint", "time.dt=0.004"});
  const double midpoint_2ms = mean_free_decay_zeta({"scheme.predictor=midpoint", "time.dt=0.002"});
  const double omega1 = rectangular_sloshing_omega(0.5, 0.25, 9.81);
  testing::report("predictor_zeta_euler_4ms", euler_4ms);
  testing::report("predictor_zeta_midpoint_4ms", midpoint_4ms);
  testing::report("predictor_zeta_midpoint_2ms", midpoint_2ms);
  testing::check(Check{.quantity = "free-decay damping of the Euler predictor less the midpoint's, dt = 4 ms",
                       .unit = "",  // fractions of critical damping
                       .measured = euler_4ms - midpoint_4ms,
                       .kind = Tolerance::relative,
                       .reference = omega1 * 0.004 / 4.0,
                       .tolerance = 0.25,
                       .source = "w1 dt / 4 of the Euler predictor with the trapezoidal update (docs/physics.md); 25%"});
  testing::check(Check{.quantity = "free-decay damping of the midpoint predictor, dt = 4 ms against 2 ms",
                       .unit = "",  // fractions of critical damping
                       .measured = midpoint_4ms,
                       .kind = Tolerance::absolute,
                       .reference = midpoint_2ms,
                       .tolerance = 0.0005,
                       .source = "a second-order, non-damping predictor: no change with the step; 0.05 points of critical"});
}

}  // namespace
}  // namespace sloshsph
