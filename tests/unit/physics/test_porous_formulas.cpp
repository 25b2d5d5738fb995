// Closed forms of the porous-element closures (physics/porous): Kozeny-Carman, Ergun, the
// slat-screen loss coefficient and the Morison pressure drop.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/physics/porous.hpp"

namespace sloshsph {
namespace {

// Thesis eq. 2.22 by hand, for the thesis screens (n_w = 1 - 5/12 ~ 0.58, D_c = dp = 7 mm):
//   n^3 = 0.195112, D^2 = 4.9e-5 m^2, n^3 D^2 = 9.560488e-6, 150 (1 - n)^2 = 26.46,
//   K = 9.560488e-6 / 26.46 = 3.6131852e-7 m^2.
// Tolerance: 1e-7 relative (the hand value is given to 8 digits).
TEST(PorousFormulas, KozenyCarmanHandValue) {
  EXPECT_NEAR(kozeny_carman_permeability(0.58, 0.007), 3.6131852e-7, 3.6131852e-7 * 1e-7);
}

// K scales with D^2 and n^3 / (1 - n)^2 (eq. 2.22): exact ratios to round-off (1e-14).
TEST(PorousFormulas, KozenyCarmanScaling) {
  const double k = kozeny_carman_permeability(0.5, 0.01);
  EXPECT_NEAR(kozeny_carman_permeability(0.5, 0.02) / k, 4.0, 1e-14);
  EXPECT_NEAR(k, 0.125 * 1e-4 / (150.0 * 0.25), 1e-14 * k);
}

// Thesis eq. 2.21 by hand, mu = 1.0e-3 Pa s, rho = 1000 kg/m^3, K above, n = 0.58, |u| = 0.1 m/s:
//   viscous    mu/K |u|                              = 1e-3 / 3.6131852e-7 * 0.1 = 276.764 Pa/m
//   inertial   1.75/sqrt(150) = 0.14288690, sqrt(K) = 6.0109776e-4, n^1.5 = 0.44171484,
//              rho / (sqrt(K) n^1.5) = 3.7662826e6 1/m,  x 0.14288690 x |u|^2 = 5381.52 Pa/m
//   total      5658.29 Pa/m, along u.
// Tolerance: 1e-5 relative (hand values to 6 digits).
TEST(PorousFormulas, ErgunHandValue) {
  const double k = kozeny_carman_permeability(0.58, 0.007);
  const Vec2 g = ergun_pressure_gradient(1.0e-3, 1000.0, k, 0.58, Vec2{0.1, 0.0});
  EXPECT_NEAR(g.x, 5658.29, 5658.29 * 1e-5);
  EXPECT_EQ(g.y, 0.0);
  // The two terms separately: the Darcy limit (rho = 0) and the inertial term (mu = 0).
  EXPECT_NEAR(ergun_pressure_gradient(1.0e-3, 0.0, k, 0.58, Vec2{0.1, 0.0}).x, 276.764, 276.764 * 1e-5);
  EXPECT_NEAR(ergun_pressure_gradient(0.0, 1000.0, k, 0.58, Vec2{0.1, 0.0}).x, 5381.52, 5381.52 * 1e-5);
}

// Vector form: the loss is along u and depends on |u| only (isotropic medium), odd in u.
// Same |u| = 0.1 as above, u = (0.06, -0.08): g = 5658.29 / 0.1 * u. Tolerance 1e-5 relative.
TEST(PorousFormulas, ErgunVectorForm) {
  const double k = kozeny_carman_permeability(0.58, 0.007);
  const Vec2 u{0.06, -0.08};
  const Vec2 g = ergun_pressure_gradient(1.0e-3, 1000.0, k, 0.58, u);
  EXPECT_NEAR(g.x, 56582.9 * 0.06, 56582.9 * 0.06 * 1e-5);
  EXPECT_NEAR(g.y, -56582.9 * 0.08, 56582.9 * 0.08 * 1e-5);
  const Vec2 gm = ergun_pressure_gradient(1.0e-3, 1000.0, k, 0.58, -u);
  EXPECT_DOUBLE_EQ(gm.x, -g.x);
  EXPECT_DOUBLE_EQ(gm.y, -g.y);
}

// Ergun's inertial loss coefficient, C_E = 3.5 t (1 - n) / (n^3 D_c): for n = 0.58, D_c = 7 mm,
// t = 1 mm by hand 3.5e-3 x 0.42 / (0.195112 x 0.007) = 1.0763049 (tolerance 1e-7 relative). It
// is the same number as eq. 2.24's inertial pressure loss over t, 5381.52 Pa/m x 1e-3 m at
// |u| = 0.1 m/s, divided by 1/2 rho u^2 = 5 Pa (tolerance 1e-5, the hand value's digits).
TEST(PorousFormulas, ErgunInertialLossCoefficient) {
  const double k = kozeny_carman_permeability(0.58, 0.007);
  EXPECT_NEAR(ergun_inertial_loss_coefficient(k, 0.58, 0.001), 1.0763049, 1.0763049 * 1e-7);
  const double drop = ergun_pressure_gradient(0.0, 1000.0, k, 0.58, Vec2{0.1, 0.0}).x * 0.001;
  EXPECT_NEAR(ergun_inertial_loss_coefficient(k, 0.58, 0.001), drop / 5.0, 1e-5 * drop / 5.0);
  // Linear in t, and as 1/D_c through K_P (eq. 2.22).
  EXPECT_NEAR(ergun_inertial_loss_coefficient(k, 0.58, 0.002), 2.0 * 1.0763049, 2e-7);
  EXPECT_NEAR(ergun_inertial_loss_coefficient(kozeny_carman_permeability(0.58, 0.0035), 0.58, 0.001),
              2.0 * 1.0763049, 2e-7);
}

// Morison drag per unit area, 1/2 rho C_l |u| u: rho = 1000, C_l = 2, u = (0.06, -0.08) (|u| = 0.1):
// 0.5 * 1000 * 2 * 0.1 * u = (6, -8) Pa. Round-off tolerance 1e-12.
TEST(PorousFormulas, MorisonPressureDrop) {
  const Vec2 dp = morison_pressure_drop(1000.0, 2.0, Vec2{0.06, -0.08});
  EXPECT_NEAR(dp.x, 6.0, 1e-12);
  EXPECT_NEAR(dp.y, -8.0, 1e-12);
  EXPECT_NEAR(morison_pressure_drop(1000.0, 2.0, Vec2{0.1, 0.0}).x, 10.0, 1e-12);
}

// Loss coefficient C_l = (1/(C_c (1-S)) - 1)^2, C_c = 0.405 exp(-pi S) + 0.595 by hand:
//   S = 0.5:   exp(-pi/2) = 0.20787958, C_c = 0.67919123, 1/(C_c 0.5) = 2.9446788, C_l = 3.7817756
//   S = 5/12 (thesis screens, h_slat = 5 mm, h_gap = 7 mm): exp(-5 pi/12) = 0.27009084,
//              C_c = 0.70438679, 1/(C_c 7/12) = 2.4337278, C_l = 2.0555754
// Tolerance 1e-7 relative (hand values to 8 digits).
TEST(PorousFormulas, SlatScreenLossCoefficientHandValues) {
  EXPECT_NEAR(slat_screen_loss_coefficient(0.5), 3.7817756, 3.7817756 * 1e-7);
  EXPECT_NEAR(slat_screen_loss_coefficient(5.0 / 12.0), 2.0555754, 2.0555754 * 1e-7);
  EXPECT_NEAR(slat_screen_loss_coefficient(0.0), 0.0, 1e-15);  // no screen, no loss
}

// The contraction coefficient behind the formula has the right limits: C_c(0) = 1 gives C_l(0) =
// 0, and as S -> 1 C_c -> 0.405 e^-pi + 0.595 = 0.61250, the free-streamline (Kirchhoff / von
// Mises) contraction of a 2D slot, pi / (pi + 2) = 0.61102. So C_l (1 - S)^2 -> (1/C_c - (1-S))^2
// -> (1/0.6125)^2 = 2.6656 as S -> 1. Checked at S = 0.999 against the slot value
// (1/0.61102 - 0.001)^2 = 2.6752: the fitted C_c is 0.24% above pi/(pi+2), so C_l is ~0.5% below;
// tolerance 1%.
TEST(PorousFormulas, SlatScreenLossCoefficientHighSolidityLimit) {
  const double s = 0.999;
  const double cc_slot = std::numbers::pi / (std::numbers::pi + 2.0);
  const double expected = std::pow(1.0 / cc_slot - (1.0 - s), 2);
  EXPECT_NEAR(slat_screen_loss_coefficient(s) * (1.0 - s) * (1.0 - s), expected, 0.01 * expected);
}

// Cross-check with a tabulation from a different source: Blevins (1984), Applied Fluid Dynamics
// Handbook, loss coefficients of square-edged screens / perforated plates versus the open
// fraction 1 - S (as reproduced in the `fluids` library, fluids/filters.py, square_edge_screen,
// which cites Blevins). Baines & Peterson's own table was not available. For the solidities of TLD
// screens (0.4 <= S <= 0.95) the two agree within 12% (largest: 11% at S = 0.85); below S = 0.4
// the slat formula is lower than Blevins (27% at S = 0.3, 45% at S = 0.2), which is not tested.
TEST(PorousFormulas, SlatScreenLossCoefficientAgainstBlevinsTable) {
  struct Row { double solidity, k; };
  const Row rows[] = {{0.40, 2.0},  {0.45, 2.8},  {0.50, 3.8},  {0.55, 5.5},  {0.60, 7.7},  {0.65, 11.0},
                      {0.70, 17.0}, {0.75, 30.0}, {0.80, 52.0}, {0.85, 85.0}, {0.90, 250.0}, {0.95, 1000.0}};
  for (const Row& r : rows) {
    const double cl = slat_screen_loss_coefficient(r.solidity);
    EXPECT_NEAR(cl, r.k, 0.12 * r.k) << "S = " << r.solidity;
  }
}

}  // namespace
}  // namespace sloshsph
