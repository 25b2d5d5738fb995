#pragma once
// Rows split into contiguous ranges of about equal cost, one range per thread.
//
// An OpenMP static schedule gives each thread the same number of rows. Where rows cost unequal
// amounts the thread with the cheap rows waits at the loop's end: the PPE's fluid rows (about 25
// entries at h = 1.4 dp) come before its wall rows (about 8), the pair list's fluid rows before
// the walls' (a wall lists fluid neighbours only), and the free surface's short rows gather at
// the end of the fluid's cell order. Loops over such rows split them by cost instead
// (docs/performance.md, "Two threads: rows split by their cost"). Which thread works a row never
// changes what is computed for it, so the results stay the same bits on any thread count.
#include <omp.h>

#include <cstddef>
#include <vector>

namespace sloshsph {

class ThreadRanges {
 public:
  // Splits rows [0, n) into `parts` contiguous ranges whose sums of cost(i) (non-negative) are
  // as equal as the rows allow (equal row counts where every cost is 0). Two passes over the rows.
  template <class Cost>
  void balance(std::size_t n, int parts, Cost&& cost) {
    parts = parts < 1 ? 1 : parts;
    double total = 0.0;
    for (std::size_t i = 0; i < n; ++i) total += static_cast<double>(cost(i));
    if (!(total > 0.0)) {
      even(n, parts);
      return;
    }
    bounds_.assign(static_cast<std::size_t>(parts) + 1, n);
    bounds_[0] = 0;
    // Range k ends at the first row whose running cost reaches k / parts of the total.
    double running = 0.0;
    int k = 1;
    for (std::size_t i = 0; i < n && k < parts; ++i) {
      while (k < parts && running >= total * k / parts) bounds_[static_cast<std::size_t>(k++)] = i;
      running += static_cast<double>(cost(i));
    }
  }

  // The whole of [0, n) split into `parts` ranges of equal row counts (as schedule(static) does).
  void even(std::size_t n, int parts) {
    parts = parts < 1 ? 1 : parts;
    bounds_.resize(static_cast<std::size_t>(parts) + 1);
    for (std::size_t k = 0; k < bounds_.size(); ++k) bounds_[k] = n * k / static_cast<std::size_t>(parts);
  }

  // Ranges over blocks of `block` consecutive rows, from ranges over the rows: each bound is the
  // row bound rounded to the nearest block boundary.
  void blocks_of(const ThreadRanges& rows, std::size_t block) {
    const std::size_t blocks = (rows.rows() + block - 1) / block;
    bounds_.resize(rows.bounds_.size());
    for (std::size_t k = 0; k < bounds_.size(); ++k) {
      const std::size_t b = (rows.bounds_[k] + block / 2) / block;
      bounds_[k] = b < blocks ? b : blocks;
    }
    if (!bounds_.empty()) bounds_.back() = blocks;
  }

  int parts() const { return bounds_.empty() ? 0 : static_cast<int>(bounds_.size()) - 1; }
  std::size_t rows() const { return bounds_.empty() ? 0 : bounds_.back(); }
  std::size_t begin(int part) const { return bounds_[static_cast<std::size_t>(part)]; }
  std::size_t end(int part) const { return bounds_[static_cast<std::size_t>(part) + 1]; }
  std::size_t memory_bytes() const { return bounds_.capacity() * sizeof(std::size_t); }

 private:
  std::vector<std::size_t> bounds_;  // part k holds rows [bounds_[k], bounds_[k + 1])
};

// Calls body(i) for every row of `ranges`, each range on one thread of one parallel region. A
// region with fewer threads than ranges (ranges split for more threads than are allowed now, a
// nested region, a thread limit) works the ranges round-robin.
template <class Body>
void parallel_for_ranges(const ThreadRanges& ranges, Body&& body) {
  const int parts = ranges.parts();
  if (parts <= 1) {
    for (std::size_t i = 0; i < ranges.rows(); ++i) body(i);
    return;
  }
  const int allowed = omp_get_max_threads();
#pragma omp parallel num_threads(parts < allowed ? parts : allowed)
  {
    const int threads = omp_get_num_threads();
    for (int part = omp_get_thread_num(); part < parts; part += threads)
      for (std::size_t i = ranges.begin(part); i < ranges.end(part); ++i) body(i);
  }
}

}  // namespace sloshsph
