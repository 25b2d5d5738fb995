// Screen particle sampling (physics/porous make_screen_particles) and clipping to the tank
// section (geometry/screens clip_to_section).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/screens.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/physics/porous.hpp"

namespace sloshsph {
namespace {

TankGeometry rectangle(double length, double height) {
  TankSpec s;
  s.shape = "rectangle";
  s.length = length;
  s.height = height;
  return make_tank(s, "test");
}

ScreenSpec vertical_screen(double x, double y0, double y1, double solidity = 5.0 / 12.0) {
  ScreenSpec s;
  s.name = "screen";
  s.from = {x, y0};
  s.to = {x, y1};
  s.solidity = solidity;
  s.thickness = 0.001;
  return s;
}

// The key of the InputError thrown by f(), or "" if none.
template <class F>
std::string error_key(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "case.toml");
    return e.key();
  }
  return "";
}

// A vertical screen over the full height 0.6 m of a 1 m tank, dp_sc = dp = 0.01 m: 60 particles,
// spacing 0.01 m, the end ones 0.005 m from the floor and the top (exact arithmetic, 1e-12).
// Defaults: h_sc = 2.5 h (thesis 2.5.3), D_c = dp_sc, K from eq. 2.22, n_w = 1 - S.
TEST(ScreenParticles, CountSpacingAndEnds) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  const double dp = 0.01, h = 1.4 * dp;
  const ScreenParticles sp = make_screen_particles({vertical_screen(0.4, 0.0, 0.6)}, dp, h, tank, "case.toml");
  ASSERT_EQ(sp.size(), 60u);
  ASSERT_EQ(sp.elements.size(), 1u);
  const ScreenElement& e = sp.elements[0];
  EXPECT_EQ(e.count, 60u);
  EXPECT_NEAR(e.spacing, 0.01, 1e-12);
  EXPECT_NEAR(e.length, 0.6, 1e-12);
  EXPECT_NEAR(e.smoothing_length, 2.5 * h, 1e-15);
  EXPECT_NEAR(e.porosity, 7.0 / 12.0, 1e-15);
  EXPECT_NEAR(e.permeability, kozeny_carman_permeability(7.0 / 12.0, 0.01), 1e-20);
  // The undisturbed kernel sum of a fluid lattice is 1 up to the lattice error (< 1e-3 for h_sc = 3.5 dp).
  EXPECT_NEAR(e.undisturbed_weight, 1.0, 1e-3);
  EXPECT_NEAR(sp.position.front().y, 0.005, 1e-12);
  EXPECT_NEAR(sp.position.back().y, 0.595, 1e-12);
  for (std::size_t k = 0; k < sp.size(); ++k) {
    EXPECT_NEAR(sp.position[k].x, 0.4, 1e-12);
    EXPECT_EQ(sp.element[k], 0u);
    if (k > 0) {
      EXPECT_NEAR(sp.position[k].y - sp.position[k - 1].y, 0.01, 1e-12);
    }
  }
  // The unit normal is perpendicular to the centre line.
  EXPECT_NEAR(std::abs(e.normal.x), 1.0, 1e-12);
  EXPECT_NEAR(e.normal.y, 0.0, 1e-12);
}

// A length that is not a whole number of dp_sc: n = ceil(L / dp_sc) particles at spacing L / n <= dp_sc,
// half a spacing from each end. L = 0.6, dp_sc = 0.007: n = 86, spacing 0.0069767.
TEST(ScreenParticles, EqualSpacingNotAboveDpSc) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  ScreenSpec s = vertical_screen(0.4, 0.0, 0.6);
  s.spacing = 0.007;
  const ScreenParticles sp = make_screen_particles({s}, 0.01, 0.014, tank, "case.toml");
  ASSERT_EQ(sp.size(), 86u);
  const double ds = 0.6 / 86.0;
  EXPECT_NEAR(sp.elements[0].spacing, ds, 1e-12);
  EXPECT_LE(sp.elements[0].spacing, 0.007);
  EXPECT_NEAR(sp.elements[0].nominal_spacing, 0.007, 0.0);
  EXPECT_NEAR(sp.position.front().y, 0.5 * ds, 1e-12);
  EXPECT_NEAR(0.6 - sp.position.back().y, 0.5 * ds, 1e-12);
}

