// SDOF structure with Newmark average acceleration (src/sloshsph/structure/sdof.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/structure/sdof.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

// Mean period between up-crossings of zero (linear interpolation of the crossing times).
double upcrossing_period(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> tc;
  for (std::size_t i = 0; i + 1 < x.size(); ++i)
    if (x[i] < 0 && x[i + 1] >= 0) tc.push_back(t[i] + (t[i + 1] - t[i]) * (-x[i]) / (x[i + 1] - x[i]));
  return tc.size() < 2 ? 0.0 : (tc.back() - tc.front()) / static_cast<double>(tc.size() - 1);
}

// Free vibration from x0 for `periods` natural periods at `steps_per_period`; returns (t, x).
void free_vibration(Sdof& s, double x0, int periods, int steps_per_period, std::vector<double>& t,
                    std::vector<double>& x) {
  s.set_state(x0, 0.0);
  const double dt = 1.0 / (s.spec().natural_frequency() * steps_per_period);
  t = {0.0};
  x = {x0};
  for (int n = 0; n < periods * steps_per_period; ++n) {
    s.step(dt, 0.0);
    t.push_back(s.time());
    x.push_back(s.displacement());
  }
}

TEST(SdofSpec, ThesisStructure) {
  // Thesis sec. 4.4.2.2: M = 70,000 t, C = 1,180,000 N s/m, K = 49,600,000 N/m "resulting in a
  // natural frequency of 0.134 Hz" and zeta = 1%. Tolerances: the rounding of the published
  // numbers (0.134 to 3 digits: 0.5%; zeta 1%).
  const SdofSpec s{7.0e7, 1.18e6, 4.96e7};
  EXPECT_NEAR(s.natural_frequency(), 0.134, 0.005 * 0.134);
  EXPECT_NEAR(s.damping_ratio(), 0.01, 0.01 * 0.01);
  const SdofSpec t = SdofSpec::from_frequency(1000.0, 2.0, 0.03);
  EXPECT_NEAR(t.natural_frequency(), 2.0, 1e-12);
  EXPECT_NEAR(t.damping_ratio(), 0.03, 1e-14);
  // Closed form: static F0/K at r = 0, F0 / (2 zeta K) at r = 1.
  EXPECT_DOUBLE_EQ(t.closed_form_steady_amplitude(5.0, 0.0), 5.0 / t.stiffness);
  EXPECT_NEAR(t.closed_form_steady_amplitude(5.0, 4 * kPi), 5.0 / (0.06 * t.stiffness), 1e-15);
}

TEST(SdofSpec, BadSpecIsInputError) {
  try {
    check_sdof_spec({0.0, 1.0, 1.0}, "case.toml", "structure");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "structure.mass");
  }
  EXPECT_THROW(check_sdof_spec({1.0, -1.0, 1.0}, "", "s"), InputError);
  EXPECT_THROW(Sdof(SdofSpec{1.0, 0.0, 0.0}), InputError);
}

TEST(Sdof, HarmonicSteadyStateMatchesClosedForm) {
  // F = F0 sin(w t) (and the same with a ground acceleration A sin(w t), F0 = M A) from rest;
  // zeta = 5%: transients ~ e^{-zeta w_n t} < 1e-6 after 45 forcing periods at r >= 0.5;
  // amplitude = max |x| over the last 5 periods, dt = T/200 (sampling error of the max 1.2e-4,
  // Newmark period error (w dt)^2 / 12 < 1e-4). Tolerance 1% (brief).
  const SdofSpec spec = SdofSpec::from_frequency(500.0, 1.5, 0.05);
  const double F0 = 20.0;
  for (double r : {0.5, 0.95, 1.0, 1.5}) {
    for (bool ground : {false, true}) {
      Sdof s(spec);
      const double w = r * spec.angular_frequency(), T = 2 * kPi / w, dt = T / 200;
      double amp = 0;
      const int steps = 50 * 200;
      for (int n = 1; n <= steps; ++n) {
        const double f = F0 * std::sin(w * n * dt);
        if (ground)
          s.step(dt, 0.0, -f / spec.mass);  // -M a_g = F
        else
          s.step(dt, f);
        if (n > steps - 5 * 200) amp = std::max(amp, std::abs(s.displacement()));
      }
      const double ref = s.closed_form_steady_amplitude(F0, w);
      EXPECT_NEAR(amp / ref, 1.0, 0.01) << "r = " << r << (ground ? " ground" : " force");
      if (!ground) std::printf("r = %.2f: amplitude / closed form = %.6f\n", r, amp / ref);
    }
  }
}

