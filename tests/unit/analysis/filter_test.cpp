// Zero-phase Butterworth low-pass (src/sloshsph/analysis/filter.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/analysis/filter.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> sine(double f, double amplitude, double phase, double dt, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = amplitude * std::sin(2 * kPi * f * i * dt + phase);
  return x;
}

// Amplitude and phase of the component at f, by least squares onto sin/cos over the samples
// [first, last) (an integer number of periods, so the fit is a plain projection).
struct Fit {
  double amplitude, phase;
};
Fit fit_sine(const std::vector<double>& x, double f, double dt, std::size_t first, std::size_t last) {
  double s = 0, c = 0;
  for (std::size_t i = first; i < last; ++i) {
    s += x[i] * std::sin(2 * kPi * f * i * dt);
    c += x[i] * std::cos(2 * kPi * f * i * dt);
  }
  const double n = static_cast<double>(last - first);
  s *= 2 / n;
  c *= 2 / n;
  return {std::hypot(s, c), std::atan2(c, s)};
}

double db(double ratio) { return 20 * std::log10(ratio); }

TEST(Butterworth, DesignIsUnitDcGainAndMinus3dBAtCutoff) {
  // Butterworth magnitude 1 / sqrt(1 + (f/fc)^2n) with pre-warping: exactly 1/sqrt(2) at fc.
  for (int order : {1, 2, 3, 4, 5, 8}) {
    const auto s = butterworth_lowpass(order, 5.0, 1000.0);
    EXPECT_EQ(s.size(), static_cast<std::size_t>((order + 1) / 2));
    EXPECT_NEAR(std::abs(frequency_response(s, 0.0, 1000.0)), 1.0, 1e-12) << order;
    EXPECT_NEAR(std::abs(frequency_response(s, 5.0, 1000.0)), 1.0 / std::sqrt(2.0), 1e-12) << order;
    // Monotone decrease past the cut-off (no ripple): at 2 fc, below the analog 1/sqrt(1 + 4^n)
    // (the bilinear map only compresses frequencies, adding attenuation).
    EXPECT_LE(std::abs(frequency_response(s, 10.0, 1000.0)), 1.0 / std::sqrt(1.0 + std::pow(4.0, order)) + 1e-12);
  }
  EXPECT_THROW(butterworth_lowpass(4, 600.0, 1000.0), std::invalid_argument);
  EXPECT_THROW(butterworth_lowpass(0, 5.0, 1000.0), std::invalid_argument);
}

TEST(ZeroPhaseLowpass, PassBandSineUnchangedWithoutShift) {
  // 0.5 Hz sine, fs = 1000 Hz (dt of a typical SPH output 1 ms), fc = 5 Hz: |H|^2 = 1/(1 + 0.1^8)
  // -> amplitude within 0.5% (brief); zero phase: fitted phase difference and cross-correlation lag 0.
  const double dt = 1e-3, f = 0.5;
  const std::size_t n = 20000;  // 20 s = 10 periods
  const auto x = sine(f, 1.0, 0.3, dt, n);
  const auto y = lowpass_zero_phase(x, dt);
  const Fit fx = fit_sine(x, f, dt, 0, n), fy = fit_sine(y, f, dt, 0, n);
  EXPECT_NEAR(fy.amplitude / fx.amplitude, 1.0, 0.005);
  EXPECT_NEAR(fy.phase - fx.phase, 0.0, 1e-4);  // 1e-4 rad = 0.03 ms at 0.5 Hz: far below one sample
  // Cross-correlation c(lag) = sum x[i] y[i + lag] over a whole number of periods (8 periods,
  // samples 2000..17999, so c(lag) = (N/2) A^2 cos(w (lag dt) + phase error) exactly) over lags
  // -50..50 samples: peaks at lag 0.
  int best_lag = 99;
  double best = -1e300;
  for (int lag = -50; lag <= 50; ++lag) {
    double c = 0;
    for (std::size_t i = 2000; i < 18000; ++i) c += x[i] * y[i + lag];
    if (c > best) best = c, best_lag = lag;
  }
  EXPECT_EQ(best_lag, 0);
  // End effects: with the odd reflection and the steady-state (value and slope) start, the first
  // and last seconds follow the sine too (1% of the amplitude).
  double worst_end = 0;
  for (std::size_t i = 0; i < n; ++i) worst_end = std::max(worst_end, std::abs(y[i] - x[i]));
  EXPECT_LT(worst_end, 0.01);
  std::printf("pass band: amplitude ratio %.8f, phase %.2e rad, worst sample error incl. ends %.2e\n",
              fy.amplitude / fx.amplitude, fy.phase - fx.phase, worst_end);
}

