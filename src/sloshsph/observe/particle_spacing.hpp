#pragma once
// The closest pair of fluid particles (timeseries column `closest_pair`, issue 30 section 4):
// particles of an SPH fluid stand about dp apart, and two that come much closer than that are the
// start of a merged pair (with Wendland's kernel the pressure force between two particles vanishes
// as their distance does, so nothing in the momentum equation parts two that have met).
#include <algorithm>
#include <cstddef>
#include <limits>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {

// The smallest distance between two fluid particles, in m, or `reach` when no two are closer than
// that. One cell grid of the fluid with cells of `reach`: O(n).
// NaN when a fluid position is not finite (the state of a failed step, sampled for the record).
template <int D>
double closest_fluid_pair(const BasicParticles<D>& p, double reach) {
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    if (!is_finite(p.position[i])) return std::numeric_limits<double>::quiet_NaN();
  BasicCellGrid<D> grid;
  grid.build(p.position, 0, p.n_fluid, reach);
  double closest2 = reach * reach;
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    grid.for_each_candidate(p.position[i], reach, [&](std::uint32_t j) {
      if (j <= i) return;  // each pair once
      closest2 = std::min(closest2, norm2(p.position[j] - p.position[i]));
    });
  return std::sqrt(closest2);
}

}  // namespace sloshsph
