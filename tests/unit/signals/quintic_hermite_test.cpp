// The quintic Hermite interpolant (quintic_hermite.hpp): exact on quintics, and the cubic spline
// itself when it is given the spline's knot data.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "sloshsph/signals/quintic_hermite.hpp"

namespace sloshsph {
namespace {

// Reference: a quintic's value, rate and acceleration at two knots determine it, so the
// interpolant of a quintic is the quintic itself. Non-uniform knots. Tolerance: rounding, 1e-10.
TEST(QuinticHermite, ReproducesAQuintic) {
  auto f = [](double t) { return 0.2 + t - 0.5 * t * t + 0.3 * std::pow(t, 3) - 0.1 * std::pow(t, 4) + 0.04 * std::pow(t, 5); };
  auto df = [](double t) { return 1.0 - t + 0.9 * t * t - 0.4 * std::pow(t, 3) + 0.2 * std::pow(t, 4); };
  auto ddf = [](double t) { return -1.0 + 1.8 * t - 1.2 * t * t + 0.8 * std::pow(t, 3); };
  HermiteSamples s;
  for (double t : {-1.0, -0.3, 0.4, 0.45, 1.5, 2.0}) {
    s.t.push_back(t);
    s.value.push_back(f(t));
    s.first.push_back(df(t));
    s.second.push_back(ddf(t));
  }
  for (double t = -1.0; t <= 2.0; t += 0.01) {
    const SplineSample v = evaluate(s, t);
    EXPECT_NEAR(v.value, f(t), 1e-10) << t;
    EXPECT_NEAR(v.first, df(t), 1e-10) << t;
    EXPECT_NEAR(v.second, ddf(t), 1e-10) << t;
  }
}

// Reference: each piece of a cubic spline is a cubic, reproduced by the quintic Hermite
// interpolant of its end data. Tolerance: rounding, 1e-12 of the data's scale.
TEST(QuinticHermite, WithTheSplineKnotDataIsTheSpline) {
  TimeSeries data{{0.0, 0.1, 0.25, 0.3, 0.5, 0.8, 0.9}, {0.0, 0.02, -0.01, 0.03, 0.05, -0.02, 0.0}};
  const CubicInterpolant spline = not_a_knot_spline(data);
  const HermiteSamples h = hermite_samples(spline);
  for (double t = 0.0; t <= 0.9; t += 0.001) {
    const SplineSample a = evaluate(spline, t), b = evaluate(h, t);
    EXPECT_NEAR(a.value, b.value, 1e-12) << t;
    EXPECT_NEAR(a.first, b.first, 1e-11) << t;
    EXPECT_NEAR(a.second, b.second, 1e-9) << t;
  }
}

TEST(QuinticHermite, RefusesBadSamples) {
  EXPECT_THROW(check_hermite_samples(HermiteSamples{{0.0}, {0.0}, {0.0}, {0.0}}, "x"), std::invalid_argument);
  EXPECT_THROW(check_hermite_samples(HermiteSamples{{0.0, 0.0}, {0.0, 1.0}, {0.0, 0.0}, {0.0, 0.0}}, "x"),
               std::invalid_argument);
  EXPECT_THROW(check_hermite_samples(HermiteSamples{{0.0, 1.0}, {0.0, 1.0}, {0.0, INFINITY}, {0.0, 0.0}}, "x"),
               std::invalid_argument);
}

}  // namespace
}  // namespace sloshsph
