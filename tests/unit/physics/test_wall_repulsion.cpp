// The repulsive wall force of thesis eq. 3.18 in the form of physics/wall_repulsion.hpp:
// zero beyond its range, repulsive and bounded inside, continuous at the range.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/physics/wall_repulsion.hpp"

namespace sloshsph {
namespace {

constexpr double kStrength = 9.81 * 0.25;  // D = g H for H = 0.25 m, m^2/s^2
constexpr double kRange = 0.7 * 0.005;     // r0 = h/2, h = 1.4 dp, dp = 5 mm

// Zero at and beyond r0 in every direction, and for coincident particles (no direction).
TEST(WallRepulsion, ZeroBeyondRange) {
  for (double r : {kRange, 1.0001 * kRange, 1.5 * kRange, 10.0 * kRange})
    for (double a : {0.0, 0.7, 2.0, 4.0}) {
      const Vec2 f = thesis_wall_repulsion(Vec2{r * std::cos(a), r * std::sin(a)}, kStrength, kRange);
      EXPECT_EQ(f.x, 0.0);
      EXPECT_EQ(f.y, 0.0);
    }
  const Vec2 f0 = thesis_wall_repulsion(Vec2{0.0, 0.0}, kStrength, kRange);
  EXPECT_EQ(norm(f0), 0.0);
}

// Inside r0 the force points from the wall particle to the fluid particle (along +x_iw),
// its magnitude never exceeds 24 D / r0 and reaches it below r0 / 2; magnitude falls
// monotonically from r0/2 to r0 and tends to 0 at r0 (continuity: within 1e-3 of the bound
// at r = (1 - 1e-5) r0).
TEST(WallRepulsion, RepulsiveAndBoundedInside) {
  const double bound = thesis_wall_repulsion_bound(kStrength, kRange);
  double previous = bound;
  for (int k = 1; k < 1000; ++k) {
    const double r = kRange * k / 1000.0;
    const Vec2 x{0.6 * r, 0.8 * r};
    const Vec2 f = thesis_wall_repulsion(x, kStrength, kRange);
    const double m = norm(f);
    EXPECT_GT(dot(f, x), 0.0) << "r = " << r;
    EXPECT_NEAR(dot(f, x), m * r, 1e-9 * m * r) << "not along x_iw at r = " << r;
    EXPECT_LE(m, bound * (1.0 + 1e-12)) << "r = " << r;
    if (r <= 0.5 * kRange) EXPECT_NEAR(m, bound, 1e-9 * bound) << "r = " << r;
    else EXPECT_LE(m, previous * (1.0 + 1e-12)) << "r = " << r;
    previous = m;
  }
  const Vec2 edge = thesis_wall_repulsion(Vec2{0.0, (1.0 - 1e-5) * kRange}, kStrength, kRange);
  EXPECT_LT(norm(edge), 1e-3 * bound);
}

// The Lennard-Jones bracket of eq. 3.18: at r = 0.8 r0, D [(1/0.8)^4 - (1/0.8)^2] / r.
TEST(WallRepulsion, MatchesTheLennardJonesForm) {
  const double r = 0.8 * kRange, q = 1.0 / 0.8;
  const Vec2 f = thesis_wall_repulsion(Vec2{r, 0.0}, kStrength, kRange);
  EXPECT_NEAR(f.x, kStrength * (std::pow(q, 4) - q * q) / r, 1e-9 * f.x);
  EXPECT_EQ(f.y, 0.0);
}

}  // namespace
}  // namespace sloshsph
