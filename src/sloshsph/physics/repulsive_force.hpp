#pragma once
// The soft repulsive force of the coupled dynamic solid boundary treatment
// (Shao et al. 2012 eqs. 25-28), per unit mass of the fluid particle:
//   F_ij = 0.01 c^2 chi f(eta) x_ij / r_ij^2,   eta = r_ij / (0.75 h),
//   chi = 1 - r_ij / dd  for 0 < r_ij < dd (0 beyond),
//   f(eta) = 2/3 (0 < eta <= 2/3), 2 eta - 1.5 eta^2 (2/3 < eta <= 1), 0.5 (2 - eta)^2 (1 < eta < 2), 0.
// x_ij points from the boundary particle j to the fluid particle i; dd is the initial particle
// spacing. The force is finite (it grows as 1/r only as chi -> 1), continuous, and zero for a
// fluid particle at the lattice distance dd from the boundary particle.
#include <cmath>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

// Shao eq. 28.
inline double repulsive_shape(double eta) {
  if (eta <= 0.0) return 0.0;
  if (eta <= 2.0 / 3.0) return 2.0 / 3.0;
  if (eta <= 1.0) return 2.0 * eta - 1.5 * eta * eta;
  if (eta < 2.0) return 0.5 * (2.0 - eta) * (2.0 - eta);
  return 0.0;
}

// Shao eqs. 25-27: acceleration of fluid particle i from boundary particle j, r_ij = r_i - r_j.
inline Vec2 repulsive_acceleration(Vec2 rij, double c0, double h, double spacing) {
  const double r2 = norm2(rij);
  if (!(r2 > 0.0)) return {};
  const double r = std::sqrt(r2);
  if (r >= spacing) return {};
  const double chi = 1.0 - r / spacing;
  const double eta = r / (0.75 * h);
  return rij * (0.01 * c0 * c0 * chi * repulsive_shape(eta) / r2);
}

}  // namespace sloshsph
