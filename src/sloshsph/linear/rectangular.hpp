#pragma once
// Linear (potential-flow) sloshing of a rectangular tank.
#include <cmath>
#include <numbers>

namespace sloshsph {

// n-th natural angular frequency (n = 1, 2, ...) of a rectangular tank of length L
// filled to depth h: omega_n^2 = (n pi g / L) tanh(n pi h / L) (thesis eq. 4.29 for n = 1).
inline double rectangular_sloshing_omega(double length, double depth, double gravity, int n = 1) {
  const double k = n * std::numbers::pi / length;
  return std::sqrt(gravity * k * std::tanh(k * depth));
}

// The depth that tunes a rectangular tank of length L to omega (inverse of the above, n = 1).
// Returns a negative value when omega is not reachable (omega^2 >= g pi / L).
inline double rectangular_depth_for_omega(double length, double omega, double gravity) {
  const double k = std::numbers::pi / length;
  const double t = omega * omega / (gravity * k);
  if (t >= 1.0 || t <= 0.0) return -1.0;
  return std::atanh(t) / k;
}

}  // namespace sloshsph
