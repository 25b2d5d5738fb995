#pragma once
// The pair layer: every interaction between two particles in a scheme goes through a PairList.
//
// A PairList is the Verlet neighbour list (sph/neighbours.hpp) filtered to the kernel's support
// at one set of positions: it is built once per set of positions a step uses (ISPH: r(t), then
// r*; WCSPH: each evaluation of the rates and the end of the step), and every stage then visits
// the same pairs through for_each, which hands it r_ij, the kernel value W and the gradient factor
// F (grad_i W_ij = F r_ij). So the cut-off lives here alone, the skin's pairs cost nothing after
// the build, and the stages state only their physics.
//
// What is kept per pair is the neighbour's index and the kernel's W and F, worked out once in the
// build; r_ij is worked out from the positions as a stage reads the pair. An ISPH step reads each
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
struct Pair {
  std::uint32_t j;  // the neighbour
  Vec2 rij;         // r_i - r_j, m
  double w;         // W(|r_ij|), 1/m^2
  double f;         // (dW/dr) / r: grad_i W_ij = f r_ij, 1/m^4
  double r2() const { return norm2(rij); }
};

class PairList {
 public:
  // The pairs of the rows from `first_row` on of `nl` with r_ij^2 within kernel_reach2 at
  // positions `x` (the same particles, fluid then walls, as the list was built for), for the
  // kernel `type` of smoothing length h. Rows before `first_row` are left empty (a pass that reads
  // only the walls' rows need not filter the fluid's).
  void build(KernelType type, double h, const std::vector<Vec2>& x, const NeighbourList& nl,
             std::size_t first_row = 0) {
    const std::size_t n = nl.rows();
    assert(x.size() == n && "one position per row");
    x_ = &x;
    nl_ = &nl;
    cubic_ = type == KernelType::cubic_spline;
    wendland_ = WendlandC2(h);
    cubic_spline_ = CubicSpline(h);
    self_w_ = cubic_ ? cubic_spline_.w(0.0) : wendland_.w(0.0);
    const double reach2 = cubic_ ? kernel_reach2(cubic_spline_) : kernel_reach2(wendland_);
    end_.resize(n);
    j_.resize(nl.total_pairs());
    w_.resize(nl.total_pairs());
    f_.resize(nl.total_pairs());
    if (n == 0) return;
    const std::uint32_t* index = nl.begin(0);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      if (i < first_row) {
        end_[i] = nl.offset(i);
        continue;
      }
      const Vec2 ri = x[i];
      std::size_t out = nl.offset(i);
      // Without a branch on the cut-off (a third of the Verlet row is skin, in no predictable
      // order): every candidate is written at `out`, which moves on only for a pair within the
      // support (out <= s, so a row never overruns its Verlet slots).
      // r^2 waits in w_ for fill_kernel.
      for (std::size_t s = nl.offset(i); s < nl.offset(i + 1); ++s) {
        const std::uint32_t j = index[s];
        const double r2 = norm2(ri - x[j]);
        j_[out] = j;
        w_[out] = r2;
        out += r2 <= reach2 ? 1 : 0;
      }
      end_[i] = out;
      if (cubic_) fill_kernel(cubic_spline_, i, out);
      else fill_kernel(wendland_, i, out);
    }
  }

  void build(const WendlandC2& k, const std::vector<Vec2>& x, const NeighbourList& nl) {
    build(KernelType::wendland_c2, k.h, x, nl);
  }
  void build(const CubicSpline& k, const std::vector<Vec2>& x, const NeighbourList& nl) {
    build(KernelType::cubic_spline, k.h, x, nl);
  }

  // Calls body(const Pair&) for each pair of row i, in the row's order.
  template <class Body>
  void for_each(std::size_t i, Body&& body) const {
    row(i, body);
  }

  // W(0): a particle's own share of a kernel sum.
  double self_w() const { return self_w_; }
  std::size_t count(std::size_t i) const { return end_[i] - nl_->offset(i); }
  std::size_t rows() const { return end_.size(); }
  std::size_t memory_bytes() const {
    return end_.capacity() * sizeof(std::size_t) + j_.capacity() * sizeof(std::uint32_t) +
           (w_.capacity() + f_.capacity()) * sizeof(double);
  }

 private:
  // W and F of row i's kept pairs, slots [nl.offset(i), end), from the r^2 the filter left in w_:
  // once per build for every stage (a loop without gathers, which the compiler vectorises).
  template <class K>
  void fill_kernel(const K& kernel, std::size_t i, std::size_t end) {
    double* w = w_.data();
    double* f = f_.data();
#pragma omp simd
    for (std::size_t s = nl_->offset(i); s < end; ++s) {
      double ws, fs;
      kernel.w_and_gradient(std::sqrt(w[s]), ws, fs);
      w[s] = ws;
      f[s] = fs;
    }
  }

  template <class Body>
  void row(std::size_t i, Body& body) const {
    const std::vector<Vec2>& x = *x_;
    const Vec2 ri = x[i];
    for (std::size_t s = nl_->offset(i); s < end_[i]; ++s) {
      const std::uint32_t j = j_[s];
      body(Pair{j, ri - x[j], w_[s], f_[s]});
    }
  }

  const std::vector<Vec2>* x_ = nullptr;
  const NeighbourList* nl_ = nullptr;
  bool cubic_ = false;
  WendlandC2 wendland_{1.0};
  CubicSpline cubic_spline_{1.0};
  double self_w_ = 0.0;
  std::vector<std::size_t> end_;  // row i's pairs: slots [nl.offset(i), end_[i])
  std::vector<std::uint32_t> j_;
  std::vector<double> w_, f_;  // W and F of the pair in the same slot
};

}  // namespace sloshsph
