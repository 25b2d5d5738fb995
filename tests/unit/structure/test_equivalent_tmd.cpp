// The linear equivalent-TMD estimate (src/sloshsph/structure/equivalent_tmd.hpp) against the
// closed-form white-noise integrals of one and two degrees of freedom and Warburton's optimum.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/structure/equivalent_tmd.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

// int_-inf^inf |B(iw) / A(iw)|^2 dw for A of degree 4 and B of degree 3 (coefficients of s^0..s^4,
// s = iw): the tabulated integral I_4 (James, Nichols & Phillips 1947; Crandall & Mark 1963).
double white_noise_integral_4(const double a[5], const double b[4]) {
  const double num = a[0] * b[3] * b[3] * (a[0] * a[3] - a[1] * a[2]) +
                     a[0] * a[1] * a[4] * (2 * b[1] * b[3] - b[2] * b[2]) -
                     a[0] * a[3] * a[4] * (b[1] * b[1] - 2 * b[0] * b[2]) +
                     a[4] * b[0] * b[0] * (a[1] * a[4] - a[2] * a[3]);
  const double den = a[0] * a[4] * (a[0] * a[3] * a[3] + a[1] * a[1] * a[4] - a[1] * a[2] * a[3]);
  return kPi * num / den;
}

// The thesis's building (M_s = 70,000 t, C_s = 1.18e6 N s/m, K_s = 4.96e7 N/m) with a tank's first
// mode of mass m_1 (kg) at f_1 (Hz), and `rigid` kg riding with the structure.
EquivalentTmd thesis_building_with(double m1, double f1, double rigid) {
  EquivalentTmd tmd;
  tmd.structure = {7.0e7, 1.18e6, 4.96e7};
  tmd.convective_mass = m1;
  tmd.rigid_mass = rigid;
  tmd.convective_omega = 2.0 * kPi * f1;
  return tmd;
}

TEST(EquivalentTmd, WithoutTankItIsTheStructureAlone) {
  // Reference: int_0^inf |H|^2 df = pi f_n / (4 zeta) for a linear SDOF (Crandall & Mark 1963), so
  // the area method returns the structure's own zeta. Tolerance 1e-4 (the band 1e-3-100 f_n
  // leaves out ~1e-6 of the area); the RMS ratios are 1 to rounding.
  EquivalentTmd tmd;
  tmd.structure = SdofSpec::from_frequency(7.0e7, 0.134, 0.01);
  const double fn = tmd.structure.natural_frequency();
  const EquivalentTmdResponse r = equivalent_tmd_response(tmd, 0.05, 1e-3 * fn, 100.0 * fn);
  EXPECT_NEAR(r.effective_damping, 0.01, 1e-6);
  EXPECT_NEAR(r.displacement_rms_ratio, 1.0, 1e-12);
  EXPECT_NEAR(r.acceleration_rms_ratio, 1.0, 1e-12);
  EXPECT_NEAR(equivalent_tmd_admittance(tmd, 0.05, fn), 1.0 / (4.0 * 0.01 * 0.01), 1e-9);
}