// An element drawn through the floor and above the top of the walls is cut at both (to 1e-9 m,
// the bisection tolerance is far below): the same 60 particles as the exact one.
TEST(ScreenParticles, ClippedToFloorAndTop) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  const ScreenParticles exact = make_screen_particles({vertical_screen(0.4, 0.0, 0.6)}, 0.01, 0.014, tank, "case.toml");
  const ScreenParticles cut = make_screen_particles({vertical_screen(0.4, -0.2, 0.9)}, 0.01, 0.014, tank, "case.toml");
  ASSERT_EQ(cut.size(), exact.size());
  for (std::size_t k = 0; k < cut.size(); ++k) {
    EXPECT_NEAR(cut.position[k].x, exact.position[k].x, 1e-9);
    EXPECT_NEAR(cut.position[k].y, exact.position[k].y, 1e-9);
  }
  const ClippedLine line = clip_to_section(tank, {0.4, -0.2}, {0.4, 0.9}, "case.toml", "screens.0");
  EXPECT_TRUE(line.clipped_from);
  EXPECT_TRUE(line.clipped_to);
  EXPECT_NEAR(line.from.y, 0.0, 1e-9);
  EXPECT_NEAR(line.to.y, 0.6, 1e-9);
}

// A horizontal baffle drawn from outside the left wall to x = 0.4 at y = 0.1: cut at the wall x = 0,
// 40 particles of 0.01 m from x = 0.005.
TEST(ScreenParticles, HorizontalBaffleClippedAtWall) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  ScreenSpec s;
  s.name = "baffle";
  s.from = {-0.5, 0.1};
  s.to = {0.4, 0.1};
  s.solidity = 0.6;
  const ScreenParticles sp = make_screen_particles({s}, 0.01, 0.014, tank, "case.toml");
  ASSERT_EQ(sp.size(), 40u);
  EXPECT_NEAR(sp.position.front().x, 0.005, 1e-9);
  EXPECT_NEAR(sp.position.back().x, 0.395, 1e-9);
  EXPECT_NEAR(std::abs(sp.elements[0].normal.y), 1.0, 1e-12);
}

// Curved bottom: a vertical screen through the lowest point of a parabolic tank, drawn from below
// the bottom to above the top, is cut at the bottom (y = 0 at x = L/2) and at the top of the walls.
TEST(ScreenParticles, ClippedToParabolicBottom) {
  TankSpec t;
  t.shape = "parabolic";
  t.length = 1.0;
  t.height = 0.5;
  t.coefficient = 2.0;  // y = 2 (x - 0.5)^2 reaches 0.5 at the walls
  const TankGeometry tank = make_tank(t, "test");
  const ClippedLine line = clip_to_section(tank, {0.5, -1.0}, {0.5, 2.0}, "case.toml", "screens.0");
  EXPECT_NEAR(line.from.y, tank.bottom_at(0.5), 1e-9);
  EXPECT_NEAR(line.to.y, tank.y_top, 1e-9);
  // Off-centre, x = 0.7: the bottom is at 2 * 0.2^2 = 0.08 (to the polyline's chord error, 1e-6).
  const ClippedLine off = clip_to_section(tank, {0.7, -1.0}, {0.7, 2.0}, "case.toml", "screens.0");
  EXPECT_NEAR(off.from.y, 0.08, 1e-6);
}

