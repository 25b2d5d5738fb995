#pragma once
// The pair layer: every interaction between two particles in a scheme goes through a PairList
// (PairList3 in 3D: the same code, BasicPairList<D>).
//
// A PairList is the Verlet neighbour list (sph/neighbours.hpp) filtered to the kernel's support
// at one set of positions: it is built once per set of positions a step uses (ISPH: r(t), then
// r*; WCSPH: each evaluation of the rates and the end of the step), and every stage then visits
// the same pairs through for_each, which hands it r_ij, the kernel value W and the gradient factor
// F (grad_i W_ij = F r_ij). So the cut-off lives here alone, the skin's pairs cost nothing after
// the build, and the stages state only their physics.
//
// What is kept per pair is the neighbour's index and the kernel's W and F, worked out once in the
// build, for the pairs within the support only (per block of rows, below); r_ij is worked out from
// the positions as a stage reads the pair. An ISPH step reads each
// set of pairs in three to four stages, each of which evaluated the kernel (a square root and its
// polynomial) before. Measured (docs/performance.md, "The kept multigrid hierarchy and the stored
// kernel"): on the machine of 2026-12-05 (2 MiB of L2 a core) the stages that read the pairs fell
// to 25-45% of their time and the build rose 3-fold, for 16 bytes a Verlet slot; the step of the
// Tait tank with screens ran 15% faster (3.20 against 3.76 ms, min of 5 alternated, one thread).
// On the machine of 2026-12-04 (512 KiB of L2) the same idea had run no faster, probably because
// the pair data then no longer fit the cache.
//
// Order: a row keeps the order of its Verlet row, so every sum over pairs adds the same terms
// in the same order as a loop over the Verlet row that skips the pairs beyond the support. A
// stage that used to visit the skin's pairs added exact zeros for them (W = F = 0 for q >= 2),
// which changes no sum: the results are the same bits.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/kernel.hpp"
#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {

// One pair (i, j) of i's row, as a stage sees it.
template <int D>
struct BasicPair {
  std::uint32_t j;  // the neighbour
  Vec<D> rij;       // r_i - r_j, m
  double w;         // W(|r_ij|), 1/m^2 (1/m^3 in 3D)
  double f;         // (dW/dr) / r: grad_i W_ij = f r_ij, 1/m^4 (1/m^5 in 3D)
  double r2() const { return norm2(rij); }
};

template <int D>
class BasicPairList {
 public:
  // The pairs of the rows from `first_row` on of `nl` with r_ij^2 within kernel_reach2 at
  // positions `x` (the same particles, fluid then walls, as the list was built for), for the
  // kernel `type` of smoothing length h. Rows before `first_row` are left empty (a pass that reads
  // only the walls' rows need not filter the fluid's).
  void build(KernelType type, double h, const std::vector<Vec<D>>& x, const BasicNeighbourList<D>& nl,
             std::size_t first_row = 0) {
    const std::size_t n = nl.rows();
    assert(x.size() == n && "one position per row");
    x_ = &x;
    cubic_ = type == KernelType::cubic_spline;
    wendland_ = WendlandC2(h, D);
    cubic_spline_ = CubicSpline(h, D);
    self_w_ = cubic_ ? cubic_spline_.w(0.0) : wendland_.w(0.0);
    reach2_ = cubic_ ? kernel_reach2(cubic_spline_) : kernel_reach2(wendland_);
    begin_.resize(n);
    end_.resize(n);
    blocks_.resize((n + kBlockRows - 1) / kBlockRows);
#pragma omp parallel for schedule(static)
    for (std::size_t b = 0; b < blocks_.size(); ++b) build_block(b, nl, first_row);
  }

  void build(const WendlandC2& k, const std::vector<Vec<D>>& x, const BasicNeighbourList<D>& nl) {
    build(KernelType::wendland_c2, k.h, x, nl);
  }
  void build(const CubicSpline& k, const std::vector<Vec<D>>& x, const BasicNeighbourList<D>& nl) {
    build(KernelType::cubic_spline, k.h, x, nl);
  }

  // Calls body(const BasicPair<D>&) for each pair of row i, in the row's order.
  template <class Body>
  void for_each(std::size_t i, Body&& body) const {
    row(i, body);
  }

  // W(0): a particle's own share of a kernel sum.
  double self_w() const { return self_w_; }
  std::size_t count(std::size_t i) const { return end_[i] - begin_[i]; }
  std::size_t rows() const { return end_.size(); }
  std::size_t memory_bytes() const {
    std::size_t bytes = (begin_.capacity() + end_.capacity()) * sizeof(std::uint32_t) +
                        blocks_.capacity() * sizeof(Block);
    for (const Block& b : blocks_)
      bytes += b.j.capacity() * sizeof(std::uint32_t) + (b.w.capacity() + b.f.capacity()) * sizeof(double);
    return bytes;
  }

