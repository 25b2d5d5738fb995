// Upright cylinders (issue 31, section 2; geometry/cylinder_tank.hpp): the fill is the cubic lattice
// inside r <= R - dp/2 below the level, symmetric about the axis; the walls are outside the fluid
// region with normals towards it; the settled level is the fill's volume over pi R^2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/geometry/cylinder_tank.hpp"

namespace sloshsph {
namespace {

TEST(CylinderTank, FillIsTheLatticeInsideTheWall) {
  const CylinderTank tank{0.15, 0.3};
  const double dp = 0.015, depth = 0.15;
  const std::vector<Vec3> fluid = fill_fluid(tank, dp, depth);
  // Reference: the count of lattice points of one layer inside r <= R - dp/2, times the 10 rows
  // whose centres lie below the level (exact integers).
  int layer = 0;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i)
      if (std::hypot((i + 0.5) * dp - 0.15, (j + 0.5) * dp - 0.15) <= 0.15 - 0.5 * dp + 1e-12) ++layer;
  EXPECT_EQ(fluid.size(), static_cast<std::size_t>(10 * layer));
  Vec3 sum{};
  for (const Vec3& q : fluid) {
    EXPECT_GE(tank.signed_distance(q), 0.5 * dp - 1e-12);
    EXPECT_LT(q.z, depth);
    sum += q;
  }
  // Symmetric about the axis (dp divides 2R): the centroid on it, to round-off.
  EXPECT_NEAR(sum.x / fluid.size(), 0.15, 1e-12);
  EXPECT_NEAR(sum.y / fluid.size(), 0.15, 1e-12);
  // The settled level: the particles' volume over pi R^2, below the nominal depth by the ring of
  // gaps along the wall (here 12%).
  const double level = cylinder_settled_level(tank, fluid.size(), dp);
  EXPECT_NEAR(level, fluid.size() * dp * dp * dp / (std::numbers::pi * 0.15 * 0.15), 1e-15);
  EXPECT_LT(level, depth);
  EXPECT_GT(level, 0.85 * depth);
}

TEST(CylinderTank, WallsSurroundTheFluidWithInwardNormals) {
  const CylinderTank tank{0.15, 0.3};
  const double dp = 0.015;
  const int layers = 2;
  const std::vector<WallSample3> walls = sample_walls(tank, dp, layers);
  std::size_t side = 0, bottom = 0;
  for (const WallSample3& w : walls) {
    EXPECT_LT(tank.signed_distance(w.position), 0.0);
    EXPECT_NEAR(norm(w.normal), 1.0, 1e-12);
    if (w.normal.z == 1.0) {
      ++bottom;
      EXPECT_LT(tank.from_axis(w.position), tank.radius);
      EXPECT_GT(w.position.z, -layers * dp);
    } else {
      ++side;
      // The side's normal points at the axis, and its layer stands (k + 1/2) dp outside the wall.
      const Vec3 to_axis{tank.radius - w.position.x, tank.radius - w.position.y, 0.0};
      EXPECT_NEAR(dot(w.normal, to_axis), norm(to_axis), 1e-9);
      const double layer = (tank.from_axis(w.position) - tank.radius) / dp - 0.5;
      EXPECT_NEAR(layer, std::round(layer), 1e-9);
    }
  }
  // The side's rings: round(2 pi (R + (k + 1/2) dp) / dp) around, on 20 levels from -2 dp to the top.
  const std::size_t around = std::lround(2.0 * std::numbers::pi * (0.15 + 0.5 * dp) / dp) +
                             std::lround(2.0 * std::numbers::pi * (0.15 + 1.5 * dp) / dp);
  EXPECT_EQ(side, around * (20 + 2));
  EXPECT_GT(bottom, 0u);
}

TEST(CylinderTank, FirstModeOfLinearTheory) {
  // omega^2 = g k tanh(k h), k = 1.8412 / R: R = 0.15 m, h = 0.15 m, g = 9.81 gives 10.7006 rad/s.
  EXPECT_NEAR(cylinder_first_sloshing_omega(0.15, 0.15, 9.81), 10.7006, 1e-4);
}

}  // namespace
}  // namespace sloshsph
