// The pair layer (sph/pairs.hpp): a PairList holds exactly the Verlet pairs within the kernel's
// support, in the Verlet row's order, with W and F of the kernel, and only those take memory.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "sloshsph/sph/kernel.hpp"
#include "sloshsph/sph/neighbours.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {
namespace {

constexpr double kDp = 0.01;
constexpr double kH = 1.4 * kDp;

// A jittered lattice of n x n particles (the first n_fluid fluid, the rest walls), 1,600 by
// default: 25 blocks of the pair list's 64 rows, so that rows of every block are checked.
std::vector<Vec2> jittered_lattice(int n, double jitter, std::uint32_t seed) {
  std::vector<Vec2> x;
  std::uint32_t state = seed;
  auto next = [&] {  // a small LCG: the test needs only a fixed, irregular arrangement
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24) - 0.5;
  };
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) x.push_back({a * kDp + jitter * kDp * next(), b * kDp + jitter * kDp * next()});
  return x;
}

// Row i's pairs as a reference: the Verlet row, in its order, with r^2 within the support.
std::vector<std::uint32_t> expected_row(const NeighbourList& nl, const std::vector<Vec2>& x, std::size_t i,
                                        double reach2) {
  std::vector<std::uint32_t> row;
  for (const std::uint32_t* j = nl.begin(i); j != nl.end(i); ++j)
    if (norm2(x[i] - x[*j]) <= reach2) row.push_back(*j);
  return row;
}

void expect_pairs_match(const PairList& pairs, const NeighbourList& nl, const std::vector<Vec2>& x,
                        std::size_t first_row) {
  const WendlandC2 k(kH);
  const double reach2 = kernel_reach2(k);
  ASSERT_EQ(pairs.rows(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::vector<std::uint32_t> want =
        i < first_row ? std::vector<std::uint32_t>{} : expected_row(nl, x, i, reach2);
    std::vector<std::uint32_t> got;
    pairs.for_each(i, [&](const Pair& q) {
      got.push_back(q.j);
      const Vec2 rij = x[i] - x[q.j];
      EXPECT_EQ(q.rij.x, rij.x);
      EXPECT_EQ(q.rij.y, rij.y);
      double w = 0.0, f = 0.0;
      k.w_and_gradient(std::sqrt(norm2(rij)), w, f);
      EXPECT_EQ(q.w, w) << "row " << i << ", neighbour " << q.j;
      EXPECT_EQ(q.f, f) << "row " << i << ", neighbour " << q.j;
    });
    ASSERT_EQ(got, want) << "row " << i;
    EXPECT_EQ(pairs.count(i), want.size());
  }
}

TEST(PairList, HoldsTheVerletPairsWithinTheSupportInTheirOrder) {
  const std::vector<Vec2> x = jittered_lattice(40, 0.3, 7);
  NeighbourList nl(2.0 * kH, 0.2 * 2.0 * kH);
  nl.build(x, 1200);  // 1,200 fluid, 400 walls
  PairList pairs;
  pairs.build(WendlandC2(kH), x, nl);
  expect_pairs_match(pairs, nl, x, 0);
}

TEST(PairList, RowsBeforeFirstRowAreEmpty) {
  const std::vector<Vec2> x = jittered_lattice(40, 0.3, 11);
  NeighbourList nl(2.0 * kH, 0.2 * 2.0 * kH);
  nl.build(x, 1200);
  PairList pairs;
  pairs.build(KernelType::wendland_c2, kH, x, nl, 1000);
  expect_pairs_match(pairs, nl, x, 1000);
}

// Built again at positions where the rows hold more pairs than at the first build (the particles
// drawn together), the list grows its storage and still holds exactly the pairs within the support.
TEST(PairList, RebuildWithMorePairsPerRow) {
  std::vector<Vec2> x = jittered_lattice(40, 0.0, 3);
  NeighbourList nl(2.0 * kH, 0.2 * 2.0 * kH);
  nl.build(x, x.size());
  PairList pairs;
  pairs.build(WendlandC2(kH), x, nl);
  expect_pairs_match(pairs, nl, x, 0);
  const std::size_t bytes_before = pairs.memory_bytes();
  for (Vec2& r : x) r = r * 0.96;  // within the Verlet skin: the same list, more pairs within the support
  pairs.build(WendlandC2(kH), x, nl);
  expect_pairs_match(pairs, nl, x, 0);
  EXPECT_GT(pairs.memory_bytes(), bytes_before);
}

// Only the pairs within the support take memory: 20 bytes each (neighbour, W, F) and a sixteenth
// more for room to grow, plus 8 bytes a row, against 20 bytes a Verlet slot before (where a third
// of the slots are the skin's). Bound: 20 B x 1.2 a kept pair + 8 B a row + the blocks' headers.
TEST(PairList, MemoryFollowsThePairsWithinTheSupport) {
  const std::vector<Vec2> x = jittered_lattice(40, 0.1, 5);
  NeighbourList nl(2.0 * kH, 0.2 * 2.0 * kH);
  nl.build(x, x.size());
  PairList pairs;
  pairs.build(WendlandC2(kH), x, nl);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < x.size(); ++i) kept += pairs.count(i);
  const double bound = 20.0 * 1.2 * static_cast<double>(kept) + 8.0 * static_cast<double>(x.size()) + 4096.0;
  EXPECT_LE(static_cast<double>(pairs.memory_bytes()), bound);
  EXPECT_LT(static_cast<double>(kept), 0.8 * static_cast<double>(nl.total_pairs()))
      << "the skin should hold a good part of the Verlet slots, or this test shows nothing";
}

}  // namespace
}  // namespace sloshsph
