#pragma once
// Single-degree-of-freedom structure: the building's fundamental sway mode (thesis sec. 4.2.3,
// eq. 4.20: M_s x'' + C_s x' + K_s x = F_e + F_TLD; Sun et al. 1992), integrated in time by
// Newmark's average acceleration method.
#include <string>

#include "sloshsph/core/state_io.hpp"

namespace sloshsph {

struct SdofSpec {
  double mass = 0.0;       // M_s, kg (generalised mass)
  double damping = 0.0;    // C_s, N s/m
  double stiffness = 0.0;  // K_s, N/m

  // From the mass, the natural frequency (Hz) and the damping ratio: K = M w_n^2, C = 2 zeta M w_n.
  static SdofSpec from_frequency(double mass, double natural_frequency_hz, double zeta);

  double angular_frequency() const;  // w_n = sqrt(K / M), rad/s
  double natural_frequency() const;  // f_n = w_n / (2 pi), Hz
  double damping_ratio() const;      // zeta = C / (2 sqrt(K M))

  // Steady-state displacement amplitude under F0 sin(omega t) (closed form):
  //   X = (F0 / K) / sqrt((1 - r^2)^2 + (2 zeta r)^2),  r = omega / w_n.
  double closed_form_steady_amplitude(double force_amplitude, double omega) const;
};

// Throws InputError(where, key_prefix + ".mass" / ".damping" / ".stiffness", ...) unless M > 0,
// K > 0, C >= 0 and all are finite.
void check_sdof_spec(const SdofSpec& spec, const std::string& where, const std::string& key_prefix);

// The SDOF in time. The state (x, v, a) is RELATIVE to the ground; with a ground acceleration a_g
// the equation is (M + m_a) x'' + C x' + K x = F - (M + m_a) a_g, and the absolute acceleration
// is x'' + a_g. Without ground motion (thesis 4.4.2: force excitation) relative = absolute.
//
// Time integration: Newmark's average acceleration method (gamma = 1/2, beta = 1/4; Newmark 1959),
//   x_n+1 = x_n + dt v_n + dt^2/4 (a_n + a_n+1),  v_n+1 = v_n + dt/2 (a_n + a_n+1),
// with a_n+1 from the equation of motion at t_n+1 (implicit: one division per step for the
// linear SDOF). It is unconditionally stable, second-order accurate, and adds no numerical
// damping: for linear free vibration the energy (M v^2 + K x^2)/2 is conserved exactly (the
// method is the trapezoidal rule); the only error is a period elongation ~ (w_n dt)^2 / 12.
// Discrete energy balance (exact to rounding): E_n+1 - E_n = dt vbar (Fbar_eff - C vbar), with
// vbar, Fbar_eff the step averages; dissipated_energy() and input_work() accumulate the two terms.
//
// Added mass m_a (set_added_mass): a mass moving rigidly with the structure, treated implicitly.
// A TLD coupling can put the liquid mass m_w here and pass only the sloshing force
// F_sw = F_w - m_w x''_abs (thesis 2.6.3.1) as external force, which avoids the lag of feeding back
// the whole base shear from the previous step.
class Sdof {
 public:
  explicit Sdof(const SdofSpec& spec);

  const SdofSpec& spec() const { return spec_; }
  double closed_form_steady_amplitude(double force_amplitude, double omega) const {
    return spec_.closed_form_steady_amplitude(force_amplitude, omega);
  }

  // Sets the added mass and recomputes the acceleration at the current time.
  void set_added_mass(double added_mass);
  double added_mass() const { return added_mass_; }

  // Sets x, v and the acceleration that satisfies the equation of motion with the given force and
  // ground acceleration at the current time (the constructor starts at rest with zero force).
  void set_state(double x, double v, double external_force = 0.0, double ground_acceleration = 0.0);

  // Advances by dt; `external_force` (N) and `ground_acceleration` (m/s^2) are their values at the
  // END of the step, t + dt (Newmark enforces the equation of motion there).
  void step(double dt, double external_force, double ground_acceleration = 0.0);

  double time() const { return time_; }
  double displacement() const { return x_; }   // m, relative to the ground
  double velocity() const { return v_; }       // m/s, relative
  double acceleration() const { return a_; }   // m/s^2, relative
  double absolute_acceleration() const { return a_ + ground_acceleration_; }

  // (M + m_a) v^2 / 2 + K x^2 / 2 (relative motion), J.
  double mechanical_energy() const;
  double dissipated_energy() const { return dissipated_; }  // sum of dt C vbar^2, J
  double input_work() const { return input_work_; }         // sum of dt vbar Fbar_eff, J
  // Checkpoints: the whole state (time, x, v, a, forces, added mass, energy sums).
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  double total_mass() const { return spec_.mass + added_mass_; }

  SdofSpec spec_;
  double added_mass_ = 0.0;
  double time_ = 0.0;
  double x_ = 0.0, v_ = 0.0, a_ = 0.0;
  double external_force_ = 0.0;  // F at the current time
  double force_eff_ = 0.0;       // F - (M + m_a) a_g at the current time
  double ground_acceleration_ = 0.0;
  double dissipated_ = 0.0;
  double input_work_ = 0.0;
};

}  // namespace sloshsph
