#pragma once
// Mechanical admittance function (MAF) and effective damping of a structure under random force
// (thesis sec. 4.4.2.2, eq. 4.30; Vickery, Isyumov & Davenport 1983, J. Wind Eng. Ind. Aerodyn. 11,
// 285-294).
#include "sloshsph/analysis/spectrum.hpp"

namespace sloshsph {

// Thesis eq. 4.30: |H(f)|^2 = S(f) K^2 / S_0(f), with S the PSD of the structural displacement
// (or another response, e.g. the wave height) and S_0 the PSD of the applied force; K the
// generalised stiffness. For the structure alone |H|^2 -> 1 at f -> 0 (static response F/K).
// This version takes a flat force spectrum of level `force_psd_level` (N^2/Hz, one-sided, as
// BandLimitedNoise::psd_level gives); bins where the force has no power must be cut by the caller
// (effective_damping_ratio integrates only over the range it is given).
Spectrum mechanical_admittance(const Spectrum& response_psd, double force_psd_level, double stiffness);

// Same with a measured force PSD on the same grid (e.g. welch_psd of the force with the same
// segment length); bins where the force PSD is below `floor` times its maximum are set to 0.
Spectrum mechanical_admittance(const Spectrum& response_psd, const Spectrum& force_psd, double stiffness,
                               double floor = 1e-6);

// |H(f)|^2 of a linear SDOF: 1 / ((1 - r^2)^2 + (2 zeta r)^2), r = f / f_n.
double sdof_admittance(double f, double natural_frequency, double zeta);

// Effective damping ratio from the area under the admittance curve (Vickery et al. 1983): for a
// linear SDOF, integral_0^inf |H(f)|^2 df = f_n integral_0^inf dr / ((1 - r^2)^2 + (2 zeta r)^2)
// = pi f_n / (4 zeta) (the standard white-noise integral, e.g. Crandall & Mark 1963), so the
// structure with a damper is replaced by the SDOF of the same f_n and the same area:
//   zeta_eff = pi f_n / (4 A),  A = trapezoid integral of |H|^2 over [f_lo, f_hi].
// The range should hold all of the resonant response; the part left out biases zeta_eff up
// (for f_n = 0.134 Hz, zeta = 1% and the 0.05-0.5 Hz band: ~0.5%).
double effective_damping_ratio(const Spectrum& admittance, double natural_frequency, double f_lo, double f_hi);

}  // namespace sloshsph
