// The cell-list Verlet neighbour list against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {
namespace {

std::vector<Vec2> random_points(std::size_t n, unsigned seed, double size) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, size);
  std::vector<Vec2> p(n);
  for (auto& q : p) q = {u(rng), u(rng)};
  return p;
}

TEST(Neighbours, EqualsBruteForceOnRandomPoints) {
  // Reference: all pairs closer than the search radius, by brute force. Fluid rows list
  // fluid and walls; wall rows list fluid only. Must be exactly equal.
  const auto pts = random_points(1500, 7, 1.0);
  const std::size_t n_fluid = 1000;
  NeighbourList nl(0.04, 0.01);
  nl.build(pts, n_fluid);
  const double r2 = 0.05 * 0.05;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::set<std::uint32_t> expected;
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (j == i || (i >= n_fluid && j >= n_fluid)) continue;
      if (norm2(pts[i] - pts[j]) < r2) expected.insert(static_cast<std::uint32_t>(j));
    }
    std::set<std::uint32_t> got(nl.begin(i), nl.end(i));
    ASSERT_EQ(got, expected) << "particle " << i;
    ASSERT_EQ(nl.count(i), expected.size()) << "duplicates in row " << i;
  }
}

TEST(Neighbours, StaleAfterHalfTheSkin) {
  auto pts = random_points(200, 3, 0.3);
  NeighbourList nl(0.04, 0.01);
  nl.build(pts, 200);
  EXPECT_FALSE(nl.stale(pts, 200));
  pts[17].x += 0.0049;
  EXPECT_FALSE(nl.stale(pts, 200));
  pts[17].x += 0.0002;
  EXPECT_TRUE(nl.stale(pts, 200));
  EXPECT_TRUE(nl.stale(pts, 199));  // a particle removed
}

TEST(Neighbours, CellOrderIsAPermutation) {
  const auto pts = random_points(500, 11, 0.5);
  auto order = cell_order(pts, 400, 0.05);
  ASSERT_EQ(order.size(), 400u);
  std::sort(order.begin(), order.end());
  for (std::uint32_t k = 0; k < 400; ++k) EXPECT_EQ(order[k], k);
}

TEST(Neighbours, ClusteredAndSpreadPoints) {
  // Points far apart (a splash) and a dense cluster: the grid must cover both.
  std::vector<Vec2> pts = {{0.0, 0.0}, {0.001, 0.0}, {5.0, 7.0}, {5.0005, 7.0}, {-3.0, 2.0}};
  NeighbourList nl(0.002, 0.0);
  nl.build(pts, pts.size());
  EXPECT_EQ(nl.count(0), 1u);
  EXPECT_EQ(nl.count(2), 1u);
  EXPECT_EQ(nl.count(4), 0u);
}

}  // namespace
}  // namespace sloshsph