TEST(ZeroPhaseLowpass, StopBandSineAttenuatedBy40dB) {
  // 50 Hz = 10 fc: analog 4th order forward-backward |H|^2 = 1/(1 + 10^8) (-160 dB); the brief asks > 40 dB.
  const double dt = 1e-3, f = 50.0;
  const std::size_t n = 4000;
  const auto y = lowpass_zero_phase(sine(f, 1.0, 0.0, dt, n), dt);
  const Fit fy = fit_sine(y, f, dt, 1000, 3000);
  EXPECT_LT(db(fy.amplitude), -40.0);
  std::printf("stop band (10 fc): %.1f dB\n", db(fy.amplitude));
}

TEST(ZeroPhaseLowpass, CutoffIsMinus6dB) {
  // Forward-backward squares |H|: at fc, |H|^2 = 1/2 = -6.02 dB; tolerance 0.1 dB (brief).
  const double dt = 1e-3, f = 5.0;
  const std::size_t n = 10000;
  const auto y = lowpass_zero_phase(sine(f, 1.0, 0.0, dt, n), dt);
  const Fit fy = fit_sine(y, f, dt, 2000, 8000);  // 30 periods away from the ends
  EXPECT_NEAR(db(fy.amplitude), -6.0206, 0.1);
  EXPECT_NEAR(fy.phase, 0.0, 1e-3);
  std::printf("cut-off: %.4f dB (theory -6.0206), phase %.2e rad\n", db(fy.amplitude), fy.phase);
}

TEST(ZeroPhaseLowpass, ConstantAndRampPassUnchanged) {
  // DC gain 1 and an even response |H|^2 keep polynomials of degree <= 1 in the steady state; the
  // odd reflection continues a ramp exactly and each pass starts in the steady state of a ramp, so
  // both pass unchanged up to rounding. Rounding in the recursion is amplified by ~1 / Omega^2
  // = 1 / tan(pi fc / fs)^2 = 4e3 (poles near z = 1): tolerance 1e-10 of the values.
  const double dt = 1e-3;
  std::vector<double> c(3000, 2.5), r(3000);
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = -1.0 + 0.002 * i;
  const auto yc = lowpass_zero_phase(c, dt);
  const auto yr = lowpass_zero_phase(r, dt);
  double ec = 0, er = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    ec = std::max(ec, std::abs(yc[i] - c[i]));
    er = std::max(er, std::abs(yr[i] - r[i]));
  }
  EXPECT_LT(ec, 1e-10 * 2.5);
  EXPECT_LT(er, 1e-10 * 5.0);
  std::printf("constant error %.1e, ramp error %.1e\n", ec, er);
}

TEST(ZeroPhaseLowpass, ShortSeriesAndBadInput) {
  const std::vector<double> two{1.0, 2.0};
  EXPECT_EQ(lowpass_zero_phase(two, 1e-3).size(), 2u);  // padding limited to n - 1
  EXPECT_THROW(lowpass_zero_phase({1.0}, 1e-3), std::invalid_argument);
  EXPECT_THROW(lowpass_zero_phase(two, 0.2), std::invalid_argument);  // fs = 5 Hz: 5 Hz above Nyquist
}

}  // namespace
}  // namespace sloshsph
