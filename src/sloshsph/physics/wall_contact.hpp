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

template <int D>
struct BasicWallContact {
  std::size_t corrected = 0;  // particles whose velocity or position was corrected
  Vec<D> force_on_fluid;      // N/m (N in 3D), the momentum the walls took out of the fluid, per dt
  Moment<D> moment_on_fluid{};  // its moment about the origin (each correction at its particle)
};
using WallContact = BasicWallContact<2>;

// Inward unit normal of the container at p: the gradient of the exact signed distance `exact`
// (central differences over `eps`, one axis after the other); at a corner, the direction away
// from the nearest point.
template <int D, class ExactDistance>
Vec<D> container_normal(const ExactDistance& exact, Vec<D> p, double eps) {
  Vec<D> g;
  for (int a = 0; a < D; ++a) {
    Vec<D> step;
    component_ref(step, a) = eps;
    component_ref(g, a) = exact(p + step) - exact(p - step);
  }
  const double length = norm(g);
  if (length > 0.0) return g / length;
  Vec<D> up;
  component_ref(up, D - 1) = 1.0;
  return up;
}

inline Vec2 container_normal(const TankGeometry& tank, Vec2 p, double eps) {
  return container_normal<2>([&tank](Vec2 q) { return tank.signed_distance(q); }, p, eps);
}

// The wall-contact step above on the fluid particles of `p`. `sampled` is a cheap first test of
// the signed distance (in 2D the sampled ContainerDistance: bilinear between grid nodes `grid`
// apart, so within sqrt(2) grid of the exact value, the distance being 1-Lipschitz), `exact` the
// exact one. Serial, so that the force sum does not depend on the thread count; the first test is
// one look-up per particle.
template <int D, class SampledDistance, class ExactDistance>
BasicWallContact<D> keep_fluid_in_container(BasicParticles<D>& p, const SampledDistance& sampled,
                                            const ExactDistance& exact, double dp, double grid, double dt) {
  const double contact = 0.25 * dp;
  BasicWallContact<D> out;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    // A non-finite position is not a contact: the driver's check reports it (it was counted
    // as a correction before, so the Faltinsen WCSPH run's last row showed 2 contacts).
    if (!is_finite(p.position[i])) continue;
    if (sampled(p.position[i]) >= contact + 1.5 * grid) continue;
    const double d = exact(p.position[i]);
    if (d >= contact) continue;
    const Vec<D> n = container_normal<D>(exact, p.position[i], 1e-3 * dp);
    const double approach = dot(p.velocity[i], n);
    if (approach >= 0.0 && d >= 0.0) continue;  // close, but leaving: nothing to do
    if (approach < 0.0) {
      p.velocity[i] -= approach * n;
      const Vec<D> taken = (p.mass * approach / dt) * n;
      out.force_on_fluid -= taken;
      out.moment_on_fluid -= cross(p.position[i], taken);
    }
    if (d < 0.0) p.position[i] += (0.5 * contact - d) * n;
    ++out.corrected;
  }
  return out;
}

// The 2D tank: the sampled ContainerDistance and the section's exact distance.
inline WallContact keep_fluid_in_tank(Particles& p, const ContainerDistance& distance, const TankGeometry& tank,
                                      double dp, double grid, double dt) {
  return keep_fluid_in_container<2>(
      p, distance, [&tank](Vec2 q) { return tank.signed_distance(q); }, dp, grid, dt);
}

}  // namespace sloshsph