TEST(EquivalentTmd, AreaMatchesTheTwoDegreeOfFreedomWhiteNoiseIntegral) {
  // The thesis's building with a tank like FR (m_1 = 527 t on 0.1456 Hz, 198 t rigid), zeta_t = 3%.
  // Reference: X/F = D_1 / (D_s D_1 + m_1 s^2 (c_1 s + k_1)), D_1 = m_1 s^2 + c_1 s + k_1,
  // D_s = (M + m_r) s^2 + C s + K, integrated in closed form (I_4 above); zeta_eff = pi f_n /
  // (4 K^2 int_0^inf |X/F|^2 df) with int_0^inf df = I_4 / (4 pi). Tolerance 1e-4 (quadrature, band).
  const EquivalentTmd tmd = thesis_building_with(5.27e5, 0.1456, 1.98e5);
  const double zeta_t = 0.03;
  const double m = tmd.structure.mass + tmd.rigid_mass, c = tmd.structure.damping, k = tmd.structure.stiffness;
  const double m1 = tmd.convective_mass, k1 = m1 * std::pow(tmd.convective_omega, 2);
  const double c1 = 2.0 * zeta_t * m1 * tmd.convective_omega;
  const double a[5] = {k * k1, c * k1 + k * c1, m * k1 + c * c1 + k * m1 + m1 * k1, m * c1 + c * m1 + m1 * c1, m * m1};
  const double b[4] = {k1, c1, m1, 0.0};
  const double fn = tmd.structure.natural_frequency();
  const double exact = kPi * fn / (4.0 * k * k * white_noise_integral_4(a, b) / (4.0 * kPi));
  const EquivalentTmdResponse r = equivalent_tmd_response(tmd, zeta_t, 1e-3 * fn, 100.0 * fn);
  std::printf("  zeta_eff = %.6f%%, closed form %.6f%%\n", 100 * r.effective_damping, 100 * exact);
  EXPECT_NEAR(r.effective_damping / exact, 1.0, 1e-4);
  EXPECT_GT(r.effective_damping, tmd.structure.damping_ratio());
  EXPECT_LT(r.acceleration_rms_ratio, 1.0);
}

TEST(EquivalentTmd, OptimumMatchesWarburton) {
  // Reference: Warburton (1982, Earthq. Eng. Struct. Dyn. 10:381, Table I, white-noise force on an
  // undamped structure, displacement variance): tuned to omega_1 / omega_s = sqrt(1 + mu/2) / (1 + mu),
  // the variance is least at zeta_t = sqrt(mu (1 + 3mu/4) / (4 (1 + mu) (1 + mu/2))). Tolerance 1%
  // (the search resolves zeta_t to 0.1%).
  for (double mu : {0.005, 0.01, 0.05}) {
    EquivalentTmd tmd;
    tmd.structure = {1.0, 0.0, 1.0};
    tmd.convective_mass = mu;
    tmd.convective_omega = std::sqrt(1.0 + mu / 2.0) / (1.0 + mu);
    const double fn = tmd.structure.natural_frequency();
    const EquivalentTmdResponse best = optimal_equivalent_tmd(tmd, 0.01 * fn, 10.0 * fn);
    const double warburton = std::sqrt(mu * (1.0 + 0.75 * mu) / (4.0 * (1.0 + mu) * (1.0 + mu / 2.0)));
    std::printf("  mu = %.3f: optimum zeta_t = %.5f (Warburton %.5f), zeta_eff = %.4f\n", mu, best.zeta_tank,
                warburton, best.effective_damping);
    EXPECT_NEAR(best.zeta_tank / warburton, 1.0, 0.01);
    for (double other : {0.5 * warburton, 2.0 * warburton})
      EXPECT_LT(equivalent_tmd_response(tmd, other, 0.01 * fn, 10.0 * fn).effective_damping, best.effective_damping);
  }
}

TEST(EquivalentTmd, TankDampingForAnEffectiveDampingInvertsTheResponse) {
  // Round trip on the lower branch (tolerance: the bisection's 0.1% in zeta_t), and no answer
  // beyond the optimum or below the structure's own damping.
  const EquivalentTmd tmd = thesis_building_with(4.30e5, 0.1315, 2.95e5);  // like the SF tank
  for (double zeta_t : {0.002, 0.0134, 0.03}) {
    const double zeta_eff = equivalent_tmd_response(tmd, zeta_t, 0.05, 0.5).effective_damping;
    const std::optional<double> back = tank_damping_for_effective_damping(tmd, zeta_eff, 0.05, 0.5);
    ASSERT_TRUE(back.has_value()) << zeta_t;
    EXPECT_NEAR(*back / zeta_t, 1.0, 2e-3);
  }
  const EquivalentTmdResponse best = optimal_equivalent_tmd(tmd, 0.05, 0.5);
  EXPECT_FALSE(tank_damping_for_effective_damping(tmd, 1.01 * best.effective_damping, 0.05, 0.5).has_value());
  EXPECT_FALSE(tank_damping_for_effective_damping(tmd, 0.0094, 0.05, 0.5).has_value());
}

}  // namespace
}  // namespace sloshsph
