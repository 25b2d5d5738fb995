#pragma once
// The structure that carries the tank(s): the building's fundamental sway mode as an SDOF
// (thesis 4.2.3, eq. 4.20: M_s x'' + C_s x' + K_s x = F_e + F_TLD), its external load F_e(t)
// ([structure.load]) and the two-way coupling with the fluid (eqs. 4.21-4.22).
//
// Coupling, every fluid step t_n -> t_n+1 (run/simulation.cpp drives it):
//  1. The structure advances first (Newmark average acceleration, structure/sdof.hpp) with
//     F_e(t_n+1) and the sloshing force of the previous fluid step, extrapolated linearly to
//     t_n+1 from the last two fluid steps (see advance()).
//  2. The fluid takes its step in the tank frame with the body force -A, A = (a_n + a_n+1) / 2
//     the structure's absolute acceleration averaged over the step. For Newmark's method this
//     is exact: v_n+1 - v_n = dt (a_n + a_n+1) / 2, so the tank the fluid feels has exactly the
//     structure's velocity change.
//  3. The base shear of that step (F_w: force of the walls and screens on the fluid, N per
//     metre of tank width) gives the sloshing force F_sw = F_w - m_w A (thesis 2.6.3.1), used
//     by the structure in the next step.
// Why the split (added-mass form): the force of the tanks on the structure is
//   F_TLD = -n b (F_w + m_r A) = -n b (m_w + m_r) A - n b F_sw,
// with n tanks of width b, m_w the fluid mass and m_r the rigid mass per metre (liquid sealed
// under a solid floor, ...). The inertial part -n b (m_w + m_r) A is moved to the left-hand
// side as an added mass (treated implicitly by Newmark) and only F_sw, which varies at the
// sloshing frequency and is a small part of F_w far from resonance, is lagged by one step.
// Feeding back the whole lagged F_w instead is an explicit treatment of the liquid's inertia
// and becomes unstable when n b m_w is comparable to M_s (the added-mass instability of
// partitioned fluid-structure coupling, Causin, Gerbeau & Nobile 2005). Checked in
// tests/unit/coupling (M = m_w) and tests/validation/structure_coupling_validation.cpp: the
// structure loses exactly the work the walls do on the liquid, to 1e-5 of its energy.
#include <memory>
#include <optional>
#include <string>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/signals/time_series.hpp"
#include "sloshsph/signals/white_noise.hpp"
#include "sloshsph/structure/sdof.hpp"

namespace sloshsph {

// M, C, K of the case's structure.
SdofSpec sdof_spec(const StructureSpec& spec);

// The external force F_e(t), N. Built once per run: a record is read, noise generated and
// scaled, at construction (InputError naming structure.load.* for a bad record or band).
//  harmonic: F = r(t) A sin(2 pi f t), r(t) = (1 - cos(pi t / ramp)) / 2 for t < ramp.
//  noise:    the sum of sinusoids of signals/white_noise.hpp (seed, band, duration
//            max(time.end, 1 / f_low), 0.01 s samples or finer), linearly interpolated, with a
//            flat one-sided PSD S0 (N^2/Hz) over the band. With `target_peak_mg`, S0 is chosen so
//            that the structure WITHOUT tanks reaches that mean peak acceleration over
//            `peak_duration` (thesis 4.4.2.1: the mean hourly peak), by random vibration theory:
//              sigma_a^2 = integral_{f_lo}^{f_hi} S0 w^4 / ((K - M w^2)^2 + (C w)^2) df
//              nu = sqrt(m_2 / m_0) (Rice), g = sqrt(2 ln(nu T)) + 0.5772 / sqrt(2 ln(nu T))
//              (Davenport 1964), and S0 such that g sigma_a = target x 1e-3 x 9.80665 m/s^2
//            (signals/white_noise.hpp: scale_noise_to_mean_peak). With `rms`:
//            S0 = rms^2 / (f_hi - f_lo). The record holds the harmonics of 1/duration in the
//            band, so its variance is S0 N df, within df of S0 (f_hi - f_lo).
//  record:   two-column CSV (time, N) x scale, from `start`; zero outside the record.
//  pulse:    one-cycle sine or cosine of peak `amplitude` over [start, start + period].
class StructureLoad {
 public:
  StructureLoad() = default;
  // `structure` gives M, C, K for the noise scaling; `end_time` the length of the run (s).
  StructureLoad(const StructureSpec& structure, double end_time);
  double at(double t) const;  // N

