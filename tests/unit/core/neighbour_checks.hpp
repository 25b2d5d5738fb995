#pragma once
// Checks shared by the 2D and 3D neighbour-list tests.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph::testing {

// n points uniformly at random in the square (cube) [0, size)^D.
template <int D>
std::vector<Vec<D>> random_points(std::size_t n, unsigned seed, double size) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, size);
  std::vector<Vec<D>> p(n);
  for (auto& q : p) {
    if constexpr (D == 2) q = {u(rng), u(rng)};
    else q = {u(rng), u(rng), u(rng)};
  }
  return p;
}

// Reference: all pairs closer than the search radius, by brute force. Fluid rows list fluid and
// walls; wall rows list fluid only. The list must equal it exactly, without duplicates. Returns
// the number of pairs, so that a test can check it is not vacuous.
template <int D>
std::size_t expect_list_equals_brute_force(const std::vector<Vec<D>>& pts, std::size_t n_fluid, double support,
                                           double skin) {
  BasicNeighbourList<D> nl(support, skin);
  nl.build(pts, n_fluid);
  const double r2 = (support + skin) * (support + skin);
  std::size_t total = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::set<std::uint32_t> expected;
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (j == i || (i >= n_fluid && j >= n_fluid)) continue;
      if (norm2(pts[i] - pts[j]) < r2) expected.insert(static_cast<std::uint32_t>(j));
    }
    const std::set<std::uint32_t> got(nl.begin(i), nl.end(i));
    EXPECT_EQ(got, expected) << "particle " << i;
    EXPECT_EQ(nl.count(i), expected.size()) << "duplicates in row " << i;
    if (got != expected) break;
    total += expected.size();
  }
  return total;
}

}  // namespace sloshsph::testing
