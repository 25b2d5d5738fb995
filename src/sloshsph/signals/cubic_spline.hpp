#pragma once
// Cubic spline through sampled values, with its first and second derivatives: a measured
// angle record (a pitch from a file) becomes theta(t), theta'(t), theta''(t), continuous, so that
// the angular acceleration entering the Euler term of the tank frame (physics/frame.hpp) is the
// second derivative of a C2 curve, not a difference of noisy differences.
#include <vector>

#include "sloshsph/signals/time_series.hpp"

namespace sloshsph {

// The spline s(t) on [t_0, t_n-1], stored as its knots, values and second derivatives
// (moments) M_i. On [t_i, t_i+1], h = t_i+1 - t_i, a = t_i+1 - t, b = t - t_i
// (e.g. de Boor, "A Practical Guide to Splines", ch. IV):
//   s   = M_i a^3/(6h) + M_i+1 b^3/(6h) + (y_i - M_i h^2/6) a/h + (y_i+1 - M_i+1 h^2/6) b/h
//   s'  = -M_i a^2/(2h) + M_i+1 b^2/(2h) + (y_i+1 - y_i)/h - (M_i+1 - M_i) h/6
//   s'' = (M_i a + M_i+1 b) / h
// The moments solve the continuity of s' at the interior knots,
//   h_i-1 M_i-1 + 2 (h_i-1 + h_i) M_i + h_i M_i+1 = 6 ((y_i+1 - y_i)/h_i - (y_i - y_i-1)/h_i-1),
// closed by the NOT-A-KNOT end conditions (s''' continuous at t_1 and t_n-2). Why not-a-knot:
// a record generally starts and ends in motion, and the natural spline's s'' = 0 at both ends
// would put an O(1) error on theta'' (the Euler term) near them; not-a-knot keeps the O(h^2)
// error of theta'' up to the ends (measured on a sine: within the clamped spline's bound
// 3/8 h^2 |f''''| inside, up to 1.9 times it in the two intervals at each end;
// tests/unit/signals/cubic_spline_test.cpp) and reproduces any cubic exactly.
struct CubicInterpolant {
  std::vector<double> t;       // knots, strictly increasing
  std::vector<double> y;       // values at the knots
  std::vector<double> moment;  // s''(t_i)
};

// Value and first two derivatives of a spline at one time.
struct SplineSample {
  double value = 0.0;
  double first = 0.0;   // ds/dt
  double second = 0.0;  // d2s/dt2
};

// The not-a-knot spline through the samples: >= 4 samples, strictly increasing finite times.
// Throws std::invalid_argument otherwise. O(n) (a tridiagonal solve).
CubicInterpolant not_a_knot_spline(const TimeSeries& samples);

// s, s', s'' at t. For t outside [t_0, t_n-1] the end interval's cubic is extended (callers
// decide what happens outside the record). O(log n).
SplineSample evaluate(const CubicInterpolant& spline, double t);

}  // namespace sloshsph
