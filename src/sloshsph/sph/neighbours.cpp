#include "sloshsph/sph/neighbours.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {

template <int D>
void BasicCellGrid<D>::build(const std::vector<Vec<D>>& position, std::size_t begin, std::size_t end,
                             double cell_size) {
  cell_size_ = cell_size;
  // The bounding box of the indexed points, one empty cell around it.
  Vec<D> lowest = componentwise(Vec<D>{}, [](double) { return std::numeric_limits<double>::max(); });
  Vec<D> highest = -lowest;
  for (std::size_t i = begin; i < end; ++i) {
    // std::min and std::max pass a NaN by, and its cell index would be undefined: refused here
    // (found: the sample of a failed step's state built a grid over it, 2026-12-07).
    if (!is_finite(position[i])) throw RunFailure("cell grid: point " + std::to_string(i) + " is not finite");
    lowest = componentwise(lowest, position[i], [](double a, double b) { return std::min(a, b); });
    highest = componentwise(highest, position[i], [](double a, double b) { return std::max(a, b); });
  }
  if (begin == end) lowest = highest = Vec<D>{};
  origin_ = componentwise(lowest, [cell_size](double a) { return a - cell_size; });
  double cells = 1.0;
  for (int k = 0; k < D; ++k) cells *= (component(highest, k) - component(origin_, k)) / cell_size + 2.0;
  // The points are inside the tank but for a step's flight of the leaked ones: a grid of more
  // cells than this means points flung far away, which a run reports rather than allocates.
  constexpr double kMaxCells = 2.0e8;
  if (!(cells <= kMaxCells))
    throw RunFailure("cell grid: the points spread over " + std::to_string(cells) + " cells of " +
                     std::to_string(cell_size) + " m (points flung far out of the tank)");
  std::size_t ncell = 1;
  for (int k = 0; k < D; ++k) {
    n_[k] = static_cast<int>((component(highest, k) - component(origin_, k)) / cell_size) + 2;
    ncell *= static_cast<std::size_t>(n_[k]);
  }
  cell_start_.assign(ncell + 1, 0);
  std::vector<std::uint32_t> cell(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    const int c = cell_of(position[i]);
    cell[i - begin] = static_cast<std::uint32_t>(c);
    ++cell_start_[c + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(end - begin);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = begin; i < end; ++i) sorted_[fill[cell[i - begin]]++] = static_cast<std::uint32_t>(i);
}

template <int D>
bool moved_more_than(const std::vector<Vec<D>>& now, const std::vector<Vec<D>>& then, std::size_t count,
                     double distance) {
  const double limit2 = distance * distance;
  bool moved = false;
#pragma omp parallel for reduction(|| : moved) schedule(static)
  for (std::size_t i = 0; i < count; ++i) moved = moved || norm2(now[i] - then[i]) > limit2;
  return moved;
}

template <int D>
bool BasicNeighbourList<D>::stale(const std::vector<Vec<D>>& position, std::size_t n_fluid) const {
  if (!built_ || position.size() != position_at_build_.size() || n_fluid != n_fluid_at_build_) return true;
  // Every particle: the walls of an elastic plate move too (fixed walls never trip the test).
  return moved_more_than(position, position_at_build_, position.size(), 0.5 * skin_);
}

template <int D>
void BasicNeighbourList<D>::build(const std::vector<Vec<D>>& position, std::size_t n_fluid) {
  const std::size_t n = position.size();
  const double radius = support_ + skin_;
  const double r2 = radius * radius;
  grid_.build(position, 0, n, radius);
  offset_.assign(n + 1, 0);

  // A wall particle never lists another wall particle.
  auto for_each_neighbour = [&](std::size_t i, auto&& emit) {
    const Vec<D> pi = position[i];
    const bool wall_i = i >= n_fluid;
    grid_.for_each_candidate(pi, radius, [&](std::uint32_t j) {
      if (j == i || (wall_i && j >= n_fluid)) return;
      if (norm2(position[j] - pi) < r2) emit(j);
    });
  };

#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t c = 0;
    for_each_neighbour(i, [&](std::uint32_t) { ++c; });
    offset_[i + 1] = c;
  }
  for (std::size_t i = 0; i < n; ++i) offset_[i + 1] += offset_[i];
  index_.resize(offset_[n]);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t* out = index_.data() + offset_[i];
    for_each_neighbour(i, [&](std::uint32_t j) { *out++ = j; });
  }
  position_at_build_ = position;
  n_fluid_at_build_ = n_fluid;
  built_ = true;
  ++builds_;
}

template <int D>
std::size_t BasicNeighbourList<D>::memory_bytes() const {
  return offset_.capacity() * sizeof(std::size_t) + index_.capacity() * sizeof(std::uint32_t) +
         position_at_build_.capacity() * sizeof(Vec<D>) + grid_.sorted().capacity() * sizeof(std::uint32_t) +
         grid_.cell_start().capacity() * sizeof(std::uint32_t);
}

template <int D>
std::vector<std::uint32_t> cell_order(const std::vector<Vec<D>>& position, std::size_t n_fluid, double cell_size) {
  BasicCellGrid<D> grid;
  grid.build(position, 0, n_fluid, cell_size);
  return grid.sorted();
}

template <int D>
void BasicNeighbourList<D>::save(StateWriter& w) const {
  w.value("neighbours.built", static_cast<std::uint8_t>(built_));
  w.value("neighbours.builds", static_cast<std::uint64_t>(builds_));
  w.value("neighbours.n_fluid", static_cast<std::uint64_t>(n_fluid_at_build_));
  w.array("neighbours.position_at_build", position_at_build_);
  w.array("neighbours.offset", offset_);
  w.array("neighbours.index", index_);
}

template <int D>
void BasicNeighbourList<D>::load(StateReader& r) {
  built_ = r.value<std::uint8_t>("neighbours.built") != 0;
  builds_ = static_cast<std::size_t>(r.value<std::uint64_t>("neighbours.builds"));
  n_fluid_at_build_ = static_cast<std::size_t>(r.value<std::uint64_t>("neighbours.n_fluid"));
  position_at_build_ = r.array<Vec<D>>("neighbours.position_at_build");
  offset_ = r.array<std::size_t>("neighbours.offset");
  index_ = r.array<std::uint32_t>("neighbours.index");
  // The grid is a function of the positions at the build: rebuilt, not stored.
  if (built_) grid_.build(position_at_build_, 0, position_at_build_.size(), support_ + skin_);
}

// The two dimensions.
template class BasicCellGrid<2>;
template class BasicCellGrid<3>;
template class BasicNeighbourList<2>;
template class BasicNeighbourList<3>;
template bool moved_more_than<2>(const std::vector<Vec2>&, const std::vector<Vec2>&, std::size_t, double);
template bool moved_more_than<3>(const std::vector<Vec3>&, const std::vector<Vec3>&, std::size_t, double);
template std::vector<std::uint32_t> cell_order<2>(const std::vector<Vec2>&, std::size_t, double);
template std::vector<std::uint32_t> cell_order<3>(const std::vector<Vec3>&, std::size_t, double);

}  // namespace sloshsph