  StructureLoadType type() const { return spec_.type; }
  double psd_level() const { return psd_level_; }  // noise: S0 of the applied force, N^2/Hz
  const std::optional<NoiseScaling>& scaling() const { return scaling_; }  // noise with target_peak_mg

 private:
  StructureLoadSpec spec_;
  std::shared_ptr<const TimeSeries> series_;  // noise or record, N
  std::optional<NoiseScaling> scaling_;
  double psd_level_ = 0.0;
};

// The noise load's spectral level S0 of the applied force (N^2/Hz) and, with target_peak_mg,
// the predicted response of the structure alone (0 and nullopt for another load).
struct NoiseLoadLevel {
  double psd_level = 0.0;  // N^2/Hz
  std::optional<NoiseScaling> scaling;
};
NoiseLoadLevel noise_load_level(const StructureSpec& structure);

// The structure in time, coupled to the fluid of one 2D tank section standing for `tanks`
// tanks of width `tank_width`. The state is relative to the ground; without ground motion
// relative = absolute.
class StructureCoupling {
 public:
  StructureCoupling(const StructureSpec& spec, double end_time);

  // The liquid mass per metre of tank width that moves with the tank (kg/m): sets the added
  // mass n b (m_w + m_r) and recomputes the acceleration at the current time. Call before
  // start() and whenever fluid particles leave the tank.
  void set_fluid_mass(double fluid_mass_per_width);

  // The state at t = 0: initial displacement and velocity, F_e(0), ground acceleration a_g(0).
  void start(double ground_acceleration);

  // Advances by dt with the sloshing force per metre of tank width F_sw of the last fluid step
  // (N/m; the force of the walls on the fluid minus m_w A) and the ground acceleration at the
  // END of the step (m/s^2).
  void advance(double dt, double sloshing_force_per_width, double ground_acceleration_end);

  double time() const { return sdof_.time(); }
  double displacement() const { return sdof_.displacement(); }  // m, relative to the ground
  double velocity() const { return sdof_.velocity(); }          // m/s, relative
  double absolute_acceleration() const { return sdof_.absolute_acceleration(); }  // m/s^2
  double external_force() const { return external_force_; }    // N, F_e at the current time

  // Force of all tanks on the structure (N) when the walls push the fluid with F_w (N/m) and
  // the tank accelerates at A (absolute): -n b (F_w + m_r A).
  double tld_force(double wall_force_per_width, double tank_acceleration) const;
  // n b: multiplies a 2D quantity per metre of tank width to give the bank of tanks.
  double tank_factor() const { return static_cast<double>(spec_.tanks) * spec_.tank_width; }
  // (M v^2 + K x^2) / 2 of the structure alone (without the liquid's added mass), J.
  double structure_energy() const;

  const StructureSpec& spec() const { return spec_; }
  const StructureLoad& load() const { return load_; }
  const Sdof& sdof() const { return sdof_; }
  // Checkpoints: the SDOF and the force history of the extrapolation.
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  StructureSpec spec_;
  StructureLoad load_;
  Sdof sdof_;
  double external_force_ = 0.0;
  // The sloshing force history for the extrapolation in advance().
  double last_dt_ = 0.0;
  double previous_force_ = 0.0, previous_force_time_ = 0.0;
  bool has_force_history_ = false;
};

}  // namespace sloshsph