 private:
  // The pairs are kept per block of kBlockRows rows, each block's rows one after the other, so that
  // only the pairs within the support take memory, not every slot of the Verlet list (a third of
  // which is skin): a row's count is known only once it is filtered, and a block's arrays grow
  // when its rows need more room than any build before (docs/performance.md, "Where the memory
  // goes"). 64 rows: blocks small enough that the static split over two threads stays even on a
  // tank of 2,000 particles.
  static constexpr std::size_t kBlockRows = 64;
  struct Block {
    std::vector<std::uint32_t> j;  // the neighbour
    std::vector<double> w, f;      // W and F of the pair in the same slot
  };

  // Filters block b's rows into its arrays.
  void build_block(std::size_t b, const BasicNeighbourList<D>& nl, std::size_t first_row) {
    const std::vector<Vec<D>>& x = *x_;
    Block& block = blocks_[b];
    const std::size_t first = b * kBlockRows, last = std::min(first + kBlockRows, nl.rows());
    const std::uint32_t* index = nl.begin(0);
    std::size_t out = 0;
    for (std::size_t i = first; i < last; ++i) {
      begin_[i] = static_cast<std::uint32_t>(out);
      if (i < first_row) {
        end_[i] = begin_[i];
        continue;
      }
      const std::size_t candidates = nl.count(i);
      if (block.j.size() < out + candidates) grow(block, out + candidates, out, i - first, last - i - 1);
      const Vec<D> ri = x[i];
      std::uint32_t* j_out = block.j.data();
      double* r2_out = block.w.data();
      // Without a branch on the cut-off (a third of the Verlet row is skin, in no predictable
      // order): every candidate is written at `out`, which moves on only for a pair within the
      // support (the block has room for all of the row's candidates).
      // r^2 waits in w for fill_kernel.
      for (std::size_t s = nl.offset(i); s < nl.offset(i + 1); ++s) {
        const std::uint32_t j = index[s];
        const double r2 = norm2(ri - x[j]);
        j_out[out] = j;
        r2_out[out] = r2;
        out += r2 <= reach2_ ? 1 : 0;
      }
      end_[i] = static_cast<std::uint32_t>(out);
    }
    if (cubic_) fill_kernel(cubic_spline_, block, out);
    else fill_kernel(wendland_, block, out);
  }

  // Room for `needed` slots and for the block's `rows_left` rows at the mean kept count of its
  // `rows_done` (`kept` pairs), so that the first build of a block grows it about twice and not
  // to the size of its Verlet rows; and a sixteenth more, so that a later build whose rows hold a
  // few pairs more than any before does not grow it again at once.
  static void grow(Block& block, std::size_t needed, std::size_t kept, std::size_t rows_done, std::size_t rows_left) {
    const std::size_t rest = rows_done > 0 ? kept / rows_done * rows_left : 0;
    const std::size_t size = needed + rest + (needed + rest) / 16;
    block.j.resize(size);
    block.w.resize(size);
    block.f.resize(size);
  }

  // W and F of a block's first `count` slots (its rows' kept pairs), from the r^2 the filter left in
  // w: once per build for every stage, the block's rows at once (a loop without gathers, which the
  // compiler vectorises).
  template <class K>
  static void fill_kernel(const K& kernel, Block& block, std::size_t count) {
    double* w = block.w.data();
    double* f = block.f.data();
#pragma omp simd
    for (std::size_t s = 0; s < count; ++s) {
      double ws, fs;
      kernel.w_and_gradient(std::sqrt(w[s]), ws, fs);
      w[s] = ws;
      f[s] = fs;
    }
  }

  template <class Body>
  void row(std::size_t i, Body& body) const {
    const std::vector<Vec<D>>& x = *x_;
    const Vec<D> ri = x[i];
    const Block& block = blocks_[i / kBlockRows];
    const std::uint32_t* j = block.j.data();
    const double* w = block.w.data();
    const double* f = block.f.data();
    // The bounds in locals: a body that writes 32-bit integers (the PPE's column indices) could
    // otherwise alias end_ and make the compiler load it again at every pair.
    const std::size_t begin = begin_[i], end = end_[i];
    for (std::size_t s = begin; s < end; ++s) body(BasicPair<D>{j[s], ri - x[j[s]], w[s], f[s]});
  }

  const std::vector<Vec<D>>* x_ = nullptr;
  bool cubic_ = false;
  WendlandC2 wendland_{1.0};
  CubicSpline cubic_spline_{1.0};
  double self_w_ = 0.0;
  double reach2_ = 0.0;
  std::vector<std::uint32_t> begin_, end_;  // row i's pairs: slots [begin_[i], end_[i]) of its block
  std::vector<Block> blocks_;
};

using Pair = BasicPair<2>;
using PairList = BasicPairList<2>;
using Pair3 = BasicPair<3>;
using PairList3 = BasicPairList<3>;

}  // namespace sloshsph
