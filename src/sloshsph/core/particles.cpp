#include "sloshsph/core/particles.hpp"

#include <stdexcept>

namespace sloshsph {
namespace {

template <class T>
void permute_prefix(std::vector<T>& v, const std::vector<std::uint32_t>& order, std::vector<T>& scratch) {
  scratch.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) scratch[k] = v[order[k]];
  std::copy(scratch.begin(), scratch.end(), v.begin());
}

template <class T>
void compact_prefix(std::vector<T>& v, std::size_t n_prefix, const std::vector<std::uint8_t>& remove) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i < n_prefix && remove[i]) continue;
    v[out++] = v[i];
  }
  v.resize(out);
}

// Every per-particle array must have the length of `position`; a store built by hand
// that misses one would otherwise be read out of bounds by the permutation.
template <int D>
void require_consistent(const BasicParticles<D>& p) {
  const std::size_t n = p.size();
  if (p.velocity.size() != n || p.pressure.size() != n || p.pressure_back.size() != n ||
      p.density.size() != n || p.normal.size() != n || p.id.size() != n || p.n_fluid > n ||
      p.wall_motion_velocity.size() != p.wall_motion_acceleration.size() ||
      (p.has_moving_walls() && p.wall_motion_velocity.size() != n - p.n_fluid))
    throw std::logic_error("Particles: per-particle arrays differ in length (use Particles::resize)");
}

}  // namespace

template <int D>
void BasicParticles<D>::permute_fluid(const std::vector<std::uint32_t>& order) {
  std::vector<Vec<D>> s2;
  std::vector<double> s1;
  std::vector<std::int32_t> si;
  require_consistent(*this);
  permute_prefix(position, order, s2);
  permute_prefix(velocity, order, s2);
  permute_prefix(normal, order, s2);
  permute_prefix(pressure, order, s1);
  permute_prefix(pressure_back, order, s1);
  permute_prefix(density, order, s1);
  permute_prefix(id, order, si);
}

template <int D>
void BasicParticles<D>::remove_fluid(const std::vector<std::uint8_t>& remove) {
  require_consistent(*this);
  const std::size_t n = n_fluid;
  compact_prefix(position, n, remove);
  compact_prefix(velocity, n, remove);
  compact_prefix(normal, n, remove);
  compact_prefix(pressure, n, remove);
  compact_prefix(pressure_back, n, remove);
  compact_prefix(density, n, remove);
  compact_prefix(id, n, remove);
  std::size_t removed = 0;
  for (std::size_t i = 0; i < n; ++i) removed += remove[i] ? 1 : 0;
  n_fluid -= removed;
}

template struct BasicParticles<2>;
template struct BasicParticles<3>;

}  // namespace sloshsph
