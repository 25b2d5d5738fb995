#include "sloshsph/sph/neighbours.hpp"

#include <algorithm>
#include <limits>

namespace sloshsph {

void CellGrid::build(const std::vector<Vec2>& position, std::size_t begin, std::size_t end, double cell_size) {
  cell_size_ = cell_size;
  double xmin = std::numeric_limits<double>::max(), ymin = xmin;
  double xmax = std::numeric_limits<double>::lowest(), ymax = xmax;
  for (std::size_t i = begin; i < end; ++i) {
    xmin = std::min(xmin, position[i].x);
    xmax = std::max(xmax, position[i].x);
    ymin = std::min(ymin, position[i].y);
    ymax = std::max(ymax, position[i].y);
  }
  if (begin == end) xmin = xmax = ymin = ymax = 0.0;
  origin_ = {xmin - cell_size, ymin - cell_size};
  nx_ = static_cast<int>((xmax - origin_.x) / cell_size) + 2;
  ny_ = static_cast<int>((ymax - origin_.y) / cell_size) + 2;
  const std::size_t ncell = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
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

bool moved_more_than(const std::vector<Vec2>& now, const std::vector<Vec2>& then, std::size_t count, double distance) {
  const double limit2 = distance * distance;
  bool moved = false;
#pragma omp parallel for reduction(|| : moved) schedule(static)
  for (std::size_t i = 0; i < count; ++i) moved = moved || norm2(now[i] - then[i]) > limit2;
  return moved;
}

bool NeighbourList::stale(const std::vector<Vec2>& position, std::size_t n_fluid) const {
  if (!built_ || position.size() != position_at_build_.size() || n_fluid != n_fluid_at_build_) return true;
  // Every particle: the walls of an elastic plate move too (fixed walls never trip the test).
  return moved_more_than(position, position_at_build_, position.size(), 0.5 * skin_);
}

void NeighbourList::build(const std::vector<Vec2>& position, std::size_t n_fluid) {
  const std::size_t n = position.size();
  const double radius = support_ + skin_;
  const double r2 = radius * radius;
  grid_.build(position, 0, n, radius);
  offset_.assign(n + 1, 0);

  // A wall particle never lists another wall particle.
  auto for_each_neighbour = [&](std::size_t i, auto&& emit) {
    const Vec2 pi = position[i];
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

std::size_t NeighbourList::memory_bytes() const {
  return offset_.capacity() * sizeof(std::size_t) + index_.capacity() * sizeof(std::uint32_t) +
         position_at_build_.capacity() * sizeof(Vec2) + grid_.sorted().capacity() * sizeof(std::uint32_t) +
         grid_.cell_start().capacity() * sizeof(std::uint32_t);
}

std::vector<std::uint32_t> cell_order(const std::vector<Vec2>& position, std::size_t n_fluid, double cell_size) {
  CellGrid grid;
  grid.build(position, 0, n_fluid, cell_size);
  return grid.sorted();
}

void NeighbourList::save(StateWriter& w) const {
  w.value("neighbours.built", static_cast<std::uint8_t>(built_));
  w.value("neighbours.builds", static_cast<std::uint64_t>(builds_));
  w.value("neighbours.n_fluid", static_cast<std::uint64_t>(n_fluid_at_build_));
  w.array("neighbours.position_at_build", position_at_build_);
  w.array("neighbours.offset", offset_);
  w.array("neighbours.index", index_);
}

void NeighbourList::load(StateReader& r) {
  built_ = r.value<std::uint8_t>("neighbours.built") != 0;
  builds_ = static_cast<std::size_t>(r.value<std::uint64_t>("neighbours.builds"));
  n_fluid_at_build_ = static_cast<std::size_t>(r.value<std::uint64_t>("neighbours.n_fluid"));
  position_at_build_ = r.array<Vec2>("neighbours.position_at_build");
  offset_ = r.array<std::size_t>("neighbours.offset");
  index_ = r.array<std::uint32_t>("neighbours.index");
  // The grid is a function of the positions at the build: rebuilt, not stored.
  if (built_) grid_.build(position_at_build_, 0, position_at_build_.size(), support_ + skin_);
}

}  // namespace sloshsph
