// The wall-contact step (physics/wall_contact.hpp): a particle that would leave the tank is
// stopped at the wall and put back; particles away from the wall, or leaving it, are untouched.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/physics/wall_contact.hpp"

namespace sloshsph {
namespace {

constexpr double kDp = 0.01;

TankGeometry tank_of(const std::string& shape) {
  TankSpec s;
  s.shape = shape;
  s.length = 1.0;
  s.height = 0.6;
  return make_tank(s, "test");
}

// One fluid particle at `x` with velocity `v` (mass 0.1 kg/m).
Particles one(Vec2 x, Vec2 v) {
  Particles p;
  p.resize(1);
  p.n_fluid = 1;
  p.mass = 0.1;
  p.position[0] = x;
  p.velocity[0] = v;
  return p;
}

WallContact contact(const TankGeometry& tank, Particles& p, double dt = 1e-3) {
  const ContainerDistance distance(tank, 0.5 * kDp, 4 * kDp);
  return keep_fluid_in_tank(p, distance, tank, kDp, 0.5 * kDp, dt);
}

TEST(WallContact, ParticleOnTheLatticeIsUntouched) {
  const TankGeometry tank = tank_of("rectangle");
  Particles p = one({0.3, 0.5 * kDp}, {0.2, -0.1});  // the first fluid row, dp/2 above the floor
  const WallContact c = contact(tank, p);
  EXPECT_EQ(c.corrected, 0u);
  EXPECT_EQ(p.velocity[0].y, -0.1);
  EXPECT_EQ(p.position[0].y, 0.5 * kDp);
}

TEST(WallContact, CloseAndApproachingLosesOnlyItsNormalVelocity) {
  const TankGeometry tank = tank_of("rectangle");
  Particles p = one({0.3, 0.1 * kDp}, {0.2, -0.5});
  const double dt = 1e-3;
  const WallContact c = contact(tank, p, dt);
  EXPECT_EQ(c.corrected, 1u);
  EXPECT_NEAR(p.velocity[0].y, 0.0, 1e-9);
  EXPECT_NEAR(p.velocity[0].x, 0.2, 1e-9);  // free slip
  EXPECT_NEAR(p.position[0].y, 0.1 * kDp, 1e-15);  // inside: not moved
  // The wall took m * 0.5 m/s of downward momentum in one step: an upward force on the fluid.
  EXPECT_NEAR(c.force_on_fluid.y, 0.1 * 0.5 / dt, 1e-6);
  EXPECT_NEAR(c.force_on_fluid.x, 0.0, 1e-6);
}

TEST(WallContact, CloseButLeavingIsUntouched) {
  const TankGeometry tank = tank_of("rectangle");
  Particles p = one({0.3, 0.1 * kDp}, {0.2, 0.5});
  EXPECT_EQ(contact(tank, p).corrected, 0u);
  EXPECT_EQ(p.velocity[0].y, 0.5);
}

TEST(WallContact, ParticleThroughTheEndWallIsPutBackInside) {
  const TankGeometry tank = tank_of("rectangle");
  Particles p = one({1.0 + 0.3 * kDp, 0.3}, {0.4, 0.1});  // beyond the right wall, moving out
  const WallContact c = contact(tank, p);
  EXPECT_EQ(c.corrected, 1u);
  EXPECT_NEAR(p.position[0].x, 1.0 - 0.125 * kDp, 1e-9);  // dp/8 inside
  EXPECT_NEAR(p.position[0].y, 0.3, 1e-12);
  EXPECT_NEAR(p.velocity[0].x, 0.0, 1e-9);
  EXPECT_NEAR(p.velocity[0].y, 0.1, 1e-9);
  EXPECT_GT(tank.signed_distance(p.position[0]), 0.0);
}

TEST(WallContact, CurvedWallUsesItsLocalNormal) {
  const TankGeometry tank = tank_of("circular");  // centre (0.5, 0.5), radius 0.5
  const Vec2 centre{0.5, 0.5};
  const Vec2 out = normalized(Vec2{-1.0, -1.0});   // towards the lower left of the circle
  Particles p = one(centre + (0.5 + 0.2 * kDp) * out, 0.3 * out + 0.1 * perp(out));
  EXPECT_EQ(contact(tank, p).corrected, 1u);
  EXPECT_NEAR(norm(p.position[0] - centre), 0.5 - 0.125 * kDp, 1e-6);
  EXPECT_NEAR(dot(p.velocity[0], out), 0.0, 1e-6);             // the outward part is gone
  EXPECT_NEAR(dot(p.velocity[0], perp(out)), 0.1, 1e-6);       // the tangential part is kept
}

TEST(WallContact, FarFromTheWallsNothingHappens) {
  const TankGeometry tank = tank_of("rectangle");
  Particles p = one({0.5, 0.2}, {3.0, -3.0});
  EXPECT_EQ(contact(tank, p).corrected, 0u);
  EXPECT_EQ(p.velocity[0].x, 3.0);
}

// A particle whose position is already NaN is left to the driver's non-finite check (exit 3
// naming it): it is not a contact and adds no force.
TEST(WallContact, NonFinitePositionIsNotAContact) {
  const TankGeometry tank = tank_of("rectangle");
  Particles p = one({std::nan(""), std::nan("")}, {0.0, -1.0});
  const WallContact c = contact(tank, p);
  EXPECT_EQ(c.corrected, 0u);
  EXPECT_EQ(c.force_on_fluid.x, 0.0);
  EXPECT_EQ(c.force_on_fluid.y, 0.0);
}

}  // namespace
}  // namespace sloshsph
