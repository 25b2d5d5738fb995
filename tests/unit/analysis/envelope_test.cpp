// Crest envelopes (analysis/envelope): the largest value of each period, and the comparison of
// two series period by period.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sloshsph/analysis/envelope.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

// y = A(t) sin(2 pi t / T) sampled every dt, A growing linearly.
void growing_sine(double growth, double dt, std::vector<double>& t, std::vector<double>& y) {
  for (int k = 0; k * dt < 8.0; ++k) {
    t.push_back(k * dt);
    y.push_back((1.0 + growth * k * dt) * std::sin(2.0 * kPi * k * dt));
  }
}

TEST(Envelope, CrestOfEachPeriod) {
  std::vector<double> t, y;
  growing_sine(0.0, 0.001, t, y);
  const std::vector<double> c = crests_per_period(t, y, 0.0, 1.0, 8);
  ASSERT_EQ(c.size(), 8u);
  for (double v : c) EXPECT_NEAR(v, 1.0, 1e-5);
  // A window beyond the series has no sample.
  EXPECT_TRUE(std::isnan(crests_per_period(t, y, 0.0, 1.0, 9).back()));
}

TEST(Envelope, ComparisonIsRelativeToTheLargestReferenceCrest) {
  std::vector<double> t, y, ts, ys;
  growing_sine(1.0, 0.001, t, y);   // crests about 1.25, 2.25, ... 8.25
  growing_sine(0.9, 0.002, ts, ys);  // the simulated one grows 10% slower, on another grid
  const EnvelopeComparison c = compare_crest_envelopes(t, y, ts, ys, 0.0, 1.0, 8);
  // Period k (0-based): crest at t = k + 1/4, reference 1 + (k + 1/4), simulated 1 + 0.9 (k + 1/4);
  // the largest reference crest is 8.25.
  // (A growing sine's crest comes slightly after k + 1/4: 5e-4.)
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(c.deviation[k], -0.1 * (k + 0.25) / 8.25, 5e-4) << k;
  EXPECT_NEAR(c.worst_deviation, 0.1 * 7.25 / 8.25, 5e-4);
  // A period missing from the simulation makes the worst deviation NaN, never a pass.
  ts.resize(ts.size() / 2);
  ys.resize(ys.size() / 2);
  EXPECT_TRUE(std::isnan(compare_crest_envelopes(t, y, ts, ys, 0.0, 1.0, 8).worst_deviation));
}

}  // namespace
}  // namespace sloshsph