TEST(Sdof, FreeVibrationPeriodAndLogDecrement) {
  // Damped period T_d = 2 pi / (w_n sqrt(1 - zeta^2)); Newmark lengthens it by ~ (w_n dt)^2 / 12
  // = 3.3e-4 at 100 steps a period: tolerance 0.1%. Log decrement over 10 cycles,
  // delta = ln(x_0 / x_10) / 10 = 2 pi zeta / sqrt(1 - zeta^2) -> zeta within 1% (Newmark changes
  // the decay rate by O((w dt)^2) too).
  const double zeta = 0.02;
  Sdof s(SdofSpec::from_frequency(10.0, 0.8, zeta));
  std::vector<double> t, x;
  free_vibration(s, 0.05, 20, 100, t, x);
  const double td = 1.0 / (0.8 * std::sqrt(1 - zeta * zeta));
  const double period = upcrossing_period(t, x);
  EXPECT_NEAR(period / td, 1.0, 1e-3);
  // Peaks: local maxima refined by a parabola through three samples.
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < x.size(); ++i)
    if (x[i] > x[i - 1] && x[i] >= x[i + 1]) {
      const double d = 0.5 * (x[i + 1] - x[i - 1]), c2 = x[i + 1] - 2 * x[i] + x[i - 1];
      peaks.push_back(x[i] - d * d / (2 * c2));
    }
  ASSERT_GE(peaks.size(), 11u);
  const double delta = std::log(peaks[0] / peaks[10]) / 10;
  const double zeta_meas = delta / std::sqrt(4 * kPi * kPi + delta * delta);
  EXPECT_NEAR(zeta_meas / zeta, 1.0, 0.01);
  std::printf("free vibration: T / T_d = %.6f, zeta from log decrement %.6f (0.02)\n", period / td, zeta_meas);
}

TEST(Sdof, EnergyConservedWithoutDampingAndBalancedWithIt) {
  // Undamped linear free vibration: Newmark average acceleration conserves (M v^2 + K x^2) / 2
  // exactly (trapezoidal rule); tolerance 1e-10 relative (brief) over 1000 periods at only 20
  // steps a period (rounding only).
  Sdof s(SdofSpec{3.0, 0.0, 1200.0});
  s.set_state(0.02, 0.5);
  const double e0 = s.mechanical_energy();
  const double dt = 2 * kPi / s.spec().angular_frequency() / 20;
  double worst = 0;
  for (int n = 0; n < 20000; ++n) {
    s.step(dt, 0.0);
    worst = std::max(worst, std::abs(s.mechanical_energy() - e0) / e0);
  }
  EXPECT_LT(worst, 1e-10);
  // Damped and forced: E_n - E_0 = input work - dissipated energy, exactly (to rounding).
  Sdof d(SdofSpec::from_frequency(3.0, 2.0, 0.05));
  double worst_balance = 0, scale = 0;
  for (int n = 1; n <= 5000; ++n) {
    d.step(0.01, 7.0 * std::sin(3.0 * n * 0.01), 0.5 * std::cos(11.0 * n * 0.01));
    scale = std::max(scale, d.mechanical_energy() + d.dissipated_energy());
    worst_balance = std::max(worst_balance, std::abs(d.mechanical_energy() - (d.input_work() - d.dissipated_energy())));
  }
  EXPECT_LT(worst_balance / scale, 1e-10);
  std::printf("energy: undamped drift %.2e, damped balance residual %.2e (relative)\n", worst, worst_balance / scale);
}

