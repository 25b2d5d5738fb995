// Amplitude envelopes (analysis/envelope): the extremes of each period, and the comparison of two
// series period by period by their half heights.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sloshsph/analysis/envelope.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

// y = offset + A(t) sin(2 pi t), A = 1 + growth t, sampled every dt for 8 s.
void growing_sine(double growth, double offset, double dt, std::vector<double>& t, std::vector<double>& y) {
  for (int k = 0; k * dt < 8.0; ++k) {
    t.push_back(k * dt);
    y.push_back(offset + (1.0 + growth * k * dt) * std::sin(2.0 * kPi * k * dt));
  }
}

TEST(Envelope, ExtremesOfEachPeriod) {
  std::vector<double> t, y;
  growing_sine(0.0, 0.0, 0.001, t, y);
  const PeriodExtremes e = extremes_per_period(t, y, 0.0, 1.0, 8);
  ASSERT_EQ(e.crest.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    EXPECT_NEAR(e.crest[k], 1.0, 1e-5);
    EXPECT_NEAR(e.trough[k], -1.0, 1e-5);
  }
  // A window beyond the series has no sample.
  EXPECT_TRUE(std::isnan(extremes_per_period(t, y, 0.0, 1.0, 9).crest.back()));
}

TEST(Envelope, ComparisonOfHalfHeightsIgnoresAnOffset) {
  std::vector<double> t, y, ts, ys;
  growing_sine(1.0, 0.0, 0.001, t, y);    // amplitude about 1.5, 2.5, ... 8.5 in period k
  growing_sine(0.9, 0.3, 0.002, ts, ys);  // grows 10% slower, on another grid, and rests 0.3 high
  const EnvelopeComparison c = compare_envelopes(t, y, ts, ys, 0.0, 1.0, 8);
  // Period k (0-based): half height 1 + (k + 1/2) against 1 + 0.9 (k + 1/2) (crest at k + 1/4,
  // trough at k + 3/4), the largest reference 8.5. (A growing sine's extremes come slightly late.)
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(c.deviation[k], -0.1 * (k + 0.5) / 8.5, 5e-4) << k;
  EXPECT_NEAR(c.worst_deviation, 0.1 * 7.5 / 8.5, 5e-4);
  // A period missing from the simulation makes the worst deviation NaN, never a pass.
  ts.resize(ts.size() / 2);
  ys.resize(ys.size() / 2);
  EXPECT_TRUE(std::isnan(compare_envelopes(t, y, ts, ys, 0.0, 1.0, 8).worst_deviation));
}

}  // namespace
}  // namespace sloshsph
