#pragma once
// The pair layer: every interaction between two particles in a scheme goes through a PairList.
//
// A PairList is the Verlet neighbour list (sph/neighbours.hpp) filtered to the kernel's support
// at one set of positions, with the kernel value W(r_ij) and the gradient factor F(r_ij)
// (grad_i W_ij = F r_ij) kept per pair. It is built once per set of positions a step uses
// (ISPH: r(t), then r*), by one pass that does the only square root and kernel evaluation of
// each pair; every stage then reads the same pairs. So the cut-off lives here alone, the skin's
// pairs cost nothing after the build, and the stages state only their physics.
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
  Vec2 grad() const { return rij * f; }
};

class PairList {
 public:
  // The pairs of every row of `nl` with r_ij^2 within kernel_reach2 at positions `x` (the same
  // particles, fluid then walls, as the list was built for).
  template <class K>
  void build(const K& kernel, const std::vector<Vec2>& x, const NeighbourList& nl) {
    const std::size_t n = nl.rows();
    assert(x.size() == n && "one position per row");
    x_ = &x;
    nl_ = &nl;
    self_w_ = kernel.w(0.0);
    end_.resize(n);
    j_.resize(nl.total_pairs());
    w_.resize(nl.total_pairs());
    f_.resize(nl.total_pairs());
    const double reach2 = kernel_reach2(kernel);
    const std::uint32_t* index = nl.begin(0);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 ri = x[i];
      std::size_t out = nl.offset(i);
      // Without a branch on the cut-off (a third of the Verlet row is skin, in no predictable
      // order): every candidate is evaluated and written at `out`, which moves on only for a
      // pair within the support (slot out <= s, so a row never overruns its Verlet slots).
      for (std::size_t s = nl.offset(i); s < nl.offset(i + 1); ++s) {
        const std::uint32_t j = index[s];
        const double r2 = norm2(ri - x[j]);
        j_[out] = j;
        kernel.w_and_gradient(std::sqrt(r2), w_[out], f_[out]);
        out += r2 <= reach2 ? 1 : 0;
      }
      end_[i] = out;
    }
  }

  // Calls body(const Pair&) for each pair of row i, in the row's order.
  template <class Body>
  void for_each(std::size_t i, Body&& body) const {
    const std::vector<Vec2>& x = *x_;
    const Vec2 ri = x[i];
    for (std::size_t s = nl_->offset(i); s < end_[i]; ++s) {
      const std::uint32_t j = j_[s];
      body(Pair{j, ri - x[j], w_[s], f_[s]});
    }
  }

  // W(0): a particle's own share of a kernel sum.
  double self_w() const { return self_w_; }
  std::size_t count(std::size_t i) const { return end_[i] - nl_->offset(i); }
  std::size_t rows() const { return end_.size(); }
  bool built_on(const std::vector<Vec2>& x) const { return x_ == &x && end_.size() == x.size(); }
  std::size_t memory_bytes() const {
    return end_.capacity() * sizeof(std::size_t) + j_.capacity() * sizeof(std::uint32_t) +
           (w_.capacity() + f_.capacity()) * sizeof(double);
  }

 private:
  const std::vector<Vec2>* x_ = nullptr;
  const NeighbourList* nl_ = nullptr;
  double self_w_ = 0.0;
  std::vector<std::size_t> end_;  // row i's pairs: slots [nl.offset(i), end_[i])
  std::vector<std::uint32_t> j_;
  std::vector<double> w_, f_;
};

}  // namespace sloshsph
