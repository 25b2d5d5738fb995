// Kernel normalisation and consistency (thesis eq. 2.3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/sph/kernel.hpp"

namespace sloshsph {
namespace {

// Integral of W over the plane by the radial rule 2 pi int_0^2h W(r) r dr (composite Simpson,
// 20000 intervals: quadrature error far below the 1e-6 tolerance).
template <class K>
double radial_integral(const K& k) {
  const int n = 20000;
  const double a = 0.0, b = k.support(), hstep = (b - a) / n;
  double s = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double r = a + i * hstep;
    const double wgt = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    s += wgt * k.w(r) * r;
  }
  return 2.0 * std::numbers::pi * s * hstep / 3.0;
}

// Sum of W over a square lattice of spacing dp around a lattice point, times dp^2.
template <class K>
double lattice_sum(const K& k, double dp) {
  const int n = static_cast<int>(k.support() / dp) + 1;
  double s = 0.0;
  for (int a = -n; a <= n; ++a)
    for (int b = -n; b <= n; ++b) s += k.w(dp * std::hypot(a, b));
  return s * dp * dp;
}

TEST(Kernel, WendlandIntegratesToOne) {
  // Reference: a kernel is normalised, integral W dA = 1. Tolerance 1e-6 (quadrature).
  for (double h : {0.001, 0.007, 1.0}) EXPECT_NEAR(radial_integral(WendlandC2(h)), 1.0, 1e-6) << "h = " << h;
}

TEST(Kernel, CubicSplineIntegratesToOne) {
  for (double h : {0.001, 0.007, 1.0}) EXPECT_NEAR(radial_integral(CubicSpline(h)), 1.0, 1e-6) << "h = " << h;
}

TEST(Kernel, WendlandLatticeSumAtTheThesisRatio) {
  // Reference: the particle approximation of 1 on a lattice, sum_j V W_ij, at h = 1.4 dp
  // (thesis 2.6.1) within 1% of 1.
  const double dp = 0.005;
  EXPECT_NEAR(lattice_sum(WendlandC2(1.4 * dp), dp), 1.0, 0.01);
}

TEST(Kernel, GradientFactorIsTheDerivative) {
  // gradient_factor(r) * r must equal dW/dr; check against a central difference (rel. 1e-6).
  const WendlandC2 w(0.01);
  const CubicSpline c(0.01);
  for (double r : {0.001, 0.004, 0.0099, 0.0101, 0.015, 0.0199}) {
    const double e = 1e-8;
    EXPECT_NEAR(w.gradient_factor(r) * r, (w.w(r + e) - w.w(r - e)) / (2 * e), 1e-6 * std::abs(w.norm / w.h)) << r;
    EXPECT_NEAR(c.gradient_factor(r) * r, (c.w(r + e) - c.w(r - e)) / (2 * e), 1e-6 * std::abs(c.norm / c.h)) << r;
  }
}

TEST(Kernel, WendlandDerivativeIsMinusFiveQ) {
  // The derivative of eq. 2.3 is norm * (-5 q)(1 - q/2)^3 (the extracted text's (1 - q/3)^3 is a typo).
  const double h = 1.0;
  const WendlandC2 w(h);
  for (double q : {0.3, 1.0, 1.7}) {
    const double expected = w.norm * (-5.0 * q) * std::pow(1.0 - q / 2.0, 3) / h;
    EXPECT_NEAR(w.gradient_factor(q * h) * q * h, expected, 1e-12);
  }
}

TEST(Kernel, CompactSupport) {
  const WendlandC2 w(0.01);
  EXPECT_EQ(w.w(0.02), 0.0);
  EXPECT_EQ(w.w(0.03), 0.0);
  EXPECT_EQ(w.gradient_factor(0.02), 0.0);
  EXPECT_GT(w.w(0.0199), 0.0);
}

}  // namespace
}  // namespace sloshsph
