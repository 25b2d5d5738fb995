// Steady-state amplitudes, energy per cycle, normalised error (steady_state.hpp, compare.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sloshsph/analysis/compare.hpp"
#include "sloshsph/analysis/steady_state.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SteadyStateAmplitude, OffsetSine) {
  // x = 0.3 + 2 sin(w t + 0.7), 20 samples a period, with a decaying transient in the first cycles:
  // avg_max = 2.3, avg_min = -1.7. Parabolic refinement error <= h^4 / 64 of the amplitude at
  // h = w dt = 0.31 (1.5e-4): tolerance 1e-3 relative.
  const double T = 2.0, dt = T / 20;
  std::vector<double> t, x;
  for (int i = 0; i <= 400; ++i) {
    const double ti = i * dt + 0.0123;
    t.push_back(ti);
    x.push_back(0.3 + 2 * std::sin(2 * kPi * ti / T + 0.7) + 5 * std::exp(-ti));
  }
  const SteadyAmplitude a = steady_state_amplitude(t, x, T, 5);
  EXPECT_EQ(a.cycles, 5);
  EXPECT_NEAR(a.avg_max, 2.3, 2e-3);
  EXPECT_NEAR(a.avg_min, -1.7, 2e-3);
  // Without refinement the raw sample extremes can be off by up to 2 (1 - cos(pi / 20)) = 0.025.
  std::printf("steady amplitude: max %.6f (2.3), min %.6f (-1.7)\n", a.avg_max, a.avg_min);
  // Fewer cycles than asked if the record is short; none fits -> error.
  EXPECT_EQ(steady_state_amplitude(t, x, T, 1000).cycles, 20);
  EXPECT_THROW(steady_state_amplitude(t, x, 100.0, 3), std::invalid_argument);
}

TEST(EnergyPerCycle, ViscousDamperAndSpring) {
  // X = X0 sin(w t). A viscous force F = c X' dissipates pi c w X0^2 per cycle (closed form);
  // a spring force F = k X dissipates nothing. Trapezoid on F dX with h = w dt: relative error
  // 1 - sin(h)/h ~ h^2/6 = 1.6e-4 at 200 samples a period: tolerance 1e-3.
  const double X0 = 0.01, w = 3.0, c = 50.0, k = 1000.0;
  const double T = 2 * kPi / w, dt = T / 200;
  std::vector<double> t, fv, fk, x;
  for (int i = 0; i <= 2000; ++i) {
    t.push_back(i * dt);
    x.push_back(X0 * std::sin(w * i * dt));
    fv.push_back(c * X0 * w * std::cos(w * i * dt));
    fk.push_back(k * x.back());
  }
  const CycleEnergy ev = energy_per_cycle(t, fv, x, T, 5);
  EXPECT_EQ(ev.cycles, 5);
  EXPECT_NEAR(ev.energy / (kPi * c * w * X0 * X0), 1.0, 1e-3);
  EXPECT_NEAR(energy_per_cycle(t, fk, x, T, 5).energy, 0.0, 1e-6 * k * X0 * X0);
  // A window starting between samples (period not a multiple of dt) is interpolated.
  const CycleEnergy odd = energy_per_cycle(t, fv, x, T * 1.0, 3);
  EXPECT_NEAR(odd.energy / (kPi * c * w * X0 * X0), 1.0, 1e-3);
  // Thesis eq. 4.27 normalisation: E' = E / (0.5 m (X0 w)^2).
  EXPECT_DOUBLE_EQ(normalised_energy(2.0, 4.0, 0.5, 2.0), 2.0 / (0.5 * 4.0 * 1.0));
  std::printf("energy per cycle: %.8f J vs pi c w X0^2 = %.8f J\n", ev.energy, kPi * c * w * X0 * X0);
}

TEST(NormalisedError, ThesisEq229) {
  const std::vector<double> beta{0.8, 0.9, 1.0, 1.1, 1.2};
  const std::vector<double> f_exp{1.0, 2.0, 4.0, 2.0, 1.0};
  // Identical curves: 0. A model 10% high everywhere: exactly 0.1.
  EXPECT_DOUBLE_EQ(normalised_error(beta, f_exp, beta, f_exp).epsilon, 0.0);
  std::vector<double> high = f_exp;
  for (double& v : high) v *= 1.1;
  EXPECT_NEAR(normalised_error(beta, f_exp, beta, high).epsilon, 0.1, 1e-12);
  // Model on a finer grid, linear in beta: interpolation onto the reference abscissae is exact.
  std::vector<double> xm, fm;
  for (int i = 0; i <= 40; ++i) {
    xm.push_back(0.8 + 0.01 * i);
    fm.push_back(3.0 * xm.back());
  }
  const std::vector<double> ref_lin{2.4, 2.7, 3.0, 3.3, 3.6};
  EXPECT_NEAR(normalised_error(beta, ref_lin, xm, fm).epsilon, 0.0, 1e-14);
  // Reference points outside the model range are skipped and counted.
  const std::vector<double> xm_short{0.85, 1.15}, fm_short{2.55, 3.45};
  const NormalisedError e = normalised_error(beta, ref_lin, xm_short, fm_short);
  EXPECT_EQ(e.points, 3u);
  EXPECT_EQ(e.skipped, 2u);
  EXPECT_NEAR(e.epsilon, 0.0, 1e-14);
  EXPECT_THROW(normalised_error(beta, ref_lin, {1.0, 0.9}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(normalised_error(beta, ref_lin, {5.0, 6.0}, {1.0, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// Reference: a dashpot c driven at X = X0 sin(w t) takes W(t) = c X0^2 w^2 (t/2 + sin(2 w t)/(4 w))
// from the base; over whole cycles the oscillating part cancels: E = pi c w X0^2 per cycle.
// Tolerance 1e-4 relative: the only error is the linear interpolation of W at the window
// start (the sample spacing does not divide the period); measured 1.5e-7.
TEST(EnergyFromWork, DashpotWorkPerCycle) {
  const double c = 3.0, x0 = 0.005, w = 2.0 * std::numbers::pi * 0.9;
  std::vector<double> t, work;
  for (int k = 0; k <= 3000; ++k) {
    const double s = 0.01 * k;
    t.push_back(s);
    work.push_back(c * x0 * x0 * w * w * (s / 2.0 + std::sin(2.0 * w * s) / (4.0 * w)));
  }
  const CycleEnergy e = energy_per_cycle_from_work(t, work, 2.0 * std::numbers::pi / w, 10);
  EXPECT_EQ(e.cycles, 10);
  std::printf("energy from work: ratio to pi c w X0^2 = %.12f\n", e.energy / (std::numbers::pi * c * w * x0 * x0));
  EXPECT_NEAR(e.energy / (std::numbers::pi * c * w * x0 * x0), 1.0, 1e-4);
}

}  // namespace
}  // namespace sloshsph
