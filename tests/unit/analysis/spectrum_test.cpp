// Welch PSD, dominant frequency, zero-crossing period (src/sloshsph/analysis/spectrum.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/analysis/spectrum.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "test_noise.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(WelchPsd, WhiteNoiseIntegralIsVarianceAndLevelIs2SigmaSquaredDt) {
  // Discrete white noise of variance s^2 at dt has the flat one-sided PSD 2 s^2 dt up to 1/(2 dt).
  // 2^20 samples: the integral equals the sample variance up to the window weighting (statistical,
  // ~0.2%): tolerance 1%. Mean level over the interior bins: ~0.1% statistical, tolerance 1%.
  const double dt = 0.01, sigma = 3.0;
  const auto x = test::gaussian_noise(11, 1 << 20, sigma);
  const Spectrum s = welch_psd(x, dt, 1024);
  ASSERT_EQ(s.f.size(), 513u);
  EXPECT_DOUBLE_EQ(s.df, 100.0 / 1024);
  const double var = standard_deviation(x) * standard_deviation(x);
  double sum = 0;
  for (double v : s.value) sum += v * s.df;
  EXPECT_NEAR(sum / var, 1.0, 0.01);
  double level = 0;
  for (std::size_t k = 1; k + 1 < s.value.size(); ++k) level += s.value[k];
  level /= static_cast<double>(s.value.size() - 2);
  EXPECT_NEAR(level / (2 * sigma * sigma * dt), 1.0, 0.01);
  std::printf("white noise: integral / variance = %.5f, level / (2 s^2 dt) = %.5f\n", sum / var,
              level / (2 * sigma * sigma * dt));
}

TEST(WelchPsd, SineIntegralIsHalfSquaredAmplitude) {
  // A sine of amplitude A has variance A^2 / 2; its PSD peaks at its frequency. The Hann window
  // spreads the line over ~3 bins, the integral keeps A^2 / 2 (tolerance 0.5%: the windowed mean
  // square of a sine differs from A^2/2 by O(1/cycles per segment), here 1/(2 x 102)).
  const double dt = 0.005, f = 2.37, A = 0.8;
  std::vector<double> x(200000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = A * std::sin(2 * kPi * f * i * dt + 0.4);
  const Spectrum s = welch_psd(x, dt, 8192);
  double sum = 0;
  std::size_t kmax = 0;
  for (std::size_t k = 0; k < s.value.size(); ++k) {
    sum += s.value[k] * s.df;
    if (s.value[k] > s.value[kmax]) kmax = k;
  }
  EXPECT_NEAR(sum / (A * A / 2), 1.0, 0.005);
  EXPECT_NEAR(s.f[kmax], f, s.df);
  EXPECT_NEAR(spectrum_integral(s, 0.0, 1.0 / (2 * dt)) / (A * A / 2), 1.0, 0.005);
  std::printf("sine: integral / (A^2/2) = %.6f\n", sum / (A * A / 2));
}

TEST(WelchPsd, BadInput) {
  EXPECT_THROW(welch_psd(std::vector<double>(100, 0.0), 0.01, 256), std::invalid_argument);
  EXPECT_THROW(welch_psd(std::vector<double>(100, 0.0), 0.01, 2), std::invalid_argument);
}

TEST(DominantFrequency, JacobsenInterpolationBetweenBins) {
  // A real sine with a non-integer number of cycles (37.3) in the record: the peak lies between
  // bins. Jacobsen's estimator is exact for one complex exponential; the mirror line at -f leaks
  // ~1/(4 pi k) into the peak bins: tolerance 1% of a bin (1 / (n dt)).
  const double dt = 0.01;
  const std::size_t n = 4096;
  const double f = 37.3 / (n * dt);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = 1.5 + std::cos(2 * kPi * f * i * dt + 1.1);
  const double est = dominant_frequency_fft(x, dt);
  EXPECT_NEAR(est, f, 0.01 / (n * dt));
  std::printf("Jacobsen: f = %.6f Hz, estimate %.6f Hz, error %.4f bins\n", f, est, (est - f) * n * dt);
}

TEST(ZeroCrossingPeriod, SineWithOffset) {
  // Linear interpolation of the crossing times of a sine at 100 samples a period: the errors are
  // the same at every crossing (same local shape), so the period is exact to rounding when the
  // sampling is commensurate; with 1/f = 1.2345 s, dt = 0.01 s: error O((w dt)^3) ~ 1e-5 relative.
  const double dt = 0.01, T = 1.2345;
  std::vector<double> t, x;
  for (int i = 0; i < 5000; ++i) {
    t.push_back(i * dt);
    x.push_back(0.2 + std::sin(2 * kPi * i * dt / T - 0.5));
  }
  EXPECT_NEAR(zero_crossing_period(t, x), T, 1e-4 * T);
  EXPECT_EQ(zero_crossing_period({0, 1}, {0, 1}), 0.0);
}

}  // namespace
}  // namespace sloshsph
