// Where build_scene puts the pressure probes (scene.cpp, pressure_sensors): a point stays a point,
// `to` gives a face, `size` a face of that length centred on the probe along the nearest wall.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/scene.hpp"

namespace sloshsph {
namespace {

CaseSpec tank_with(const std::string& shape, PressureProbeSpec probe) {
  CaseSpec spec;
  spec.source = "<test>";
  spec.name = "pressure_sensors";
  spec.tank.shape = shape;
  spec.tank.length = 0.5;
  spec.tank.height = 0.4;
  spec.tank.angle = 45.0;
  spec.fill.depth = 0.2;
  spec.particles.dp = 0.02;
  spec.pressure_probes.push_back(probe);
  return spec;
}

// A point probe named "p" at `position` (m); a test adds `face_end` or `size` where it needs them.
PressureProbeSpec probe_at(Vec2 position) {
  PressureProbeSpec probe;
  probe.name = "p";
  probe.position = position;
  return probe;
}

PressureSensor sensor_of(const std::string& shape, PressureProbeSpec probe) {
  return build_scene(tank_with(shape, probe)).pressure_sensors.at(0);
}

TEST(PressureSensors, PointProbeIsUnchanged) {
  const PressureSensor s = sensor_of("rectangle", probe_at({0.5, 0.1}));
  EXPECT_FALSE(s.face);
  EXPECT_DOUBLE_EQ(s.from.x, 0.5);
  EXPECT_DOUBLE_EQ(s.from.y, 0.1);
  EXPECT_DOUBLE_EQ(s.to.x, 0.5);
  EXPECT_DOUBLE_EQ(s.to.y, 0.1);
}

TEST(PressureSensors, ToGivesTheFaceAsWritten) {
  PressureProbeSpec probe = probe_at({0.5, 0.05});
  probe.face_end = Vec2{0.5, 0.15};
  const PressureSensor s = sensor_of("rectangle", probe);
  EXPECT_TRUE(s.face);
  EXPECT_DOUBLE_EQ(s.to.y, 0.15);
}

// On the right wall of a rectangle the face is vertical, centred on the probe.
TEST(PressureSensors, SizeOnAVerticalWallIsVerticalAndCentred) {
  PressureProbeSpec probe = probe_at({0.5, 0.16});
  probe.size = 0.009;
  const PressureSensor s = sensor_of("rectangle", probe);
  EXPECT_TRUE(s.face);
  EXPECT_NEAR(s.from.x, 0.5, 1e-12);
  EXPECT_NEAR(s.to.x, 0.5, 1e-12);
  EXPECT_NEAR(std::min(s.from.y, s.to.y), 0.1555, 1e-12);
  EXPECT_NEAR(std::max(s.from.y, s.to.y), 0.1645, 1e-12);
}

// On the floor the face is horizontal; a probe dp/2 in front of the wall keeps that offset.
TEST(PressureSensors, SizeOnTheFloorIsHorizontalThroughTheProbe) {
  PressureProbeSpec probe = probe_at({0.25, 0.01});
  probe.size = 0.04;
  const PressureSensor s = sensor_of("rectangle", probe);
  EXPECT_NEAR(s.from.y, 0.01, 1e-12);
  EXPECT_NEAR(s.to.y, 0.01, 1e-12);
  EXPECT_NEAR(std::fabs(s.to.x - s.from.x), 0.04, 1e-12);
  EXPECT_NEAR(0.5 * (s.from.x + s.to.x), 0.25, 1e-12);
}

// On a 45-degree slope the face follows the slope.
TEST(PressureSensors, SizeOnASlopeFollowsIt) {
  // A V-shaped section (sloped, no flat part): the left slope runs from (0, 0.25) to (0.25, 0).
  PressureProbeSpec probe = probe_at({0.1, 0.15});
  probe.size = 0.02;
  const PressureSensor s = sensor_of("triangle", probe);
  const Vec2 d = s.to - s.from;
  EXPECT_NEAR(norm(d), 0.02, 1e-12);
  EXPECT_NEAR(std::fabs(d.x), std::fabs(d.y), 1e-9);
  EXPECT_LT(d.x * d.y, 0.0);  // down to the right
}

TEST(PressureSensors, SizeAwayFromAWallIsRefused) {
  PressureProbeSpec probe = probe_at({0.25, 0.1});
  probe.size = 0.01;
  try {
    build_scene(tank_with("rectangle", probe));
    FAIL() << "a sensor face in mid-tank was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "probes.pressure.0.size") << e.what();
  }
}

TEST(PressureSensors, SizeRunningPastTheCornerIsRefused) {
  PressureProbeSpec probe = probe_at({0.5, 0.02});
  probe.size = 0.2;  // from y = -0.08: beyond the floor
  try {
    build_scene(tank_with("rectangle", probe));
    FAIL() << "a face through the floor was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "probes.pressure.0.size") << e.what();
  }
}

}  // namespace
}  // namespace sloshsph
