// The cell-list Verlet neighbour list against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/sph/neighbours.hpp"
#include "neighbour_checks.hpp"

namespace sloshsph {
namespace {

std::vector<Vec2> random_points(std::size_t n, unsigned seed, double size) {
  return testing::random_points<2>(n, seed, size);
}

TEST(Neighbours, EqualsBruteForceOnRandomPoints) {
  // Reference: all pairs closer than the search radius, by brute force (neighbour_checks.hpp).
  const std::size_t total = testing::expect_list_equals_brute_force(random_points(1500, 7, 1.0), 1000, 0.04, 0.01);
  EXPECT_GT(total, 1000u);  // 1500 points in 1 m^2: about 11 neighbours each within 0.05 m
}

// A point that is not finite, or points flung so far apart that the grid would need more than 2e8
// cells, are a RunFailure that says so, not an out-of-bounds cell or a std::length_error (found:
// the sample of a failed step's state, 2026-12-07).
TEST(Neighbours, CellGridRefusesNonFiniteAndFarFlungPoints) {
  CellGrid grid;
  std::vector<Vec2> points = {{0.0, 0.0}, {0.1, 0.0}, {std::nan(""), 0.0}};
  EXPECT_THROW(grid.build(points, 0, points.size(), 0.1), RunFailure);
  points[2] = {2.0e11, -6.6e11};
  EXPECT_THROW(grid.build(points, 0, points.size(), 0.1), RunFailure);
  points[2] = {100.0, 50.0};  // 1e6 cells: built
  EXPECT_NO_THROW(grid.build(points, 0, points.size(), 0.1));
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
