#pragma once
// Interpolation of a signal given with its first two derivatives at the samples: the quintic
// Hermite interpolant, C2, matching value, rate and acceleration at every sample. Used for a
// pitch record (physics/excitation.cpp): with the file's own rate and acceleration columns, or
// with those of the not-a-knot cubic spline through its angles (signals/cubic_spline.hpp), for
// which the quintic Hermite interpolant is the spline itself (it reproduces any polynomial of
// degree <= 5 from its end data, so each cubic piece exactly).
#include <vector>

#include "sloshsph/signals/cubic_spline.hpp"

namespace sloshsph {

// Knots with value, first and second derivative.
struct HermiteSamples {
  std::vector<double> t;       // strictly increasing
  std::vector<double> value;
  std::vector<double> first;   // d/dt
  std::vector<double> second;  // d2/dt2
};

// The knot data of a cubic spline: s, s', s'' at its knots.
HermiteSamples hermite_samples(const CubicInterpolant& spline);

// Throws std::invalid_argument unless the samples have >= 2 knots, equal lengths and strictly
// increasing finite times and finite values (`what` names them in the message).
void check_hermite_samples(const HermiteSamples& samples, const std::string& what);

// On [t_i, t_i+1], h = t_i+1 - t_i, u = (t - t_i)/h:
//   p = y_i H0 + h y'_i H1 + h^2 y''_i H2 + h^2 y''_i+1 H3 + h y'_i+1 H4 + y_i+1 H5,
//   H0 = 1 - 10u^3 + 15u^4 - 6u^5,  H1 = u - 6u^3 + 8u^4 - 3u^5,  H2 = (u^2 - 3u^3 + 3u^4 - u^5)/2,
//   H3 = (u^3 - 2u^4 + u^5)/2,      H4 = -4u^3 + 7u^4 - 3u^5,     H5 = 10u^3 - 15u^4 + 6u^5,
// and its first two derivatives. Outside the knots the end interval's quintic is extended
// (callers decide what happens outside the record). O(log n).
SplineSample evaluate(const HermiteSamples& samples, double t);

}  // namespace sloshsph
