#pragma once
// Repulsive wall force of thesis eq. 3.18 (after Cherfils et al. 2012; Monaghan 1994's
// Lennard-Jones boundary force), used by the ISPH scheme when scheme.repulsive_walls is set.
//
// The extracted eq. 3.18 reads
//   f_iw = g H [(h_k / 2r)^4 - (h_k / 2r)^2] x_iw / r^2   for h_k / 2r <= 1, 0 otherwise,
// "valid for r < h_k/4". As printed it acts beyond r = h_k/2 and is attractive there, and it
// grows without bound as r -> 0. We use the Lennard-Jones form it comes from, with the
// inequality the other way round (Monaghan 1994, eq. 5.1: zero beyond r0):
//   f_iw = D [(r0 / s)^4 - (r0 / s)^2] x_iw / (r s),   s = max(r, r0 / 2),   for r < r0; 0 beyond,
//   r0 = range h (range = 1/2: h_k/2 of eq. 3.18, h_k = 1.4 dp being the thesis's h),
//   D  = coefficient g max(H_w, h),
// x_iw = r_i - r_w (from the wall particle to the fluid particle), H_w the still-water depth
// above the wall particle (the thesis's "fluid height above the corresponding boundary
// particle"), floored at h so the force does not vanish at the waterline, where splashes
// run up the walls. Properties (tests/unit/physics/test_wall_repulsion.cpp):
//   * zero for r >= r0 and continuous there (the bracket vanishes at s = r0);
//   * repulsive inside: the bracket is positive for s < r0, and f is along +x_iw;
//   * bounded: below r0/2 the magnitude is held at its value there, 12 D / (r0 / 2) = 24 D / r0
//     (eq. 3.18 itself grows as r^-5).
// With r0 = 0.7 dp it is zero for fluid placed on the lattice: the first fluid row stands
// dp/2 inside the wall surface and the first wall layer dp/2 outside it.
#include <algorithm>
#include <cmath>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

// Acceleration (m/s^2) of fluid particle i from first-layer wall particle w; x_iw = r_i - r_w,
// strength D = coefficient g H_w (m^2/s^2), range r0 (m).
template <int D>
Vec<D> thesis_wall_repulsion(Vec<D> x_iw, double strength, double range) {
  const double r2 = norm2(x_iw);
  if (!(r2 > 0.0) || r2 >= range * range) return {};
  const double r = std::sqrt(r2);
  const double s = std::max(r, 0.5 * range);
  const double q2 = (range / s) * (range / s);
  return x_iw * (strength * (q2 * q2 - q2) / (r * s));
}

// The largest magnitude thesis_wall_repulsion can take: 24 D / r0 (at r <= r0/2).
inline double thesis_wall_repulsion_bound(double strength, double range) { return 24.0 * strength / range; }

}  // namespace sloshsph
