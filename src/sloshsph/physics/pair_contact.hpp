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
// column 1.8e-10 dp at 9.61 s); half a second later they were still 6e-5 dp apart. Such a pair
// carries two particles' mass at one point, which is a density error the kernel sums cannot see,
// and two equal particles at one point once made the artificial viscosity divide 0 by 0
// (85fbac0).
//
// What, once per step after the scheme has moved the particles, for each pair of fluid particles
// closer than d_c = dp/4 (the wall-contact step's distance), with n the unit vector from
// i to j:
//   * approaching ((u_j - u_i).n < 0): the relative normal velocity is removed, each particle's
//     normal velocity becoming the pair's mean (a perfectly inelastic contact of two equal
//     masses: momentum is kept, the tangential velocities are kept);
//   * closer than d_c / 2: moved apart symmetrically, along n, to d_c / 2 (the centre of mass
//     stays). Two particles at one point (n undefined) part along their relative velocity if
//     they have one, and along x otherwise, the particle that comes first in the fluid order
//     towards -x.
// The pairs are corrected serially, in the order of the neighbour list's rows (i ascending, then
// i's row), so that the result does not depend on the thread count; they are looked for among
// candidates kept from step to step (PairContactStep below). Particles of still water and of
// ordinary flow stand about dp apart, four times d_c, so in calm flow the step does nothing; how
// often it acted is reported (column `pair_contacts`).
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
template <int D>
Vec<D> contact_direction(Vec<D> rij_to_j, Vec<D> relative_velocity) {
  const double r = norm(rij_to_j);
  if (r > 0.0) return rij_to_j / r;
  const double u = norm(relative_velocity);
  if (u > 0.0) return relative_velocity / u;
  Vec<D> x_axis;
  x_axis.x = 1.0;
  return x_axis;
}

// One pair's contact; returns true if it corrected the pair.
template <int D>
bool correct_pair_contact(BasicParticles<D>& p, std::size_t i, std::size_t j, double contact) {
  const Vec<D> d = p.position[j] - p.position[i];
  const double r2 = norm2(d);
  if (!(r2 < contact * contact)) return false;  // also false for a non-finite position
  const Vec<D> n = contact_direction<D>(d, p.velocity[j] - p.velocity[i]);
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

// The pair-contact step on the fluid particles of `p`, with a Verlet list of its own: the pairs
// closer than reach = 3 d_c when it was collected (from the rows of the scheme's neighbour list,
// which hold every pair within the kernel's support and skin, far wider), collected again when some
// fluid particle has moved more than (reach - d_c)/2 since, or the scheme's list was rebuilt (the
// fluid may have been reordered), or the fluid count changed. Between two collections no pair
// that was not collected can come within d_c. Checking every pair of the neighbour list at every
// step instead cost 4.5% of the instructions of a step (Tait with screens, 100 steps); this costs
// a pass over the fluid a step and one over the list every few steps (docs/performance.md).
// The candidates keep the order of the neighbour list's rows (i ascending, then i's row), so
// the corrections are made in the same order whenever the candidates were collected: a resumed
// run, which collects afresh, gives the same bits.
template <int D>
class BasicPairContactStep {
 public:
  explicit BasicPairContactStep(double dp) : contact_(0.25 * dp), reach_(0.75 * dp) {}

  // Corrects the close pairs of `p`; returns how many pairs it corrected.
  std::size_t apply(BasicParticles<D>& p, const BasicNeighbourList<D>& list) {
    if (stale(p, list)) collect(p, list);
    std::size_t corrected = 0;
    for (std::size_t k = 0; k < first_.size(); ++k)
      if (correct_pair_contact(p, first_[k], second_[k], contact_)) ++corrected;
    return corrected;
  }

  std::size_t memory_bytes() const {
    return (first_.capacity() + second_.capacity() + count_.capacity()) * sizeof(std::uint32_t) +
           position_at_collect_.capacity() * sizeof(Vec<D>);
  }

 private:
  bool stale(const BasicParticles<D>& p, const BasicNeighbourList<D>& list) const {
    if (list.builds() != list_builds_ || p.n_fluid != position_at_collect_.size()) return true;
    return moved_more_than(p.position, position_at_collect_, p.n_fluid, 0.5 * (reach_ - contact_));
  }

  // The pairs (i < j, both fluid) closer than reach_, counted per row and then written in row
  // order, both passes in parallel.
  void collect(const BasicParticles<D>& p, const BasicNeighbourList<D>& list) {
    const std::size_t nf = std::min(p.n_fluid, list.rows());
    const double reach2 = reach_ * reach_;
    auto close = [&](std::size_t i, std::uint32_t j) {
      return j > i && j < nf && norm2(p.position[j] - p.position[i]) < reach2;
    };
    count_.assign(nf + 1, 0);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < nf; ++i)
      for (const std::uint32_t* k = list.begin(i); k != list.end(i); ++k) count_[i + 1] += close(i, *k) ? 1 : 0;
    for (std::size_t i = 0; i < nf; ++i) count_[i + 1] += count_[i];
    first_.resize(count_[nf]);
    second_.resize(count_[nf]);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < nf; ++i) {
      std::uint32_t at = count_[i];
      for (const std::uint32_t* k = list.begin(i); k != list.end(i); ++k)
        if (close(i, *k)) {
          first_[at] = static_cast<std::uint32_t>(i);
          second_[at++] = *k;
        }
    }
    position_at_collect_.assign(p.position.begin(), p.position.begin() + static_cast<std::ptrdiff_t>(p.n_fluid));
    list_builds_ = list.builds();
  }

  double contact_;  // d_c = dp/4
  double reach_;    // 3 d_c: pairs closer than this are the candidates
  std::size_t list_builds_ = static_cast<std::size_t>(-1);
  std::vector<Vec<D>> position_at_collect_;  // the fluid's positions at the last collection
  std::vector<std::uint32_t> count_;       // row offsets into the candidates (collection scratch)
  std::vector<std::uint32_t> first_, second_;  // the candidate pairs (i < j)
};

using PairContactStep = BasicPairContactStep<2>;

}  // namespace sloshsph
