#pragma once
// The linear estimate a TLD designer makes before any simulation: the tank's first sloshing mode
// as a tuned mass damper (TMD) on the SDOF structure, and the effective damping that the area
// method (Vickery et al. 1983, analysis/admittance.hpp) would measure for it under white-noise
// force.
//
// Mechanical analogue of the tank (Graham & Rodriguez 1952; Housner 1963; for TLDs Sun et al.
// 1995 and the thesis's sec. 4.2.3): the liquid splits into a convective mass m_1 on a spring of
// frequency omega_1 (the first sloshing mode; linear/modal.hpp gives both) and the rest, which
// moves rigidly with the tank. The tank's damping ratio zeta_t stands for everything that
// dissipates the sloshing energy (boundary layers, breaking, screens, and in a simulation the
// scheme's own damping) and is the unknown of the estimate. Absolute displacements x (structure)
// and y (convective mass):
//   (M + m_rigid) x'' + C x' + K x + c_1 (x' - y') + k_1 (x - y) = F,
//   m_1 y'' + c_1 (y' - x') + k_1 (y - x) = 0,   k_1 = m_1 omega_1^2,  c_1 = 2 zeta_t m_1 omega_1.
// Linear: it knows neither the amplitude dependence of the sloshing frequency and damping nor
// the higher modes, which is why the simulations exist.
#include <optional>

#include "sloshsph/structure/sdof.hpp"

namespace sloshsph {

struct EquivalentTmd {
  SdofSpec structure;           // M, C, K of the structure alone
  double convective_mass = 0.0; // kg, m_1 of all the tanks
  double rigid_mass = 0.0;      // kg, the rest of the liquid plus any mass riding rigidly with the tanks
  double convective_omega = 0.0;  // rad/s, omega_1
};

// |H(f)|^2 = |K X(f) / F(f)|^2 of the structure displacement with the tank of damping ratio
// zeta_tank (thesis eq. 4.30's admittance, exactly, for the linear model).
double equivalent_tmd_admittance(const EquivalentTmd& tmd, double zeta_tank, double frequency);

struct EquivalentTmdResponse {
  double zeta_tank = 0.0;
  // pi f_n / (4 A), A the area under |H|^2 over the band and f_n the structure's own natural
  // frequency: the same definition as summary.json's structure.admittance.effective_damping_ratio.
  double effective_damping = 0.0;
  // RMS displacement and acceleration under band-limited white-noise force, divided by those of
  // the structure alone under the same force.
  double displacement_rms_ratio = 0.0;
  double acceleration_rms_ratio = 0.0;
};

// The response over the force band [f_lo, f_hi] (Hz; composite Simpson, 50 points per half-width
// of the sharpest peak, ζ f_n with ζ the smaller of the two damping ratios, at most 4e6 points).
EquivalentTmdResponse equivalent_tmd_response(const EquivalentTmd& tmd, double zeta_tank, double f_lo, double f_hi);

// The tank damping ratio in [1e-4, 1] that maximises the effective damping over the band, and
// the response there (golden-section search on log zeta_tank).
EquivalentTmdResponse optimal_equivalent_tmd(const EquivalentTmd& tmd, double f_lo, double f_hi);

// The tank damping ratio at or below the optimum's whose effective damping is `zeta_eff`: what a
// measured zeta_eff (a simulation's, a test's) means as the damping of a linear TMD of the same
// mass and tuning. Empty when zeta_eff is outside [zeta_eff(1e-4), zeta_eff(optimum)] (no linear
// tank gives it). Bisection on log zeta_tank to 0.1%, on the branch where zeta_eff increases.
std::optional<double> tank_damping_for_effective_damping(const EquivalentTmd& tmd, double zeta_eff, double f_lo,
                                                         double f_hi);

}  // namespace sloshsph
