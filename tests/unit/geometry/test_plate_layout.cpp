// Elastic plate geometry (geometry/plates): the wall particles tiling the plate, their normals and
// the face lengths that carry the fluid load.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/plates.hpp"

namespace sloshsph {
namespace {

TankGeometry box(double length, double height) {
  TankSpec s;
  s.shape = "rectangle";
  s.length = length;
  s.height = height;
  return make_tank(s, "test");
}

PlateSpec standing_plate(double x, double height, double thickness) {
  PlateSpec p;
  p.name = "p";
  p.from = {x, 0.0};
  p.standing_height = height;
  p.thickness = thickness;
  p.youngs_modulus = 1e7;
  p.density = 1000.0;
  return p;
}

TEST(PlateLayout, StandingPlateTilesItsRectangleWithFacesOnBothSidesAndTheFreeTip) {
  const double dp = 0.0015, t = 0.003, h = 0.08;
  const PlateLayout l = plate_layout(standing_plate(0.15, h, t), dp, box(0.3, 0.2), "test", "plates.0");
  EXPECT_DOUBLE_EQ(l.spec.from.y, 0.0);
  EXPECT_DOUBLE_EQ(l.spec.to.y, h);
  EXPECT_EQ(l.along, 53);  // round(0.08 / 0.0015)
  EXPECT_EQ(l.across, 2);
  ASSERT_EQ(l.walls.size(), 106u);
  double left = 0.0, right = 0.0, top = 0.0;
  for (std::size_t k = 0; k < l.walls.size(); ++k) {
    const Vec2 r = l.walls[k].position, n = l.walls[k].normal;
    EXPECT_NEAR(std::abs(r.x - 0.15), 0.75e-3, 1e-12);  // the two layers at +-t/4
    EXPECT_GT(r.y, 0.0);
    EXPECT_LT(r.y, h);
    // Normals point out of the nearest face; a long face wins a tie at the corner.
    if (n.x < -0.5) left += l.face_length[k];
    if (n.x > 0.5) right += l.face_length[k];
    if (n.y > 0.5) top += l.face_length[k];
    EXPECT_NEAR(l.face_distance[k], 0.75e-3, 1e-12);
  }
  EXPECT_NEAR(left, h, 1e-12);  // each long face is covered exactly once
  EXPECT_NEAR(right, h, 1e-12);
  EXPECT_EQ(top, 0.0);  // two layers: the tip row are corners, counted on the long faces
}

TEST(PlateLayout, ThickPlateHasInteriorParticlesWithoutFaceAndAFreeEndFace) {
  PlateSpec p = standing_plate(0.5, 0.2, 0.05);
  const double dp = 0.01;
  const PlateLayout l = plate_layout(p, dp, box(1.0, 0.5), "test", "plates.0");
  EXPECT_EQ(l.across, 5);
  double sides = 0.0, tip = 0.0;
  int interior = 0;
  for (std::size_t k = 0; k < l.walls.size(); ++k) {
    if (l.face_length[k] == 0.0) ++interior;
    if (std::abs(l.walls[k].normal.y) > 0.5) tip += l.face_length[k];
    else sides += l.face_length[k];
  }
  EXPECT_NEAR(sides, 2 * 0.2, 1e-12);
  EXPECT_NEAR(tip, 0.05 - 2 * 0.01, 1e-12);  // the free end less its two corner particles
  EXPECT_EQ(interior, 3 * (20 - 1));          // 3 inner columns, all rows but the tip row
}

TEST(PlateLayout, RejectsAOneLayerPlate) {
  // dp = t: one layer, the fluid of both sides would meet through it.
  try {
    plate_layout(standing_plate(0.15, 0.08, 0.003), 0.003, box(0.3, 0.2), "case.toml:9", "plates.0");
    FAIL() << "a one-layer plate was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "plates.0.thickness");
  }
}

TEST(PlateLayout, ClampedClampedFloorHasNoEndFaces) {
  PlateSpec p;
  p.name = "floor";
  p.from = {0.0, 0.21};
  p.to = {2.0, 0.21};
  p.thickness = 0.06;
  p.to_support = PlateSupport::clamped;
  const PlateLayout l = plate_layout(p, 0.02, box(2.0, 1.6), "test", "plates.0");
  double up = 0.0, down = 0.0;
  for (std::size_t k = 0; k < l.walls.size(); ++k) {
    EXPECT_LT(std::abs(l.walls[k].normal.x), 1e-12);
    (l.walls[k].normal.y > 0 ? up : down) += l.face_length[k];
  }
  EXPECT_NEAR(up, 2.0, 1e-12);
  EXPECT_NEAR(down, 2.0, 1e-12);
}

TEST(PlateLayout, RejectsPlatesOutsideTheTankOrTooThinForDp) {
  const TankGeometry tank = box(0.3, 0.2);
  PlateSpec outside = standing_plate(0.35, 0.08, 0.003);
  EXPECT_THROW(plate_layout(outside, 0.0015, tank, "case.toml:3", "plates.0"), InputError);
  PlateSpec too_tall = standing_plate(0.15, 0.25, 0.003);
  try {
    plate_layout(too_tall, 0.0015, tank, "case.toml:3", "plates.0");
    FAIL() << "a plate above the walls was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plates.0.height"), std::string::npos) << e.what();
  }
  EXPECT_THROW(plate_layout(standing_plate(0.15, 0.08, 0.0005), 0.0015, tank, "t", "plates.0"), InputError);
  EXPECT_THROW(plate_layout(standing_plate(0.15, 0.002, 0.003), 0.0015, tank, "t", "plates.0"), InputError);
}

}  // namespace
}  // namespace sloshsph
