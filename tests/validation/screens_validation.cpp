// Screens in a tuned liquid damper: thesis 2.6.3 / Tait et al. (2005), the tank of
// cases/tld_no_screens.toml with and without the two Ergun screens of cases/tait2005_screens.toml.
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "run_support.hpp"
#include "sloshsph/analysis/filter.hpp"
#include "sloshsph/analysis/steady_state.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/linear/rectangular.hpp"
#include "sloshsph/physics/porous.hpp"
#include "sloshsph/run/linear_case.hpp"
#include "sloshsph/run/simulation.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_absolute;
using testing::check_at_least;
using testing::check_at_most;
using testing::check_relative;
using testing::report;
using testing::run_case_in_memory;

struct TankResponse {
  double eta_max = 0.0;  // average of the last cycles' maxima of the gauge at x/L = 0.95, m
  double eta_min = 0.0;
  double energy = 0.0;   // energy taken from the base per cycle, eq. 4.28 from W_base, J/m
  std::vector<double> t, gauge;  // s; the gauge at x/L = 0.95 after the 5 Hz filter, m
};

// Both runs at X0/L = 0.005, beta = 1.0 (of the exact linear frequency), 40 s (21.8 cycles),
// averaged over the last 13 cycles after the 5 Hz zero-phase filter (thesis 2.6.3.1). To fit
// CI: dp = 10 mm (12 particles across the depth; the thesis uses 5-7 mm) and dt = 1 ms (a
// quarter of the fixed-step bound 0.4 dp / sqrt(g h) = 3.7 ms). Why so many cycles: without
// screens the resonant response beats (measured: the per-cycle energy swings between 0.14 and
// 0.73 J/m and the crest between 35 and 56 mm over cycles 5-21, not settled at 40 s; the
// thesis runs 120 s), while with screens it settles by cycle 10 (0.51-0.60 J/m). A window
// shorter than a beat compares a phase of the beat, not the damping: at 16 s (last 3 cycles)
// the energy ordering came out reversed (0.60 with screens vs 0.66 without).
TankResponse respond(const std::string& case_name) {
  const auto r = run_case_in_memory(case_name, {"particles.dp=0.01", "time.dt=0.001", "time.end=40", "excitation.amplitude=0.00483",
                                                "excitation.beta=1.0", "output.snapshot_interval=0"});
  check_at_most("particles leaked from the tank in 40 s, " + case_name, static_cast<double>(r.leaked), 0.0,
                "none may leave");
  const double omega = rectangular_sloshing_omega(0.966, 0.119, 9.81);
  const double period = 2.0 * std::numbers::pi / omega, dt = r["time"][1] - r["time"][0];
  std::vector<double> gauge = lowpass_zero_phase(r["eta:right"], dt);
  const auto eta = steady_state_amplitude(r["time"], gauge, period, 13);
  const auto e = energy_per_cycle_from_work(r["time"], r["W_base"], period, 13);
  std::printf("  %s: %zu steps in %.0f s\n", case_name.c_str(), r.steps, r.wall_seconds);
  return {eta.avg_max, eta.avg_min, e.energy, r["time"], std::move(gauge)};
}

