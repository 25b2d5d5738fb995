// Mechanical admittance (thesis eq. 4.30) and effective damping (Vickery et al. 1983).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/analysis/admittance.hpp"
#include "test_noise.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(EffectiveDamping, AnalyticSdofAdmittanceGivesZetaBack) {
  // |H|^2 of an SDOF sampled on [0, 10 f_n] with df = f_n / 2000 (40 points in the half-power
  // band): area = pi f_n / (4 zeta) up to the tail beyond 10 f_n (f_n / 3000) and the trapezoid
  // error: tolerance 1% (brief).
  for (double zeta : {0.005, 0.01, 0.05}) {
    const double f_n = 0.134;
    Spectrum h;
    h.df = f_n / 2000;
    for (int k = 0; k <= 20000; ++k) {
      h.f.push_back(k * h.df);
      h.value.push_back(sdof_admittance(h.f.back(), f_n, zeta));
    }
    const double z = effective_damping_ratio(h, f_n, 0.0, 10 * f_n);
    EXPECT_NEAR(z / zeta, 1.0, 0.01) << zeta;
    std::printf("analytic zeta %.3f -> %.6f\n", zeta, z);
  }
  EXPECT_DOUBLE_EQ(sdof_admittance(0.0, 1.0, 0.01), 1.0);
  EXPECT_NEAR(sdof_admittance(1.0, 1.0, 0.01), 1.0 / (4 * 0.01 * 0.01), 1e-9);
}

TEST(EffectiveDamping, WhiteNoiseSdofResponse) {
  // SDOF f_n = 1 Hz, zeta = 1%, force = discrete Gaussian white noise (one-sided PSD 2 s^2 dt),
  // 20000 periods (dt = 0.02 s), Newmark response, Welch PSD (2^14-sample segments, df = 0.003 Hz,
  // ~7 bins in the half-power band), MAF by eq. 4.30, area over [0, 20] Hz -> zeta_eff.
  // Statistical error: the area is K^2 var(x) / S0, and var(x) of a narrow-band response measured
  // over T scatters by 1/sqrt(zeta w_n T) = 2.8%. Newmark's frequency warping (0.13%) is
  // negligible. Tolerance 10% (brief) = 3.5 standard errors.
  const double m = 1000.0, f_n = 1.0, zeta = 0.01, dt = 0.02;
  const double w_n = 2 * kPi * f_n, k = m * w_n * w_n, c = 2 * zeta * m * w_n;
  const double sigma_f = 100.0;
  const auto force = test::gaussian_noise(2024, 1000000, sigma_f);
  const auto x = test::sdof_displacement(m, c, k, force, dt);
  const Spectrum sx = welch_psd(x, dt, 1 << 14);
  const double s0 = 2 * sigma_f * sigma_f * dt;
  const Spectrum h = mechanical_admittance(sx, s0, k);
  const double z = effective_damping_ratio(h, f_n, 0.0, 20.0);
  EXPECT_NEAR(z / zeta, 1.0, 0.10);
  // Same with the force PSD estimated the same way instead of its nominal level.
  const Spectrum sf = welch_psd(force, dt, 1 << 14);
  const double z2 = effective_damping_ratio(mechanical_admittance(sx, sf, k), f_n, 0.0, 20.0);
  EXPECT_NEAR(z2 / zeta, 1.0, 0.10);
  // The MAF tends to 1 below resonance (static response): mean over 0.1-0.3 Hz, where
  // |H|^2 = 1.01-1.2; statistical scatter of ~300 averaged bins ~ a few %: tolerance 10%.
  double low = 0, ref = 0;
  int count = 0;
  for (std::size_t i = 0; i < h.f.size(); ++i)
    if (h.f[i] >= 0.1 && h.f[i] <= 0.3) low += h.value[i], ref += sdof_admittance(h.f[i], f_n, zeta), ++count;
  EXPECT_NEAR(low / ref, 1.0, 0.10);
  std::printf("white-noise SDOF: zeta_eff = %.5f (nominal S0), %.5f (Welch force PSD); low-f MAF ratio %.4f\n", z, z2,
              low / ref);
}

}  // namespace
}  // namespace sloshsph
