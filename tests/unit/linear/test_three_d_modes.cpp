// The closed-form 3D modes of `sloshsph modes` (linear/three_d_modes.hpp, issue 31).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/cylinder_tank.hpp"
#include "sloshsph/linear/three_d_modes.hpp"

namespace sloshsph {
namespace {

CaseSpec three_d_tank(const std::string& shape, double length, double breadth, double depth) {
  CaseSpec s;
  s.tank.dimensions = 3;
  s.tank.shape = shape;
  s.tank.length = length;
  s.tank.breadth = breadth;
  s.tank.radius = 0.5 * length;
  s.fill.depth = depth;
  return s;
}

// Reference: omega^2 = g k tanh(k h), k = pi sqrt((m/L)^2 + (n/B)^2), written out for a 0.4 x 0.2 m
// box with h = 0.15 m: (1,0) k = pi/0.4, (2,0) k = pi/0.2 = (0,1)'s, (1,1) k = pi sqrt(6.25 + 25).
// Tolerance: round-off.
TEST(ThreeDModes, BoxModesInOrder) {
  const std::vector<ThreeDMode> modes = three_d_modes(three_d_tank("rectangle", 0.4, 0.2, 0.15), 4);
  ASSERT_EQ(modes.size(), 4u);
  auto omega = [](double k) { return std::sqrt(9.81 * k * std::tanh(k * 0.15)); };
  EXPECT_EQ(modes[0].m, 1);
  EXPECT_EQ(modes[0].n, 0);
  EXPECT_NEAR(modes[0].omega, omega(std::numbers::pi / 0.4), 1e-12);
  // (2,0) and (0,1) have the same k; (0,1) is generated first and the sort is stable.
  EXPECT_EQ(modes[1].m, 0);
  EXPECT_EQ(modes[1].n, 1);
  EXPECT_EQ(modes[2].m, 2);
  EXPECT_EQ(modes[2].n, 0);
  EXPECT_NEAR(modes[1].omega, modes[2].omega, 1e-12);
  EXPECT_NEAR(modes[3].omega, omega(std::numbers::pi * std::sqrt(6.25 + 25.0)), 1e-12);
  EXPECT_EQ(modes[3].m, 1);
  EXPECT_EQ(modes[3].n, 1);
}

// Reference: the (1,1) mode is the one with j'_{1,1} = 1.8412 (cylinder_first_sloshing_omega); the
// next are (2,1), j' = 3.0542, then (0,1), j' = 3.8317 (Abramowitz & Stegun, Table 9.5).
TEST(ThreeDModes, CylinderModesInOrder) {
  const std::vector<ThreeDMode> modes = three_d_modes(three_d_tank("cylinder", 0.3, 0.3, 0.15), 3);
  ASSERT_EQ(modes.size(), 3u);
  EXPECT_EQ(modes[0].m, 1);
  EXPECT_EQ(modes[0].n, 1);
  EXPECT_DOUBLE_EQ(modes[0].omega, cylinder_first_sloshing_omega(0.15, 0.15, 9.81));
  const double k2 = 3.0542 / 0.15, k0 = 3.8317 / 0.15;
  EXPECT_EQ(modes[1].m, 2);
  EXPECT_NEAR(modes[1].omega, std::sqrt(9.81 * k2 * std::tanh(k2 * 0.15)), 1e-12);
  EXPECT_EQ(modes[2].m, 0);
  EXPECT_NEAR(modes[2].omega, std::sqrt(9.81 * k0 * std::tanh(k0 * 0.15)), 1e-12);
}

TEST(ThreeDModes, PrismHasNoClosedForm) {
  EXPECT_THROW(three_d_modes(three_d_tank("sloped", 0.4, 0.2, 0.1), 3), InputError);
}

}  // namespace
}  // namespace sloshsph
