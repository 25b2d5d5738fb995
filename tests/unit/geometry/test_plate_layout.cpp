// Elastic plate geometry (geometry/plates): the wall particles tiling the plate, their normals and
// the face lengths that carry the fluid load.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/plates.hpp"

namespace sloshsph {
namespace {

KeyLocation at(const std::string& where) {
  return [where](const std::string&) { return where; };
}

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

// Sums of the face lengths by face normal.
struct FaceSums {
  double left = 0.0, right = 0.0, up = 0.0, down = 0.0;
  int interior = 0, corners = 0;
};

FaceSums sum_faces(const PlateLayout& l) {
  FaceSums f;
  for (std::size_t k = 0; k < l.walls.size(); ++k) {
    for (const PlateFace& face : {l.side_face[k], l.end_face[k]}) {
      if (face.length <= 0.0) continue;
      const Vec2 n = face.normal;
      (n.x < -0.5 ? f.left : n.x > 0.5 ? f.right : n.y > 0.5 ? f.up : f.down) += face.length;
    }
    if (l.side_face[k].length == 0.0 && l.end_face[k].length == 0.0) ++f.interior;
    if (l.side_face[k].length > 0.0 && l.end_face[k].length > 0.0) ++f.corners;
  }
  return f;
}

TEST(PlateLayout, StandingPlateTilesItsRectangleAndCoversEachFaceOnce) {
  const double dp = 0.0015, t = 0.003, h = 0.08;
  const PlateLayout l = plate_layout(standing_plate(0.15, h, t), dp, 2.66 * dp, box(0.3, 0.2), at("test"), "plates.0");
  EXPECT_DOUBLE_EQ(l.spec.from.y, 0.0);
  EXPECT_DOUBLE_EQ(l.spec.to.y, h);
  EXPECT_EQ(l.along, 53);  // round(0.08 / 0.0015)
  EXPECT_EQ(l.across, 2);
  ASSERT_EQ(l.walls.size(), 106u);
  for (std::size_t k = 0; k < l.walls.size(); ++k) {
    const Vec2 r = l.walls[k].position;
    EXPECT_NEAR(std::abs(r.x - 0.15), 0.75e-3, 1e-12);  // the two layers at +-t/4
    EXPECT_GT(r.y, 0.0);
    EXPECT_LT(r.y, h);
    EXPECT_NEAR(norm(l.walls[k].normal), 1.0, 1e-12);
    if (l.side_face[k].length > 0.0) {
      EXPECT_NEAR(l.side_face[k].distance, 0.75e-3, 1e-12);
    }
  }
  const FaceSums f = sum_faces(l);
  EXPECT_NEAR(f.left, h, 1e-12);  // each long face is covered exactly once
  EXPECT_NEAR(f.right, h, 1e-12);
  EXPECT_NEAR(f.up, t, 1e-12);     // the free tip, by its two corner particles
  EXPECT_EQ(f.down, 0.0);          // the clamped root sits on the floor: no face
  EXPECT_EQ(f.corners, 2);
  EXPECT_EQ(f.interior, 0);
  // A corner's wall normal is the diagonal: fluid above the tip and beside it both face it.
  const Vec2 corner = l.walls.back().normal;
  EXPECT_NEAR(std::abs(corner.x), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(corner.y, std::sqrt(0.5), 1e-12);
}

TEST(PlateLayout, ThickPlateHasInteriorParticlesWithoutFace) {
  const PlateLayout l = plate_layout(standing_plate(0.5, 0.2, 0.05), 0.01, 2.66 * 0.01, box(1.0, 0.5), at("test"), "plates.0");
  EXPECT_EQ(l.across, 5);
  const FaceSums f = sum_faces(l);
  EXPECT_NEAR(f.left + f.right, 2 * 0.2, 1e-12);
  EXPECT_NEAR(f.up, 0.05, 1e-12);
  EXPECT_EQ(f.interior, 3 * (20 - 1));  // 3 inner columns, all rows but the tip row
}

TEST(PlateLayout, RejectsAPlateTheKernelReachesAcross) {
  // Dincer's 3 mm plate with h = 1.33 dp: at dp = 3 mm (one layer) and at dp = 2 mm (t + dp = 5 mm
  // < 2h = 5.32 mm) the fluid of the two sides would interact through it; at dp = 1.5 mm it does not.
  for (double dp : {0.003, 0.002}) {
    try {
      plate_layout(standing_plate(0.15, 0.08, 0.003), dp, 2.66 * dp, box(0.3, 0.2), at("case.toml:9"), "plates.0");
      FAIL() << "a plate too thin for the kernel was accepted at dp = " << dp;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "plates.0.thickness");
      EXPECT_NE(std::string(e.what()).find("kernel support"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(plate_layout(standing_plate(0.15, 0.08, 0.003), 0.0015, 2.66 * 0.0015, box(0.3, 0.2), at("t"), "p"));
}

TEST(PlateLayout, ClampedClampedFloorHasNoEndFaces) {
  PlateSpec p;
  p.name = "floor";
  p.from = {0.0, 0.21};
  p.to = {2.0, 0.21};
  p.thickness = 0.06;
  p.to_support = PlateSupport::clamped;
  const PlateLayout l = plate_layout(p, 0.02, 2.66 * 0.02, box(2.0, 1.6), at("test"), "plates.0");
  for (const WallSample& w : l.walls) EXPECT_LT(std::abs(w.normal.x), 1e-12);
  const FaceSums f = sum_faces(l);
  EXPECT_NEAR(f.up, 2.0, 1e-12);
  EXPECT_NEAR(f.down, 2.0, 1e-12);
  EXPECT_EQ(f.left + f.right, 0.0);
  EXPECT_EQ(f.interior, 100);  // the middle layer
}

TEST(PlateLayout, RejectsPlatesOutsideTheTankOrTooThinForDp) {
  const TankGeometry tank = box(0.3, 0.2);
  PlateSpec outside = standing_plate(0.35, 0.08, 0.003);
  EXPECT_THROW(plate_layout(outside, 0.0015, 2.66 * 0.0015, tank, at("case.toml:3"), "plates.0"), InputError);
  PlateSpec too_tall = standing_plate(0.15, 0.25, 0.003);
  try {
    plate_layout(too_tall, 0.0015, 2.66 * 0.0015, tank, at("case.toml:3"), "plates.0");
    FAIL() << "a plate above the walls was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plates.0.height"), std::string::npos) << e.what();
  }
  EXPECT_THROW(plate_layout(standing_plate(0.15, 0.08, 0.0005), 0.0015, 2.66 * 0.0015, tank, at("t"), "plates.0"), InputError);
  EXPECT_THROW(plate_layout(standing_plate(0.15, 0.002, 0.003), 0.0015, 2.66 * 0.0015, tank, at("t"), "plates.0"), InputError);
}

}  // namespace
}  // namespace sloshsph
