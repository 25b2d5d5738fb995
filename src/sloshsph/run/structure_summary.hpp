#pragma once
// Response of the structure of a [structure] case, from the sampled time series after a run
// (thesis 4.4.2.2): RMS (sigma) and peak (chi) of the structural displacement and acceleration,
// and under a noise load the mechanical admittance |H(f)|^2 = S(f) K^2 / S_0(f) (eq. 4.30) of the
// displacement and of the wave height, with the effective damping ratio from the area under the
// displacement admittance (Vickery, Isyumov & Davenport 1983; analysis/admittance.hpp).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sloshsph/analysis/spectrum.hpp"
#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

// The columns used (timeseries.csv names in brackets).
struct StructureSeries {
  std::vector<double> time;  // s [time]
  std::vector<double> x_s;   // m, displacement relative to the ground [x_s]
  std::vector<double> a_s;   // m/s^2, absolute acceleration [a_s]
  std::vector<double> F_e;   // N, external load [F_e]
  std::vector<double> eta;   // m, a wave gauge [eta:<name>]; empty: none
  std::string eta_name;      // the gauge's name
  // m/s^2, the ground acceleration at the sample times when [structure] ground = "excitation"
  // (not a column: the caller evaluates the excitation); empty: no ground motion.
  std::vector<double> ground_acceleration;
};

// Picks the columns from a run's series (`names[k]` names `columns[k]`; time first). `gauge`
// names the wave gauge for the wave-height admittance; empty: the first "eta:" column, if any.
// `suffix` "_y" picks the sway along y of a 3D structure (x_s_y, a_s_y, F_e_y).
// Throws std::invalid_argument when x_s, a_s or F_e is missing (not a [structure] run) or
// `gauge` is not a column.
StructureSeries structure_series(const std::vector<std::string>& names,
                                 const std::vector<std::vector<double>>& columns, const std::string& gauge = "",
                                 const std::string& suffix = "");

struct StructureSummaryOptions {
  double skip_seconds = 0.0;     // start-up left out of every statistic (the thesis uses the whole hour)
  double segment_seconds = 0.0;  // Welch segment length; 0: a quarter of the record, at most 600 s
};

// Mechanical admittance (noise load only), thesis eq. 4.30 with S_0 the flat PSD level of the
// applied noise (known exactly: run/structure_coupling.hpp, noise_load_level). The series is
// first resampled onto a uniform grid (linear interpolation at the median sample interval: an
// adaptive step leaves rows slightly off the nominal interval); S is a Welch PSD (Hann, 50%
// overlap, analysis/spectrum.hpp) for the curves.
// The effective damping (Vickery et al. 1983: the SDOF with the structure's f_n whose
// admittance has the same area) is computed from the area of the WHOLE record's periodogram,
// which by Parseval is K^2 sigma_x^2 / S_0 (the response has no power outside the load's band):
//   zeta_eff = pi f_n S_0 / (4 K^2 sigma_x^2).
// Why not the area of the Welch curve (reported as effective_damping_welch): Welch segments of
// a few hundred seconds hold only a few correlation times 1/(zeta w_n) of the lightly damped
// response, and the Hann windows weigh the two ends of the record less, so the curve's area
// scatters by +-10-15% with the segment length for one hour of the thesis building alone
// (measured: 0.93-1.12% for a true 1%), against +-5% for the whole-record variance.
struct StructureAdmittance {
  Spectrum force_psd;         // Welch PSD of F_e, N^2/Hz (for reference: flat at force_level in the band)
  Spectrum displacement_psd;  // S_x, m^2/Hz
  Spectrum displacement;      // |H_s(f)|^2 = S_x K^2 / S_0
  std::optional<Spectrum> wave;  // |H_eta(f)|^2 = S_eta K^2 / S_0 with the wave height
  double force_level = 0.0;   // S_0, N^2/Hz
  double f_lo = 0.0, f_hi = 0.0;    // Hz, the load's band
  double natural_frequency = 0.0;   // Hz, sqrt(K / M) / 2 pi of the structure alone
  double structure_damping_ratio = 0.0;  // C / (2 sqrt(K M)) of the structure alone
  double effective_damping = 0.0;        // zeta_eff from the record's variance (above)
  double effective_damping_welch = 0.0;  // zeta_eff from the area of the Welch curve over [f_lo, f_hi]
  double segment_seconds = 0.0;
  std::string eta_name;
};

// std::nullopt unless the load is noise and the record holds at least 4 samples per segment
// and one segment.
std::optional<StructureAdmittance> structure_admittance(const StructureSeries& series, const StructureSpec& spec,
                                                        const StructureSummaryOptions& options = {});

// The structure without its tanks under the same load as the run: the recorded F_e (and the
// same ground acceleration), so that a tank is judged against the structure alone over the
// same record (what thesis Table 4.4's "STR" row is), not against a statistical prediction.
// Integrated by Newmark's average acceleration (structure/sdof.hpp) from the case's initial
// state, with the load linearly interpolated between samples and each sample interval split
// into sub-steps of w_n h <= 0.01 (period error 1e-5, small against the phase the response
// remembers over 1/(zeta w_n)). The load between samples is the interpolation's: with samples
// of 0.05 s and the thesis building's 0.05-0.5 Hz noise, the response is within 0.1% of the
// one under the exact load (unit test).
struct StructureAloneResponse {
  std::vector<double> x;  // m, displacement relative to the ground, at the series' times
  std::vector<double> a;  // m/s^2, absolute acceleration
};
StructureAloneResponse structure_alone_response(const StructureSeries& series, const StructureSpec& spec);

// summary.json "structure": the structure (M, C, K, f_n, zeta, tanks, width), displacement and
// acceleration RMS and peak (acceleration also in milli-g, 1 milli-g = 9.80665e-3 m/s^2), the
// load's RMS and peak; for a noise load with target_peak_mg the predicted response of the
// structure alone (RMS and mean peak acceleration) and the measured RMS normalised by it
// (thesis Fig. 4.20); and the admittance results (zeta_eff, peak |H_s|^2 and its frequency).
// "structure_without_tank": structure_alone_response's RMS and peaks (and zeta_eff under noise),
// with the run's RMS and peaks divided by them ("..._ratio_to_without_tank" in "displacement"
// and "acceleration": below 1, the tanks reduce the response).
nlohmann::json structure_summary(const StructureSeries& series, const StructureSpec& spec,
                                 const StructureSummaryOptions& options = {});

// admittance.csv: f_Hz, H2_displacement, H2_wave (with a gauge), H2_structure_alone (the
// closed-form SDOF |H|^2 for comparison), S_force_N2_per_Hz, S_displacement_m2_per_Hz; one row
// per Welch bin from 0 to 2 f_hi.
std::string admittance_csv(const StructureAdmittance& admittance);

}  // namespace sloshsph