// Several elements, with the explicit slat one kept as an element without particles, and the
// Morison loss coefficient from the solidity unless given.
TEST(ScreenParticles, SeveralElementsAndModels) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  ScreenSpec a = vertical_screen(0.3, 0.0, 0.6);
  ScreenSpec b = vertical_screen(0.5, 0.0, 0.6);
  b.model = ScreenModel::explicit_slats;
  b.slat_height = 0.005;
  b.slat_gap = 0.007;
  b.solidity = 0.0;
  ScreenSpec c = vertical_screen(0.7, 0.0, 0.3, 0.5);
  c.model = ScreenModel::morison;
  ScreenSpec d = vertical_screen(0.8, 0.0, 0.3, 0.0);
  d.model = ScreenModel::morison;
  d.loss_coefficient = 2.5;  // given: no solidity needed
  const ScreenParticles sp = make_screen_particles({a, b, c, d}, 0.01, 0.014, tank, "case.toml");
  ASSERT_EQ(sp.elements.size(), 4u);
  EXPECT_EQ(sp.elements[0].count, 60u);
  EXPECT_EQ(sp.elements[1].count, 0u);
  EXPECT_NEAR(sp.elements[1].solidity, 5.0 / 12.0, 1e-15);
  EXPECT_EQ(sp.elements[2].count, 30u);
  EXPECT_EQ(sp.elements[2].first, 60u);
  EXPECT_NEAR(sp.elements[2].loss_coefficient, slat_screen_loss_coefficient(0.5), 1e-15);
  EXPECT_NEAR(sp.elements[3].loss_coefficient, 2.5, 0.0);
  EXPECT_EQ(sp.size(), 120u);
  EXPECT_EQ(sp.element[60], 2u);
  EXPECT_EQ(sp.element[119], 3u);
}

// Bad elements name the key (screens.N.<key>, N from 0) and the file.
TEST(ScreenParticles, Errors) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  const ScreenSpec good = vertical_screen(0.4, 0.0, 0.6);
  auto make = [&](const ScreenSpec& s) {
    return error_key([&] { make_screen_particles({good, s}, 0.01, 0.014, tank, "case.toml"); });
  };
  EXPECT_EQ(make(vertical_screen(1.5, 0.1, 0.5)), "screens.1.from");   // outside the tank
  EXPECT_EQ(make(vertical_screen(0.4, 0.3, 0.3)), "screens.1.to");     // zero length
  EXPECT_EQ(make(vertical_screen(0.4, 0.7, 0.9)), "screens.1.from");   // above the top of the walls
  EXPECT_EQ(make(vertical_screen(0.4, 0.0, 0.6, 1.2)), "screens.1.solidity");
  EXPECT_EQ(make(vertical_screen(0.4, 0.0, 0.6, 0.0)), "screens.1.solidity");  // ergun needs S
  ScreenSpec s = vertical_screen(0.4, 0.0, 0.6);
  s.thickness = 0.0;
  EXPECT_EQ(make(s), "screens.1.thickness");
  s = vertical_screen(0.4, 0.0, 0.6);
  s.spacing = -0.01;
  EXPECT_EQ(make(s), "screens.1.spacing");
  s = vertical_screen(0.4, 0.0, 0.6);
  s.interaction_radius = -1.0;
  EXPECT_EQ(make(s), "screens.1.interaction_radius");
  s = vertical_screen(0.4, 0.0, 0.6, 0.3);
  s.slat_height = 0.005;
  s.slat_gap = 0.007;  // S = 5/12, not 0.3
  EXPECT_EQ(make(s), "screens.1.solidity");
  s = vertical_screen(0.4, 0.0, 0.6, 0.0);
  s.slat_height = 0.005;  // gap missing
  EXPECT_EQ(make(s), "screens.1.slat_gap");
  EXPECT_EQ(make(good), "");
}

// A line that enters the section twice (across the ridge of a W-shaped polyline bottom) is refused.
TEST(ScreenParticles, CrossingAWallIsAnError) {
  TankSpec t;
  t.shape = "polyline";
  t.points = {{0.0, 1.0}, {0.0, 0.0}, {0.5, 0.6}, {1.0, 0.0}, {1.0, 1.0}};
  const TankGeometry tank = make_tank(t, "test");
  EXPECT_EQ(error_key([&] { clip_to_section(tank, {0.05, 0.2}, {0.95, 0.2}, "case.toml", "screens.3"); }),
            "screens.3.from");
  // Above the ridge it is fine.
  EXPECT_EQ(error_key([&] { clip_to_section(tank, {0.05, 0.8}, {0.95, 0.8}, "case.toml", "screens.3"); }), "");
}

}  // namespace
}  // namespace sloshsph