// Reference: Tait et al. (2005) and thesis Fig. 2.12-2.14: screens damp the sloshing, so at
// resonance the wave is lower with screens and the liquid takes more energy per cycle from the
// base (the screens dissipate it). The bar is the ordering, as the issue states it; no
// tolerance on the size of the difference. The energy with screens must be positive.
TEST(Validation, TaitScreensDampTheResonance) {
  const TankResponse none = respond("tld_no_screens.toml");
  const TankResponse screens = respond("tait2005_screens.toml");
  report("tait_no_screens_eta_max_m", none.eta_max);
  report("tait_no_screens_eta_min_m", none.eta_min);
  report("tait_no_screens_energy_per_cycle_J_per_m", none.energy);
  report("tait_screens_eta_max_m", screens.eta_max);
  report("tait_screens_eta_min_m", screens.eta_min);
  report("tait_screens_energy_per_cycle_J_per_m", screens.energy);
  const std::string ordering = "the same tank without screens, measured (Tait et al. 2005, thesis Fig. 2.12-2.14)";
  check_at_most("average crest at x/L = 0.95 with screens, last 13 cycles", screens.eta_max, none.eta_max,
                "lower than in " + ordering, "m");
  check_at_least("energy taken from the base per cycle with screens, last 13 cycles", screens.energy, 0.0,
                 "positive: the liquid takes energy from the base", "J/m");
  check_at_least("energy taken from the base per cycle with screens, last 13 cycles", screens.energy, none.energy,
                 "more than in " + ordering, "J/m");
  testing::record_curve({"gauge", "Tuned liquid damper at resonance, gauge at x/L = 0.95 (5 Hz low-pass)", "time (s)",
                         "eta (m)", screens.t, screens.gauge, "without screens (same tank, measured)", none.t, none.gauge,
                         false});
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// The flow: cases/ergun_utube.toml, levels 0.16 m and 0.08 m either side of a screen of
// solidity 0.8, 20 mm thick, in a 0.4 m tank, dp = 5 mm. The screen's drag dominates the
// inertia of the water (rho L du/dt is about 1% of the drop), so the flow is quasi-steady: at
// each instant the level difference dh drives through the screen the flux Ergun's law allows,
//   Q(dh) = u(rho g dh) h_R + integral from h_R to h_L of u(rho g (h_L - y)) dy,
// u(dP) the superficial velocity whose Ergun drop t (mu/K u + 1.75/sqrt(150) rho/(sqrt(K) n^1.5)
// u^2) is dP (thesis eqs. 2.21-2.22; the part above the lower level sees a drop that falls to
// 0 at the upper level), and the levels follow d(dh)/dt = -4 Q / L (each half L/2 wide).
// The test finds the factor c on Ergun's drop for which this model, started from the measured
// dh at 0.3 s, reaches the measured dh at 2.5 s (dh measured by the pressure probes 0.1 m either
// side of the screen, 0.03 m above the floor, as (p_L - p_R)/(rho g), averaged over +-0.1 s
// against sloshing within each half). c is the screen's pressure drop in the simulation
// relative to Ergun's. Reference: c = 1 within 10% (the tolerance).
struct UtubeFit {
  double c = 0.0;          // simulated pressure drop / Ergun's
  double dh_start = 0.0;   // m, at 0.3 s
  double dh_end = 0.0;     // m, at 2.5 s
};

UtubeFit fit_ergun_factor(const std::string& velocity) {
  const auto r = run_case_in_memory("ergun_utube.toml", {"time.end=2.6", "output.snapshot_interval=0",
                                                         "output.sample_interval=0.01", "screens.0.velocity=" + velocity});
  check_at_most("particles leaked from the tank in 2.6 s, screen velocity " + velocity, static_cast<double>(r.leaked), 0.0,
                "none may leave");
  const double rho = 1000.0, g = 9.81, mu = 1.0e-3, length = 0.4, mean_depth = 0.12;
  const double n = 0.2, K = kozeny_carman_permeability(n, 0.005), t_sc = 0.02;
  auto level_difference = [&](double t0) {
    double sum = 0.0;
    int k = 0;
    for (std::size_t i = 0; i < r["time"].size(); ++i)
      if (std::abs(r["time"][i] - t0) <= 0.1 + 1e-9) {
        sum += (r["p:left"][i] - r["p:right"][i]) / (rho * g);
        ++k;
      }
    return sum / k;
  };
  auto flux = [&](double dh, double c) {
    // u from c * Ergun(u) = dP: the positive root of c (a u + b u^2) = dP.
    const double a = c * norm(ergun_pressure_gradient(mu, rho, K, n, Vec2{1.0, 0.0})) * t_sc;  // a + b at u = 1
    const double b = c * t_sc * 1.75 / std::sqrt(150.0) * rho / (std::sqrt(K) * std::pow(n, 1.5));
    const double a_lin = a - b;  // viscous part
    auto u = [&](double dP) { return (-a_lin + std::sqrt(a_lin * a_lin + 4.0 * b * std::max(dP, 0.0))) / (2.0 * b); };
    const double h_right = mean_depth - 0.5 * dh;
    double q = u(rho * g * dh) * h_right;
    const int slices = 20;
    for (int k = 0; k < slices; ++k) q += u(rho * g * dh * (1.0 - (k + 0.5) / slices)) * dh / slices;
    return q;
  };
  auto evolve = [&](double dh, double c) {
    for (double t = 0.3; t < 2.5 - 1e-9; t += 1e-3) dh -= 4.0 / length * flux(dh, c) * 1e-3;
    return dh;
  };
  UtubeFit fit{0.0, level_difference(0.3), level_difference(2.5)};
  double lo = 0.2, hi = 5.0;  // more resistance (larger c): slower decay, larger dh at the end
  for (int it = 0; it < 40; ++it) {
    fit.c = 0.5 * (lo + hi);
    (evolve(fit.dh_start, fit.c) < fit.dh_end ? lo : hi) = fit.c;
  }
  std::printf("  velocity = %s: dh %.4f m -> %.4f m over 0.3-2.5 s; pressure drop / Ergun's = %.3f\n", velocity.c_str(),
              fit.dh_start, fit.dh_end, fit.c);
  return fit;
}

// A Morison screen (C_l = 10, at the middle of the tank, where the first mode's flow through it is
// largest) in the clean tank of cases/clean_tank_forced.toml (L = 0.5 m, h = 0.25 m, dp = 1/120 m:
// 30 particles over the depth) forced from rest at its first natural frequency, X0 = 1 mm, 12.5 s
// (15 periods), at h = 2 dp with the Shepard velocity at the screen. Reference: the linear modal
// model with the screen's quadratic pressure loss 1/2 rho C_l |u| u acting on the modes through the
// potential flow at the screen (`sloshsph linear`, linear/screen_drag.hpp) and the scheme's own
// damping of the first mode at h = 2 dp, zeta = 0.33% (the free decay of docs/validation/notes.md,
// "Numerical damping"): its steady amplitude is 11.47 mm, the screen's equivalent damping about
// 5% of critical, 15 times the scheme's. Compared: the half crest-to-trough height of both gauges
// over the last 4 periods, both series low-passed at 5 Hz. Bar 10%: the amplitude of a
// screen-dominated resonance goes as C_l^(-1/2), so 10% is 20% in the screen's loss, and the rest
// of the model's differences from the run (weak nonlinearity, ka = 0.07; the screen force spread
// over the kernel) are a few percent. Measured 2026-12-07: +6.3% (left) and +6.4% (right) over
// periods 11-14; in a 25 s run +5.5% to +6.2% from period 10 on. With the thesis's unnormalised
// velocity sum (the default; the same 25 s run) +16%: the kernel truncated at the surface and the
// bottom under-drives the screen, as if its loss coefficient were about 25% lower.
TEST(Validation, MorisonScreenMatchesTheLinearModelWithItsQuadraticLoss) {
  const std::vector<std::string> sets = {
      "excitation.beta=1.0", "time.end=12.5", "particles.kernel_ratio=2.0",
      "screens=[{name=\"M\", x=0.25, solidity=0.5, loss_coefficient=10.0, model=\"morison\", velocity=\"shepard\"}]"};
  const auto run = run_case_in_memory("clean_tank_forced.toml", sets);
  const CaseSpec spec = resolve_case(read_case_file(testing::case_path("clean_tank_forced.toml"), sets));
  LinearCaseOptions options;
  options.damping = "0.0033";
  const LinearCase linear = linear_case_response(spec, options);
  ASSERT_EQ(linear.screens.size(), 1u);
  const double period = 2.0 * std::numbers::pi / spec.excitation.omega;
  auto half_height = [&](const std::vector<double>& t, const std::vector<double>& eta) {
    const SteadyAmplitude a = steady_state_amplitude(t, lowpass_zero_phase(eta, t[1] - t[0]), period, 4);
    return 0.5 * (a.avg_max - a.avg_min);
  };
  for (std::size_t g = 0; g < linear.gauge_names.size(); ++g) {
    const std::string column = "eta:" + linear.gauge_names[g];
    check_relative("steady half height at gauge '" + linear.gauge_names[g] + "', Morison screen, Shepard velocity",
                   half_height(run["time"], run[column]), half_height(linear.response.time, linear.response.elevation[g]),
                   0.10, "linear modal model with the screen's quadratic loss and the scheme's zeta = 0.33%", "m");
  }
  check_at_most("particles leaked", static_cast<double>(run.leaked), 0.0, "none may leave");
}

// Both velocity estimates of the screen particles. "shepard" must meet Ergun within 10%. The
// thesis's kernel sum (eq. 2.26) is truncated within 2 h_sc of the floor and of the free surface
// (here 35 mm of a 80-160 mm column), so its drag falls short; its factor is reported, and only
// checked to be below the Shepard one (the truncation can only lower the velocity estimate).
TEST(Validation, ErgunScreenPressureDropInAFlowThroughIt) {
  const UtubeFit shepard = fit_ergun_factor("shepard");
  const UtubeFit thesis = fit_ergun_factor("thesis");
  report("ergun_utube_pressure_drop_ratio_shepard", shepard.c);
  report("ergun_utube_pressure_drop_ratio_thesis", thesis.c);
  check_absolute("screen pressure drop / Ergun's (fitted factor c), Shepard velocity", shepard.c, 1.0, 0.10,
                 "Ergun's law (thesis eqs. 2.21-2.22) in the quasi-steady level decay 0.3-2.5 s");
  check_at_most("screen pressure drop / Ergun's (fitted factor c), thesis kernel-sum velocity (eq. 2.26)", thesis.c,
                shepard.c, "the Shepard factor, measured: the truncated kernel sum can only lower the velocity");
  // The flow was driven (0.08 m at the start).
  check_at_least("level difference across the screen at 0.3 s, Shepard velocity", shepard.dh_start, 0.06,
                 "the case's initial levels 0.16 m and 0.08 m: 0.08 m", "m");
}

}  // namespace
}  // namespace sloshsph
