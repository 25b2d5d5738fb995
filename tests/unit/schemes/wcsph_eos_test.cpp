// Equation of state, the sound-speed estimate, the repulsive force and the stable step, with
// numbers worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/physics/repulsive_force.hpp"
#include "sloshsph/physics/wcsph_eos.hpp"
#include "sloshsph/schemes/wcsph.hpp"
#include "wcsph_test_cases.hpp"

namespace sloshsph {
namespace {

// Dincer eq. 10: p = c0^2 (rho - rho0). c0 = 20 m/s, rho = 1010: p = 400 x 10 = 4000 Pa.
TEST(WcsphEos, LinearEquationOfStateAndInverse) {
  EXPECT_DOUBLE_EQ(eos_pressure(1010.0, 1000.0, 20.0), 4000.0);
  EXPECT_DOUBLE_EQ(eos_pressure(995.0, 1000.0, 20.0), -2000.0);
  EXPECT_DOUBLE_EQ(eos_density(4000.0, 1000.0, 20.0), 1010.0);
  EXPECT_DOUBLE_EQ(eos_density(eos_pressure(1003.25, 1000.0, 22.0), 1000.0, 22.0), 1003.25);
}

// Morris et al. estimate (Shao eq. 9, Dincer eq. 13), delta = 0.01, g = 9.81, nu = 1e-6.
// Rest tank (H = 0.25, l = 0.5): u_b = sqrt(2 g H) = sqrt(4.905) = 2.21472346 m/s;
//   u_b^2/delta = 490.5, nu u_b/(l delta) = 4.4e-4, F l/delta = 9.81 x 0.5 / 0.01 = 490.5
//   -> c0 = sqrt(490.5) = 22.1472346 m/s.
TEST(WcsphEos, SoundSpeedEstimateAtRest) {
  const CaseSpec spec = test::rest_tank_case();
  const SoundSpeedEstimate e = estimate_sound_speed(spec);
  EXPECT_NEAR(e.bulk_velocity, 2.2147234590350102, 1e-12);
  EXPECT_NEAR(e.force, 9.81, 1e-12);
  EXPECT_NEAR(e.c0, 22.147234590350102, 1e-9);
  EXPECT_NEAR(case_sound_speed(spec), 22.147234590350102, 1e-9);
}

// Harmonic base motion X0 = 0.005 m, omega = 6 rad/s: u_b = 2.21472346 + 0.03 = 2.24472346,
// u_b^2/delta = 503.878..., F = 9.81 + 0.005 x 36 = 9.99, F l/delta = 499.5 -> c0 = 10 u_b =
// 22.4472346 m/s. Long tank l = 2 m at rest: F l/delta = 1962 -> c0 = sqrt(1962) = 44.2944692.
// Viscous fluid nu = 2 m^2/s, l = 0.5: nu u_b/(l delta) = 2 x 2.21472346 / 0.005 = 885.889384
// -> c0 = 29.7638940. A given sound speed wins.
TEST(WcsphEos, SoundSpeedEstimateTerms) {
  CaseSpec moving = test::rest_tank_case();
  moving.excitation.type = ExcitationType::harmonic;
  moving.excitation.amplitude = 0.005;
  moving.excitation.omega = 6.0;
  EXPECT_NEAR(estimate_sound_speed(moving).c0, 22.447234590350102, 1e-9);
  EXPECT_NEAR(estimate_sound_speed(moving).force, 9.99, 1e-12);

  CaseSpec long_tank = test::rest_tank_case();
  long_tank.tank.length = 2.0;
  EXPECT_NEAR(estimate_sound_speed(long_tank).c0, 44.294469180700204, 1e-9);

  CaseSpec viscous = test::rest_tank_case();
  viscous.fluid.viscosity = 2.0;
  EXPECT_NEAR(estimate_sound_speed(viscous).c0, std::sqrt(2.0 * 2.2147234590350102 / 0.005), 1e-9);
  EXPECT_NEAR(estimate_sound_speed(viscous).c0, 29.763894, 1e-5);

  CaseSpec given = test::rest_tank_case();
  given.scheme.wcsph.sound_speed = 30.0;
  EXPECT_EQ(case_sound_speed(given), 30.0);
  EXPECT_EQ(WcsphScheme(given, 0.014).sound_speed(), 30.0);
  EXPECT_NEAR(WcsphScheme(test::rest_tank_case(), 0.014).sound_speed(), 22.147234590350102, 1e-9);
}

// Shao eqs. 25-28 by hand. f(0.5) = 2/3, f(0.8) = 1.6 - 0.96 = 0.64, f(1.5) = 0.5 x 0.25 = 0.125,
// f(2) = 0; continuous at 2/3 and 1. c0 = 20, h = 0.014, dd = 0.01, r = 0.005 along y:
// chi = 0.5, eta = 0.005 / 0.0105 = 0.476 -> f = 2/3, a = 0.01 x 400 x 0.5 x (2/3) / 0.005
// = 266.667 m/s^2 away from the wall; zero at and beyond dd.
TEST(WcsphEos, RepulsiveForceByHand) {
  EXPECT_DOUBLE_EQ(repulsive_shape(0.5), 2.0 / 3.0);
  EXPECT_NEAR(repulsive_shape(0.8), 0.64, 1e-15);
  EXPECT_NEAR(repulsive_shape(1.5), 0.125, 1e-15);
  EXPECT_EQ(repulsive_shape(2.0), 0.0);
  EXPECT_NEAR(repulsive_shape(2.0 / 3.0 + 1e-12), 2.0 / 3.0, 1e-10);
  EXPECT_NEAR(repulsive_shape(1.0 + 1e-12), 0.5, 1e-10);
  const Vec2 a = repulsive_acceleration({0.0, 0.005}, 20.0, 0.014, 0.01);
  EXPECT_NEAR(a.x, 0.0, 1e-12);
  EXPECT_NEAR(a.y, 800.0 / 3.0, 1e-9);
  EXPECT_EQ(norm(repulsive_acceleration({0.0, 0.01}, 20.0, 0.014, 0.01)), 0.0);
  EXPECT_EQ(norm(repulsive_acceleration({0.008, 0.008}, 20.0, 0.014, 0.01)), 0.0);
}

// stable_dt at rest: u = 0 and the fluid in balance (|du/dt| ~ 0), so the acoustic bound
// decides: dt = cfl h / c0 = 0.2 x 0.014 / 22.1472346 = 1.26426e-4 s (1e-9 relative).
TEST(WcsphEos, StableStepAtRestIsTheAcousticBound) {
  const CaseSpec spec = test::rest_tank_case();
  Scene scene = build_scene(spec);
  WcsphScheme scheme(spec, scene.h);
  FrameForce frame;
  frame.uniform = {0.0, -9.81};
  scheme.initialise(scene.particles, frame);
  const double expected = 0.2 * scene.h / 22.147234590350102;
  EXPECT_NEAR(scheme.stable_dt(scene.particles, frame), expected, 1e-9 * expected);
  // Hydrostatic start: densities from the scene pressure by the inverse equation of state.
  const Particles& p = scene.particles;
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    EXPECT_NEAR(p.density[i], 1000.0 + p.pressure[i] / (22.147234590350102 * 22.147234590350102), 1e-9);
}

}  // namespace
}  // namespace sloshsph
