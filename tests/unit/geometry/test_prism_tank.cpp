// 3D tanks extruded from a section (geometry/prism_tank.hpp; issue 31, section 2): the fill, the
// wall layers, and that the walls complete every fluid particle's kernel in a box (edges and
// corners included).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sloshsph/geometry/prism_tank.hpp"
#include "sloshsph/sph/kernel.hpp"

namespace sloshsph {
namespace {

PrismTank box(double length, double breadth, double height) {
  TankSpec s;
  s.shape = "rectangle";
  s.length = length;
  s.height = height;
  return {make_tank(s, "test"), breadth};
}

TEST(PrismTank, BoxFillIsTheLatticeBelowTheLevel) {
  // 0.6 x 0.3 x 0.4 m, dp = 20 mm, 0.2 m of water: 30 x 15 x 10 particles, each at least dp/2
  // inside every wall and below the level.
  const double dp = 0.02;
  const PrismTank tank = box(0.6, 0.3, 0.4);
  const std::vector<Vec3> fluid = fill_fluid(tank, dp, 0.2);
  EXPECT_EQ(fluid.size(), 30u * 15u * 10u);
  for (const Vec3& p : fluid) {
    EXPECT_GE(tank.signed_distance(p), 0.5 * dp - 1e-12);
    EXPECT_LT(p.z, 0.2);
  }
}

TEST(PrismTank, BoxWallsAreTheLatticeShellAroundTheFluid) {
  // Reference: with dp dividing every size, the walls are the lattice points of the box grown by
  // `layers` dp at the sides, the ends and the bottom (not the top), less those of the box:
  // (nx + 4)(ny + 4)(nz + 2) - nx ny nz for 2 layers; no two closer than dp (no point twice);
  // all outside, the furthest the second layer's corner points, 1.5 sqrt(2) dp out; unit normals
  // pointing inward.
  const double dp = 0.05;
  const PrismTank tank = box(0.6, 0.3, 0.4);
  const int nx = 12, ny = 6, nz = 8;
  const std::vector<WallSample3> walls = sample_walls(tank, dp, 2);
  EXPECT_EQ(walls.size(), static_cast<std::size_t>((nx + 4) * (ny + 4) * (nz + 2) - nx * ny * nz));
  double closest2 = 1e300;
  for (std::size_t a = 0; a < walls.size(); ++a)
    for (std::size_t b = a + 1; b < walls.size(); ++b)
      closest2 = std::min(closest2, norm2(walls[a].position - walls[b].position));
  EXPECT_NEAR(std::sqrt(closest2), dp, 1e-9);
  for (const WallSample3& w : walls) {
    const double d = tank.signed_distance(w.position);
    EXPECT_LE(d, -0.5 * dp + 1e-12);
    EXPECT_GE(d, -1.5 * std::sqrt(2.0) * dp - 1e-12);  // the section's corners: (1.5 dp, 1.5 dp) out
    EXPECT_NEAR(norm(w.normal), 1.0, 1e-12);
    // Inward: a step along the normal brings the particle nearer the wall it stands for (a side
    // wall: the section's; an end wall: its plane y = 0 or y = breadth).
    const Vec3 step = w.position + w.normal * (0.5 * dp);
    if (w.normal.y == 0.0)
      EXPECT_GT(tank.section.signed_distance(in_section(step)), tank.section.signed_distance(in_section(w.position)));
    else
      EXPECT_LT(std::abs(step.y - 0.15) , std::abs(w.position.y - 0.15));
  }
}

TEST(PrismTank, BoxWallsCompleteEveryKernel) {
  // Reference: with the walls continuing the lattice, every fluid particle whose kernel does not
  // reach the free surface (centre more than 2h below the top row) has the kernel sum of a full
  // cubic lattice, sum_j V W_ij = 1.0045 at h = 1.4 dp (tests/unit/core/three_d_test.cpp), to
  // round-off (1e-12): the edges and corners are filled. Checked on every fluid particle of a
  // small box, by brute force.
  const double dp = 0.02, h = 1.4 * dp;
  const PrismTank tank = box(0.2, 0.12, 0.2);
  const std::vector<Vec3> fluid = fill_fluid(tank, dp, 0.16);
  const std::vector<WallSample3> walls = sample_walls(tank, dp, 2);
  std::vector<Vec3> all = fluid;
  for (const WallSample3& w : walls) all.push_back(w.position);
  const WendlandC2 k(h, 3);
  double full = 0.0;  // the full lattice's sum, from the lattice itself
  for (int a = -3; a <= 3; ++a)
    for (int b = -3; b <= 3; ++b)
      for (int c = -3; c <= 3; ++c) full += k.w(dp * std::sqrt(double(a * a + b * b + c * c)));
  full *= dp * dp * dp;
  EXPECT_NEAR(full, 1.0045, 1e-4);
  const double top_row = 0.16 - 0.5 * dp;
  int checked = 0;
  for (const Vec3& p : fluid) {
    if (p.z > top_row - 2.0 * h) continue;
    double sum = 0.0;
    for (const Vec3& q : all) sum += k.w(norm(p - q));
    EXPECT_NEAR(sum * dp * dp * dp, full, 1e-12) << p.x << " " << p.y << " " << p.z;
    ++checked;
  }
  // 10 x 6 columns, the rows below 0.16 - 0.01 - 0.056 m: z = 0.01 .. 0.09, 5 rows.
  EXPECT_EQ(checked, 10 * 6 * 5);
}

TEST(PrismTank, SlopedSectionExtruded) {
  // A trapezoid section (0.4 m flat, 45 degree slopes, 0.6 m across the top) over 0.2 m: the fill
  // is the section's 2D fill repeated on the planes y = (k + 1/2) dp; every particle is at least
  // dp/2 inside, every wall particle outside; the end walls face the fluid.
  TankSpec s;
  s.shape = "sloped";
  s.length = 0.6;
  s.height = 0.3;
  s.bottom_width = 0.4;
  s.angle = 45.0;
  const double dp = 0.02;
  const PrismTank tank{make_tank(s, "test"), 0.2};
  const std::vector<Vec3> fluid = fill_fluid(tank, dp, 0.15);
  EXPECT_EQ(fluid.size(), fill_fluid(tank.section, dp, 0.15).size() * 10u);
  for (const Vec3& p : fluid) EXPECT_GE(tank.signed_distance(p), 0.5 * dp - 1e-12);
  int end_walls = 0;
  for (const WallSample3& w : sample_walls(tank, dp, 3)) {
    EXPECT_LT(tank.signed_distance(w.position), 0.0);
    EXPECT_NEAR(norm(w.normal), 1.0, 1e-12);
    if (w.normal.y != 0.0) {
      ++end_walls;
      EXPECT_EQ(w.normal.y > 0.0, w.position.y < 0.0);
    }
  }
  EXPECT_GT(end_walls, 0);
}

}  // namespace
}  // namespace sloshsph
