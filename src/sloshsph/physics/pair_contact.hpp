#pragma once
// Pair contact: two fluid particles never reach one point (scheme.pair_contact, issue 30
// section 4); the fluid-fluid counterpart of the wall-contact step (physics/wall_contact.hpp).
//
// Why: with Wendland's kernel (and any kernel whose gradient vanishes at r = 0) the pressure force
// between two particles falls to zero as they meet: grad W_ij = F(r) r_ij with F finite at 0, so
// the pair's repulsion is proportional to its distance. Where something else presses them
// together, nothing in the momentum equation parts them again. Measured (column `closest_pair`):
// in cases/faltinsen2000_wcsph.toml, Shao's repulsive walls hold particles about dp/3 from the end
// walls, pairs closer than dp/2 stand along both end walls from the first seconds, and at 9.5 s
// two particles 7 mm from the right wall, 0.24 m up, were at one point (float32 snapshots: 0; the
// column 1.8e-10 dp at 9.61 s); they moved together, 6e-5 dp apart, for seconds after. Such a pair
// carries two particles' mass at one point, which is a density error the kernel sums cannot see,
// and two equal particles at one point once made the artificial viscosity divide 0 by 0
// (85fbac0).
//
// What, once per step after the scheme has moved the particles (serial in the order of the
// fluid, so that the result does not depend on the thread count), for each pair of fluid
// particles closer than d_c = dp/4 (the wall-contact step's distance), with n the unit vector from
// i to j:
//   * approaching ((u_j - u_i).n < 0): the relative normal velocity is removed, each particle's
//     normal velocity becoming the pair's mean (a perfectly inelastic contact of two equal
//     masses: momentum is kept, the tangential velocities are kept);
//   * closer than d_c / 2: moved apart symmetrically, along n, to d_c / 2 (the centre of mass
//     stays). Two particles at one point (n undefined) part along their relative velocity if
//     they have one, and along x otherwise, the particle that comes first in the fluid order
//     towards -x.
// Particles of still water and of ordinary flow stand about dp apart, four times d_c, so in calm
// flow the step does nothing; how often it acted is reported (column `pair_contacts`).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {

// The direction from particle i to j for the contact (see above); unit length.
inline Vec2 contact_direction(Vec2 rij_to_j, Vec2 relative_velocity) {
  const double r = norm(rij_to_j);
  if (r > 0.0) return rij_to_j / r;
  const double u = norm(relative_velocity);
  if (u > 0.0) return relative_velocity / u;
  return Vec2{1.0, 0.0};
}

// One pair's contact; returns true if it corrected the pair.
inline bool correct_pair_contact(Particles& p, std::size_t i, std::size_t j, double contact) {
  const Vec2 d = p.position[j] - p.position[i];
  const double r2 = norm2(d);
  if (!(r2 < contact * contact)) return false;  // also false for a non-finite position
  const Vec2 n = contact_direction(d, p.velocity[j] - p.velocity[i]);
  const double approach = dot(p.velocity[j] - p.velocity[i], n);
  const double r = std::sqrt(r2);
  const bool too_close = r < 0.5 * contact;
  if (approach >= 0.0 && !too_close) return false;
  if (approach < 0.0) {
    p.velocity[i] += (0.5 * approach) * n;
    p.velocity[j] -= (0.5 * approach) * n;
  }
  if (too_close) {
    const double push = 0.5 * (0.5 * contact - r);
    p.position[i] -= push * n;
    p.position[j] += push * n;
  }
  return true;
}

// The pair-contact step on the fluid particles of `p`, over the pairs of the scheme's neighbour
// list (its rows hold every pair within the kernel's support and skin, far wider than d_c).
// `flagged` is scratch. Returns how many pairs it corrected.
inline std::size_t keep_fluid_pairs_apart(Particles& p, const NeighbourList& list, double dp,
                                          std::vector<std::uint8_t>& flagged) {
  const double contact = 0.25 * dp;
  const double contact2 = contact * contact;
  const std::size_t nf = std::min(p.n_fluid, list.rows());
  flagged.assign(nf, 0);
  // Find the rows with a close pair in parallel (reads only); correct them in order, serially.
  bool any = false;
#pragma omp parallel for schedule(static) reduction(|| : any)
  for (std::size_t i = 0; i < nf; ++i) {
    const Vec2 ri = p.position[i];
    for (const std::uint32_t* k = list.begin(i); k != list.end(i); ++k)
      if (*k > i && *k < nf && norm2(p.position[*k] - ri) < contact2) {
        flagged[i] = 1;
        any = true;
        break;
      }
  }
  if (!any) return 0;
  std::size_t corrected = 0;
  for (std::size_t i = 0; i < nf; ++i) {
    if (!flagged[i]) continue;
    for (const std::uint32_t* k = list.begin(i); k != list.end(i); ++k)
      if (*k > i && *k < nf && correct_pair_contact(p, i, *k, contact)) ++corrected;
  }
  return corrected;
}

}  // namespace sloshsph
