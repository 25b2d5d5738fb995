#pragma once
// Wall contact: the last line of defence that keeps fluid particles inside the tank walls
// (scheme.wall_contact), the tank-wall counterpart of the plates' contact step (after Dincer
// 2019, 2.3; run/plate_coupling.cpp).
//
// Why: the dummy-wall pressure (Adami et al. 2012) pushes a particle back only as hard as the
// fluid around it is pressed. A thin run-up jet at the free surface has p = 0 and few wall
// neighbours, so under violent sloshing single particles went straight through the end walls:
// 2 in 30 s of the Tait tank at X0/L = 0.031, dp = 14 mm (both high on the end walls, at
// y = 0.27-0.28 m); 39 in 6 s of the El Centro plate case. The thesis (1.3.5) names such losses
// in long runs as the weakness of its predecessor code.
//
// What, once per step after the scheme has moved the particles (the walls are at rest in the
// tank frame the fluid is solved in): for each fluid particle closer than d_c = dp/4 to the wall
// surface (the exact signed distance of TankGeometry), with n the inward wall normal (the
// distance gradient):
//   * approaching (v.n < 0): the normal velocity is removed, v <- v - (v.n) n (free slip, the
//     tangential velocity is kept); the momentum it loses is a wall force on the fluid,
//     -m (v.n) n / dt, added to F_w;
//   * outside the wall surface (d < 0): moved back along n to d_c / 2 inside.
// Particles at rest stand dp/2 from the wall surface, outside d_c, so the step does nothing in
// calm flow; the count of corrections is reported (column wall_contacts) so that a user sees
// how often it acted. (Putting every close particle onto the contact surface instead squeezed
// pairs together in the plate's case; this only moves particles that are already outside.)
#include <cmath>
#include <cstddef>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

struct WallContact {
  std::size_t corrected = 0;  // particles whose velocity or position was corrected
  Vec2 force_on_fluid;        // N/m, the momentum the walls took out of the fluid, per dt
};

// Inward unit normal of the container at p: the gradient of the exact signed distance
// (central differences over `eps`); at a corner, the direction away from the nearest point.
inline Vec2 container_normal(const TankGeometry& tank, Vec2 p, double eps) {
  const Vec2 g{tank.signed_distance(p + Vec2{eps, 0.0}) - tank.signed_distance(p - Vec2{eps, 0.0}),
               tank.signed_distance(p + Vec2{0.0, eps}) - tank.signed_distance(p - Vec2{0.0, eps})};
  const double length = norm(g);
  return length > 0.0 ? g / length : Vec2{0.0, 1.0};
}

// The wall-contact step above on the fluid particles of `p`. `distance` is the sampled signed
// distance (a cheap first test: bilinear between grid nodes `grid` apart, so within sqrt(2) grid
// of the exact value, the distance being 1-Lipschitz), `tank` the exact one. Serial, so that the
// force sum does not depend on the thread count; the first test is one grid look-up per particle.
inline WallContact keep_fluid_in_tank(Particles& p, const ContainerDistance& distance, const TankGeometry& tank,
                                      double dp, double grid, double dt) {
  const double contact = 0.25 * dp;
  WallContact out;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    // A non-finite position is not a contact: the driver's check reports it (it was counted
    // as a correction before, so the Faltinsen WCSPH run's last row showed 2 contacts).
    if (!std::isfinite(p.position[i].x) || !std::isfinite(p.position[i].y)) continue;
    if (distance(p.position[i]) >= contact + 1.5 * grid) continue;
    const double d = tank.signed_distance(p.position[i]);
    if (d >= contact) continue;
    const Vec2 n = container_normal(tank, p.position[i], 1e-3 * dp);
    const double approach = dot(p.velocity[i], n);
    if (approach >= 0.0 && d >= 0.0) continue;  // close, but leaving: nothing to do
    if (approach < 0.0) {
      p.velocity[i] -= approach * n;
      out.force_on_fluid -= (p.mass * approach / dt) * n;
    }
    if (d < 0.0) p.position[i] += (0.5 * contact - d) * n;
    ++out.corrected;
  }
  return out;
}

}  // namespace sloshsph