TEST(Sdof, AddedMassLowersFrequency) {
  // A rigid extra mass m moving with the structure: f = sqrt(K / (M + m)) / (2 pi); tolerance 0.5% (brief).
  const SdofSpec spec{100.0, 0.0, 4.0e4};
  const double m = 20.0;
  const double f_ref = std::sqrt(spec.stiffness / (spec.mass + m)) / (2 * kPi);
  // (a) Implicit: set_added_mass.
  Sdof a(spec);
  a.set_added_mass(m);
  std::vector<double> t, x;
  free_vibration(a, 0.01, 30, 200, t, x);  // dt from the bare f_n: ~220 steps per loaded period
  const double fa = 1.0 / upcrossing_period(t, x);
  EXPECT_NEAR(fa / f_ref, 1.0, 0.005);
  // (b) Explicit staggered coupling, as a fluid solver would do it: the extra mass's inertia force
  // -m x''_abs from the PREVIOUS step is the external force of the next step. The lag acts as a
  // small damping (estimate (m / (M + m)) w dt / 2 = 2.4e-3 of critical here; printed) but keeps
  // the frequency.
  Sdof b(spec);
  const double dt = 1.0 / (spec.natural_frequency() * 200);
  // Consistent start of the coupled system at rest at x0: x'' = -K x0 / (M + m), so the extra
  // mass pushes with -m x'' = m K x0 / (M + m).
  double force = m * spec.stiffness * 0.01 / (spec.mass + m);
  b.set_state(0.01, 0.0, force);
  t = {0.0};
  x = {0.01};
  double first_peak = 0.01, last_peak = 0.0;
  int peaks = 0;
  for (int n = 0; n < 30 * 200; ++n) {
    b.step(dt, force);
    force = -m * b.absolute_acceleration();
    t.push_back(b.time());
    x.push_back(b.displacement());
    const std::size_t i = x.size() - 2;
    if (i > 0 && x[i] > x[i - 1] && x[i] >= x[i + 1]) last_peak = x[i], ++peaks;
  }
  const double fb = 1.0 / upcrossing_period(t, x);
  EXPECT_NEAR(fb / f_ref, 1.0, 0.005);
  const double zeta_lag = std::log(first_peak / last_peak) / (2 * kPi * peaks);
  std::printf("added mass: f / f_ref = %.6f (implicit), %.6f (lagged force); lag damping ratio %.2e\n", fa / f_ref,
              fb / f_ref, zeta_lag);
}

TEST(Sdof, WhiteNoiseResponseGivesDampingBack) {
  // Random vibration theory: for a white force of one-sided PSD S0, var(x) = S0 pi f_n / (4 zeta K^2)
  // (the area under the MAF |H|^2 is pi f_n / (4 zeta), Vickery et al. 1983, thesis eq. 4.30 with
  // a flat S0), so zeta_eff = pi f_n S0 / (4 K^2 var(x)). Force: discrete Gaussian white noise
  // (std::mt19937_64, whose output the standard fixes, with our own Box-Muller), S0 = 2 s^2 dt.
  // f_n = 1 Hz, zeta = 1%, dt = 0.02 s, 20000 periods. Statistical error of var(x) for this narrow-
  // band response: 1 / sqrt(zeta w_n T) = 2.8%. Tolerance 10% (brief) = 3.5 standard errors.
  const double f_n = 1.0, zeta = 0.01, dt = 0.02, sigma = 50.0;
  Sdof s(SdofSpec::from_frequency(200.0, f_n, zeta));
  std::mt19937_64 gen(77);
  auto uniform = [&] { return static_cast<double>(gen() >> 11) * 0x1.0p-53; };
  const int steps = 1000000;
  double sum_x2 = 0;
  const int skip = 5000;  // 100 s: transient from rest (e^{-zeta w_n t} = e^{-6.3})
  for (int n = 0; n < steps; n += 2) {
    const double r = std::sqrt(-2.0 * std::log(1.0 - uniform())), th = 2 * kPi * uniform();
    for (double f : {sigma * r * std::cos(th), sigma * r * std::sin(th)}) {
      s.step(dt, f);
      if (n >= skip) sum_x2 += s.displacement() * s.displacement();
    }
  }
  const double var = sum_x2 / (steps - skip);
  const double s0 = 2 * sigma * sigma * dt;
  const double k = s.spec().stiffness;
  const double zeta_eff = kPi * f_n * s0 / (4 * k * k * var);
  EXPECT_NEAR(zeta_eff / zeta, 1.0, 0.10);
  std::printf("white noise: zeta_eff = %.5f (0.01)\n", zeta_eff);
}

}  // namespace
}  // namespace sloshsph
