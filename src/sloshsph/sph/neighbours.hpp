#pragma once
// Cell-linked list and a Verlet neighbour list in compressed-row form, for 2 or 3 dimensions
// (CellGrid and NeighbourList are the 2D ones; the definitions are instantiated for both in
// neighbours.cpp).
// The list is built with a skin around the kernel support and reused until some
// fluid particle has moved more than half the skin; every sweep of a time step
// then reads the same list (gather style: each particle reads its own row).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sloshsph/core/state_io.hpp"
#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

// Uniform grid of square (cubic in 3D) cells; particle indices sorted by cell (counting sort,
// stable). Cells are numbered x fastest, then y, then z (a 2D grid is one layer of cells in z).
template <int D>
class BasicCellGrid {
 public:
  void build(const std::vector<Vec<D>>& position, std::size_t begin, std::size_t end, double cell_size);

  double cell_size() const { return cell_size_; }
  // Cells along axis k (0: x, 1: y, 2: z; 1 along z in 2D).
  int cells(int k) const { return n_[k]; }
  int cell_along(int k, double coordinate) const {
    return clamp_index(static_cast<int>(std::floor((coordinate - component(origin_, k)) / cell_size_)), n_[k]);
  }
  int cell_of(Vec<D> p) const {
    const int c = cell_along(0, p.x) + n_[0] * cell_along(1, p.y);
    if constexpr (D == 3) return c + n_[0] * n_[1] * cell_along(2, p.z);
    else return c;
  }
  // Particles of cell c: sorted()[cell_start()[c] .. cell_start()[c + 1]).
  const std::vector<std::uint32_t>& cell_start() const { return cell_start_; }
  const std::vector<std::uint32_t>& sorted() const { return sorted_; }

  // Calls f(j) for every indexed particle in the cells overlapping the box of half-width
  // `radius` around p, cell by cell in the order of their numbers. The caller checks the exact
  // distance.
  template <class F>
  void for_each_candidate(Vec<D> p, double radius, F&& f) const {
    if (sorted_.empty()) return;
    int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) {
      lo[k] = cell_along(k, component(p, k) - radius);
      hi[k] = cell_along(k, component(p, k) + radius);
    }
    for (int cz = lo[2]; cz <= hi[2]; ++cz)
      for (int cy = lo[1]; cy <= hi[1]; ++cy)
        for (int cx = lo[0]; cx <= hi[0]; ++cx) {
          const int c = cx + n_[0] * (cy + n_[1] * cz);
          for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) f(sorted_[k]);
        }
  }

 private:
  static int clamp_index(int i, int n) { return i < 0 ? 0 : (i >= n ? n - 1 : i); }
  double cell_size_ = 1.0;
  Vec<D> origin_;
  int n_[3] = {0, 0, 1};
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> sorted_;
};

using CellGrid = BasicCellGrid<2>;
using CellGrid3 = BasicCellGrid<3>;

template <int D>
class BasicNeighbourList {
 public:
  // support: kernel support radius (2h); skin: extra search distance.
  BasicNeighbourList(double support, double skin) : support_(support), skin_(skin) {}

  // True when the list must be rebuilt: never built, particle count changed,
  // or a particle (fluid, or the wall of a moving plate) moved more than skin/2 since the last build.
  bool stale(const std::vector<Vec<D>>& position, std::size_t n_fluid) const;

  // Rows for all particles: fluid rows hold fluid and wall neighbours, wall rows
  // only fluid neighbours (walls never interact with walls). Self is excluded.
  void build(const std::vector<Vec<D>>& position, std::size_t n_fluid);

  // Rebuilds if stale; returns true if it did.
  bool update(const std::vector<Vec<D>>& position, std::size_t n_fluid) {
    if (!stale(position, n_fluid)) return false;
    build(position, n_fluid);
    return true;
  }

  void invalidate() { built_ = false; }

  const std::uint32_t* begin(std::size_t i) const { return index_.data() + offset_[i]; }
  const std::uint32_t* end(std::size_t i) const { return index_.data() + offset_[i + 1]; }
  std::size_t count(std::size_t i) const { return offset_[i + 1] - offset_[i]; }
  // Row i's entries are index slots [offset(i), offset(i + 1)).
  std::size_t offset(std::size_t i) const { return offset_[i]; }
  std::size_t rows() const { return offset_.empty() ? 0 : offset_.size() - 1; }
  std::size_t total_pairs() const { return index_.size(); }
  double search_radius() const { return support_ + skin_; }
  double skin() const { return skin_; }
  std::size_t builds() const { return builds_; }
  const BasicCellGrid<D>& grid() const { return grid_; }
  std::size_t memory_bytes() const;

  // Checkpoints: the list as built (rows, positions at the build), so that a resumed run
  // rebuilds at exactly the steps the uninterrupted run does (summation order included).
  void save(StateWriter& w) const;
  void load(StateReader& r);

 private:
  double support_;
  double skin_;
  bool built_ = false;
  std::size_t builds_ = 0;
  std::size_t n_fluid_at_build_ = 0;
  BasicCellGrid<D> grid_;
  std::vector<Vec<D>> position_at_build_;
  std::vector<std::size_t> offset_;
  std::vector<std::uint32_t> index_;
};

using NeighbourList = BasicNeighbourList<2>;
using NeighbourList3 = BasicNeighbourList<3>;

// Whether any of the first `count` points of `now` lies more than `distance` from its place in
// `then` (a list kept with a skin is stale then). A non-finite position counts as not moved: the
// driver's own check stops such a run.
template <int D>
bool moved_more_than(const std::vector<Vec<D>>& now, const std::vector<Vec<D>>& then, std::size_t count,
                     double distance);

// Fluid order that follows the cells of a grid of the given size (for memory locality).
template <int D>
std::vector<std::uint32_t> cell_order(const std::vector<Vec<D>>& position, std::size_t n_fluid, double cell_size);

}  // namespace sloshsph
