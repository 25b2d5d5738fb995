// Repulsive walls in 3D (issue 31): Shao's repulsive wall particles (WCSPH, scheme.walls =
// "repulsive") and the repulsive force of thesis eq. 3.18 (ISPH, scheme.repulsive_walls) act from
// the first layer of wall particles of every wall of a box (the two side walls, the two end walls
// across the breadth and the floor) and of an upright cylinder (side and bottom).
//
// Reference: the wall layers stand at (k + 1/2) dp outside the wall surfaces (geometry/
// prism_tank.hpp, cylinder_tank.hpp), so the first layer is the set of wall particles less than dp
// outside the tank. Here "outside" is written independently of the schemes' tank distance: for the
// box the largest overshoot max(-x, x - L, -y, y - B, -z), for the cylinder max(r - R, -z). The
// marked sets must be exactly these (no tolerance: a set), and the ISPH strength that of eq. 3.18,
// coefficient g max(H - z, h), to round-off. Before issue 31's change neither scheme marked
// anything in 3D (the case reader refused both options there).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>

#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/schemes/isph.hpp"
#include "sloshsph/schemes/wcsph.hpp"

namespace sloshsph {
namespace {

constexpr double kDp = 0.02, kDepth = 0.14, kGravity = 9.81;

std::string tank_case(const std::string& tank, const std::string& scheme) {
  return "[tank]\ndimensions = 3\n" + tank + "height = 0.3\n[fill]\ndepth = 0.14\n[particles]\ndp = 0.02\n"
         "[time]\nend = 0.1\ndt = 0.001\n[scheme]\n" + scheme;
}
const std::string kBox = "shape = \"rectangle\"\nlength = 0.4\nbreadth = 0.2\n";
const std::string kCylinder = "shape = \"cylinder\"\nradius = 0.15\n";

// How far outside the tank a wall particle stands (the largest overshoot), for each tank above.
double box_overshoot(Vec3 p) { return std::max({-p.x, p.x - 0.4, -p.y, p.y - 0.2, -p.z}); }
double cylinder_overshoot(Vec3 p) { return std::max(std::hypot(p.x - 0.15, p.y - 0.15) - 0.15, -p.z); }

BasicFrameForce<3> gravity() {
  BasicFrameForce<3> f;
  f.uniform = {0.0, 0.0, -kGravity};
  return f;
}

// The wall particles of `scene` in the first layer, by the overshoot.
std::vector<bool> first_layer(const Scene3& scene, const std::function<double(Vec3)>& overshoot) {
  const Particles3& p = scene.particles;
  std::vector<bool> in(p.n_wall(), false);
  for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
    const double d = overshoot(p.position[w]);
    in[w - p.n_fluid] = d > 0.0 && d < kDp;
  }
  return in;
}

void expect_wcsph_marks_the_first_layer(const std::string& tank, const std::function<double(Vec3)>& overshoot) {
  const CaseSpec spec = read_case_text(tank_case(tank, "type = \"wcsph\"\nwalls = \"repulsive\"\n"), "t.toml", {});
  Scene3 scene = build_scene3(spec);
  WcsphScheme3 scheme(spec, scene.h);
  scheme.initialise(scene.particles, gravity());
  const std::vector<bool> expected = first_layer(scene, overshoot);
  const std::vector<std::uint8_t>& marked = scheme.repulsive_layer();
  ASSERT_EQ(marked.size(), expected.size());
  std::size_t count = 0, wrong = 0;
  for (std::size_t k = 0; k < marked.size(); ++k) {
    count += expected[k] ? 1 : 0;
    wrong += (marked[k] != 0) != expected[k] ? 1 : 0;
  }
  std::printf("  measured: %zu of %zu wall particles in the first layer, %zu marked otherwise\n", count,
              marked.size(), wrong);
  EXPECT_GT(count, 0u);
  EXPECT_EQ(wrong, 0u);
}

void expect_isph_strength_on_the_first_layer(const std::string& tank, const std::function<double(Vec3)>& overshoot) {
  const CaseSpec spec = read_case_text(tank_case(tank, "repulsive_walls = true\n"), "t.toml", {});
  Scene3 scene = build_scene3(spec);
  IsphScheme3 scheme(spec, scene.h);
  IsphScheme3::Input in;
  in.dt = 1.0e-4;
  in.frame = gravity();
  scheme.initialise(scene.particles, in.frame);
  scheme.step(scene.particles, in);  // the layer is marked at the first step
  const std::vector<bool> expected = first_layer(scene, overshoot);
  const std::vector<double>& strength = scheme.repulsion_strength();
  ASSERT_EQ(strength.size(), expected.size());
  const Particles3& p = scene.particles;
  std::size_t wrong = 0;
  double worst = 0.0;
  for (std::size_t k = 0; k < strength.size(); ++k) {
    const double z = p.position[p.n_fluid + k].z;
    const double eq_3_18 = expected[k] ? kGravity * std::max(kDepth - z, scene.h) : 0.0;  // coefficient 1
    wrong += (strength[k] > 0.0) != expected[k] ? 1 : 0;
    worst = std::max(worst, std::abs(strength[k] - eq_3_18));
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_LT(worst, 1e-12);
}

TEST(RepulsiveWallsThreeD, ShaoLayerIsTheFirstLayerOfEveryWallOfABox) {
  expect_wcsph_marks_the_first_layer(kBox, box_overshoot);
}

TEST(RepulsiveWallsThreeD, ShaoLayerIsTheFirstLayerOfTheCylindersSideAndBottom) {
  expect_wcsph_marks_the_first_layer(kCylinder, cylinder_overshoot);
}

TEST(RepulsiveWallsThreeD, ThesisForceActsFromTheFirstLayerOfABox) {
  expect_isph_strength_on_the_first_layer(kBox, box_overshoot);
}

TEST(RepulsiveWallsThreeD, ThesisForceActsFromTheFirstLayerOfTheCylinder) {
  expect_isph_strength_on_the_first_layer(kCylinder, cylinder_overshoot);
}

}  // namespace
}  // namespace sloshsph
