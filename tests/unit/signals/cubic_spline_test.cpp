// The not-a-knot cubic spline (cubic_spline.hpp): exact on cubics, and the interpolation error
// of a sampled sine against the classical bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "sloshsph/signals/cubic_spline.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

// Reference: a not-a-knot spline reproduces any cubic exactly (one cubic through all the
// knots satisfies every condition). Non-uniform knots, 4 and 9 samples. Tolerance: rounding, 1e-11.
TEST(NotAKnotSpline, ReproducesACubicOnNonUniformKnots) {
  auto f = [](double t) { return 0.3 - 1.2 * t + 0.7 * t * t - 0.25 * t * t * t; };
  auto df = [](double t) { return -1.2 + 1.4 * t - 0.75 * t * t; };
  auto ddf = [](double t) { return 1.4 - 1.5 * t; };
  for (const std::vector<double>& knots : {std::vector<double>{0.0, 0.3, 1.1, 2.0},
                                           std::vector<double>{-1.0, -0.9, -0.2, 0.0, 0.05, 0.7, 1.3, 1.4, 2.5}}) {
    TimeSeries s;
    for (double t : knots) {
      s.t.push_back(t);
      s.value.push_back(f(t));
    }
    const CubicInterpolant spline = not_a_knot_spline(s);
    for (double t = knots.front(); t <= knots.back(); t += 0.01) {
      const SplineSample v = evaluate(spline, t);
      EXPECT_NEAR(v.value, f(t), 1e-11) << t;
      EXPECT_NEAR(v.first, df(t), 1e-11) << t;
      EXPECT_NEAR(v.second, ddf(t), 1e-11) << t;
    }
  }
}

// The largest error of s, s', s'' against sin(w t + phase), over a record of 4 periods sampled
// at n points a period, relative to the amplitude of each derivative (1, w, w^2): in the two
// intervals at each end, and inside (beyond them); the worst over 16 phases (the ends in motion).
struct SineErrors {
  double value = 0.0, first = 0.0, second = 0.0;
};
struct RegionErrors {
  SineErrors inside, ends;
};

void keep_largest(SineErrors& e, double value, double first, double second) {
  e.value = std::max(e.value, value);
  e.first = std::max(e.first, first);
  e.second = std::max(e.second, second);
}

RegionErrors sine_errors(int per_period) {
  const double w = 2.0 * kPi * 0.7, period = 2.0 * kPi / w, h = period / per_period;
  const int n = 4 * per_period + 1;
  RegionErrors e;
  for (int p = 0; p < 16; ++p) {
    const double phase = 2.0 * kPi * p / 16.0;
    TimeSeries s;
    for (int k = 0; k < n; ++k) {
      s.t.push_back(k * h);
      s.value.push_back(std::sin(w * k * h + phase));
    }
    const CubicInterpolant spline = not_a_knot_spline(s);
    for (int k = 0; k <= 20 * (n - 1); ++k) {  // 20 points per interval, the ends included
      const double t = k * h / 20.0;
      const SplineSample v = evaluate(spline, t);
      const bool end = k < 40 || k > 20 * (n - 3);
      keep_largest(end ? e.ends : e.inside, std::abs(v.value - std::sin(w * t + phase)),
                   std::abs(v.first - w * std::cos(w * t + phase)) / w,
                   std::abs(v.second + w * w * std::sin(w * t + phase)) / (w * w));
    }
  }
  return e;
}

// Reference: the cubic-spline error bounds of Hall & Meyer (1976), proven for the clamped spline,
// with h = T/N, w h = 2 pi / N and |f''''| = w^4:
//   |s - f| <= 5/384 (w h)^4,  |s' - f'|/w <= 1/24 (w h)^3,  |s'' - f''|/w^2 <= 3/8 (w h)^2
// (at N = 50 samples a period: 3.2e-6, 8.3e-5 and 5.9e-3). Tolerances: inside, those bounds
// (measured: a third of them); in the two intervals at each end, where the not-a-knot conditions
// act, 2.5, 4.5 and 2 times them (measured over 64 phases, at N = 20, 50 and 100 alike: 2.17,
// 4.31 and 1.88 times). And the order h^2 of s'' (error ratio 3.5 to 4.5 from N = 50 to 100).
TEST(NotAKnotSpline, SampledSineIsWithinTheSplineErrorBounds) {
  const RegionErrors e50 = sine_errors(50), e100 = sine_errors(100);
  const double wh = 2.0 * kPi / 50.0;
  const SineErrors bound{5.0 / 384.0 * std::pow(wh, 4), 1.0 / 24.0 * std::pow(wh, 3), 3.0 / 8.0 * wh * wh};
  for (const auto& [name, e, factor] : {std::tuple{"inside", e50.inside, SineErrors{1.0, 1.0, 1.0}},
                                        std::tuple{"ends", e50.ends, SineErrors{2.5, 4.5, 2.0}}}) {
    std::printf("  N = 50, %s: |ds| = %.3g, |ds'|/w = %.3g, |ds''|/w^2 = %.3g (%.2f, %.2f, %.2f of the bounds)\n", name,
                e.value, e.first, e.second, e.value / bound.value, e.first / bound.first, e.second / bound.second);
    EXPECT_LE(e.value, factor.value * bound.value) << name;
    EXPECT_LE(e.first, factor.first * bound.first) << name;
    EXPECT_LE(e.second, factor.second * bound.second) << name;
  }
  const double order = std::max(e50.inside.second, e50.ends.second) / std::max(e100.inside.second, e100.ends.second);
  std::printf("  s'' error ratio N = 50 / N = 100: %.3f\n", order);
  EXPECT_GT(order, 3.5);
  EXPECT_LT(order, 4.5);
}

TEST(NotAKnotSpline, RefusesTooFewOrUnorderedSamples) {
  EXPECT_THROW(not_a_knot_spline(TimeSeries{{0.0, 1.0, 2.0}, {0.0, 1.0, 0.0}}), std::invalid_argument);
  EXPECT_THROW(not_a_knot_spline(TimeSeries{{0.0, 1.0, 1.0, 2.0}, {0.0, 1.0, 0.0, 1.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace sloshsph
