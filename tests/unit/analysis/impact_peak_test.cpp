// The first impact peak of a pressure record (analysis/impact_peak.hpp) on synthetic signals
// whose peak, rise time and impulse are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "sloshsph/analysis/impact_peak.hpp"

namespace sloshsph {
namespace {

struct Record {
  std::vector<double> t, p;
};

Record sample(double t_end, double dt, const std::function<double(double)>& f) {
  Record r;
  const int n = static_cast<int>(std::lround(t_end / dt));
  for (int i = 0; i <= n; ++i) {
    r.t.push_back(i * dt);
    r.p.push_back(f(i * dt));
  }
  return r;
}

// A triangle of height a above base, rising from t0 to tp, falling to t1, sampled on its corners.
double triangle(double t, double base, double a, double t0, double tp, double t1) {
  if (t <= t0 || t >= t1) return base;
  return base + a * (t < tp ? (t - t0) / (tp - t0) : (t1 - t) / (t1 - tp));
}

TEST(ImpactPeak, TriangleOnAHydrostaticBaseline) {
  // Base 100 Pa (a submerged probe), a 1000 Pa triangle rising over 0.2 s and falling over 0.4 s.
  // The piecewise-linear interpolant is exact here, so are the answers:
  //   rise time = (0.9 - 0.1) x 0.2 s; the peak ends at the 10% level on the fall (1.6 - 0.04 s);
  //   impulse = area of the triangle 1000 x 0.6 / 2 less the two corners below 10%:
  //   300 x (1 - 0.1^2) = 297 Pa s.
  const Record r = sample(3.0, 1e-3, [](double t) { return triangle(t, 100.0, 1000.0, 1.0, 1.2, 1.6); });
  const auto peak = first_impact_peak(r.t, r.p);
  ASSERT_TRUE(peak.has_value());
  EXPECT_DOUBLE_EQ(peak->baseline, 100.0);
  EXPECT_NEAR(peak->value, 1100.0, 1e-9);
  EXPECT_NEAR(peak->time, 1.2, 1e-12);
  EXPECT_NEAR(peak->rise_start, 1.02, 1e-9);
  EXPECT_NEAR(peak->rise_end, 1.18, 1e-9);
  EXPECT_NEAR(peak->rise_time, 0.16, 1e-9);
  EXPECT_NEAR(peak->end, 1.56, 1e-9);
  EXPECT_NEAR(peak->impulse, 297.0, 1e-7);
}

TEST(ImpactPeak, FirstOfTwoHalfSinesNotTheLargest) {
  // A half-sine of amplitude P and duration T, then a second one twice as high (a re-impact):
  // the first is the first peak. For P sin(pi s / T): the 10% and 90% levels are crossed at
  // s = T asin(0.1) / pi and T asin(0.9) / pi, and the integral between the two 10% crossings
  // is 2 P T cos(asin 0.1) / pi = 2 P T sqrt(0.99) / pi.
  const double P = 5000.0, T = 0.1, t0 = 0.5, t2 = 1.5;
  const auto half_sine = [](double t, double start, double a, double duration) {
    return t > start && t < start + duration ? a * std::sin(std::numbers::pi * (t - start) / duration) : 0.0;
  };
  const Record r = sample(2.0, 1e-5, [&](double t) { return half_sine(t, t0, P, T) + half_sine(t, t2, 2 * P, T); });
  const auto peak = first_impact_peak(r.t, r.p);
  ASSERT_TRUE(peak.has_value());
  EXPECT_NEAR(peak->value, P, 1e-6 * P);
  EXPECT_NEAR(peak->time, t0 + T / 2, 1e-5);
  const double s10 = T * std::asin(0.1) / std::numbers::pi, s90 = T * std::asin(0.9) / std::numbers::pi;
  EXPECT_NEAR(peak->rise_start, t0 + s10, 1e-7);
  EXPECT_NEAR(peak->rise_time, s90 - s10, 1e-7);
  EXPECT_NEAR(peak->end, t0 + T - s10, 1e-7);
  EXPECT_NEAR(peak->impulse, 2 * P * T * std::sqrt(0.99) / std::numbers::pi, 1e-5 * P * T);
}

TEST(ImpactPeak, PeakOverAPlateauThenAReimpact) {
  // The shape of Buchner's P1 (p / rho g H): a rise to 0.69 at t = 2.77, a fall to a plateau of
  // 0.55 with wiggles of +-0.02 (below the 10% drop of 0.088 that ends a peak), then a re-impact
  // to 0.88. The first peak is 0.69 at 2.77; it ends where the fall first stops below
  // 0.69 - 0.088, at the first plateau sample (t = 3.0); the wiggles start after it.
  const Record r = sample(7.0, 0.01, [](double t) {
    if (t < 2.5) return 0.0;
    if (t < 2.77) return 0.69 * (t - 2.5) / 0.27;
    if (t < 3.0) return 0.69 - 0.14 * (t - 2.77) / 0.23;
    if (t < 5.5) return 0.55 + 0.02 * std::sin(10.0 * (t - 3.0));
    if (t < 5.8) return 0.55 + 0.33 * (t - 5.5) / 0.3;
    return 0.88;
  });
  const auto peak = first_impact_peak(r.t, r.p);
  ASSERT_TRUE(peak.has_value());
  EXPECT_NEAR(peak->value, 0.69, 1e-9);
  EXPECT_NEAR(peak->time, 2.77, 1e-9);
  EXPECT_NEAR(peak->end, 3.0, 1e-9);
  EXPECT_NEAR(peak->rise_time, 0.8 * 0.27, 1e-9);
}

TEST(ImpactPeak, SmallDipDuringTheRiseDoesNotEndIt) {
  // A dip of 0.03 on the way up (3% of the range, below the 10% drop): the peak is the top, 1.
  const Record r = sample(2.0, 0.01, [](double t) {
    if (t < 0.5) return 0.0;
    if (t < 1.0) return (t - 0.5);              // to 0.5
    if (t < 1.03) return 0.5 - (t - 1.0);       // dips to 0.47
    if (t < 1.2) return 0.47 + (t - 1.03) * 0.53 / 0.17;  // to 1.0
    return std::max(0.0, 1.0 - 2.0 * (t - 1.2));
  });
  const auto peak = first_impact_peak(r.t, r.p);
  ASSERT_TRUE(peak.has_value());
  EXPECT_NEAR(peak->value, 1.0, 1e-9);
  EXPECT_NEAR(peak->time, 1.2, 1e-9);
}

TEST(ImpactPeak, ARampThatNeverFallsPeaksAtTheEnd) {
  const Record r = sample(1.0, 0.1, [](double t) { return 10.0 * t; });
  const auto peak = first_impact_peak(r.t, r.p);
  ASSERT_TRUE(peak.has_value());
  EXPECT_NEAR(peak->value, 10.0, 1e-12);
  EXPECT_NEAR(peak->time, 1.0, 1e-12);
  EXPECT_NEAR(peak->end, 1.0, 1e-12);
  EXPECT_NEAR(peak->rise_time, 0.8, 1e-12);
  EXPECT_NEAR(peak->impulse, 0.5 * 10.0 * 1.0 * (1.0 - 0.01), 1e-9);  // from the 10% crossing (t = 0.1)
}

TEST(ImpactPeak, NoRiseNoPeak) {
  EXPECT_FALSE(first_impact_peak({0.0, 1.0, 2.0}, {5.0, 5.0, 5.0}).has_value());
  EXPECT_FALSE(first_impact_peak({0.0, 1.0, 2.0}, {5.0, 4.0, 3.0}).has_value());  // a draining probe
  EXPECT_FALSE(first_impact_peak({0.0}, {1.0}).has_value());
  EXPECT_FALSE(first_impact_peak({}, {}).has_value());
}

TEST(ImpactPeak, StopsAtTheFirstNonFiniteSample) {
  const auto peak = first_impact_peak({0.0, 1.0, 2.0, 3.0, 4.0}, {0.0, 2.0, 0.0, NAN, 9.0});
  ASSERT_TRUE(peak.has_value());
  EXPECT_DOUBLE_EQ(peak->value, 2.0);
  EXPECT_DOUBLE_EQ(peak->time, 1.0);
}

TEST(IntegralBetween, LinearPiecesClampedToTheRecord) {
  const std::vector<double> t{0.0, 1.0, 3.0}, y{0.0, 2.0, 2.0};
  EXPECT_DOUBLE_EQ(integral_between(t, y, 0.0, 3.0), 1.0 + 4.0);
  EXPECT_DOUBLE_EQ(integral_between(t, y, 0.5, 2.0), 0.5 * (1.0 + 2.0) * 0.5 + 2.0);
  EXPECT_DOUBLE_EQ(integral_between(t, y, -5.0, 9.0), 5.0);
  EXPECT_DOUBLE_EQ(integral_between(t, y, 2.0, 1.0), 0.0);
}

}  // namespace
}  // namespace sloshsph
