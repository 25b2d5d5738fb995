#include "sloshsph/structure/sdof.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {

SdofSpec SdofSpec::from_frequency(double mass, double f_n, double zeta) {
  const double w = 2.0 * std::numbers::pi * f_n;
  return {mass, 2.0 * zeta * mass * w, mass * w * w};
}

double SdofSpec::angular_frequency() const { return std::sqrt(stiffness / mass); }
double SdofSpec::natural_frequency() const { return angular_frequency() / (2.0 * std::numbers::pi); }
double SdofSpec::damping_ratio() const { return damping / (2.0 * std::sqrt(stiffness * mass)); }

double SdofSpec::closed_form_steady_amplitude(double f0, double omega) const {
  const double r = omega / angular_frequency();
  const double a = 1.0 - r * r, b = 2.0 * damping_ratio() * r;
  return (f0 / stiffness) / std::sqrt(a * a + b * b);
}

void check_sdof_spec(const SdofSpec& s, const std::string& where, const std::string& key_prefix) {
  auto key = [&](const char* name) { return key_prefix.empty() ? std::string(name) : key_prefix + "." + name; };
  if (!(s.mass > 0.0) || !std::isfinite(s.mass)) throw InputError(where, key("mass"), "must be a finite mass > 0 (kg)");
  if (!(s.stiffness > 0.0) || !std::isfinite(s.stiffness))
    throw InputError(where, key("stiffness"), "must be a finite stiffness > 0 (N/m)");
  if (!(s.damping >= 0.0) || !std::isfinite(s.damping))
    throw InputError(where, key("damping"), "must be a finite damping >= 0 (N s/m)");
}

Sdof::Sdof(const SdofSpec& spec) : spec_(spec) { check_sdof_spec(spec, "", "structure"); }

void Sdof::set_added_mass(double m) {
  if (!(m >= 0.0) || !std::isfinite(m)) throw std::invalid_argument("SDOF: added mass must be >= 0");
  added_mass_ = m;
  set_state(x_, v_, external_force_, ground_acceleration_);
}

void Sdof::set_state(double x, double v, double external_force, double ground_acceleration) {
  x_ = x;
  v_ = v;
  external_force_ = external_force;
  ground_acceleration_ = ground_acceleration;
  force_eff_ = external_force - total_mass() * ground_acceleration;
  a_ = (force_eff_ - spec_.damping * v_ - spec_.stiffness * x_) / total_mass();
}

void Sdof::step(double dt, double external_force, double ground_acceleration) {
  if (!(dt > 0.0)) throw std::invalid_argument("SDOF: time step must be > 0");
  const double m = total_mass(), c = spec_.damping, k = spec_.stiffness;
  const double force_eff = external_force - m * ground_acceleration;
  // Predictors (the part of x_n+1, v_n+1 known from step n), gamma = 1/2, beta = 1/4.
  const double x_pred = x_ + dt * v_ + 0.25 * dt * dt * a_;
  const double v_pred = v_ + 0.5 * dt * a_;
  const double a_new = (force_eff - c * v_pred - k * x_pred) / (m + 0.5 * dt * c + 0.25 * dt * dt * k);
  const double v_new = v_pred + 0.5 * dt * a_new;
  const double x_new = x_pred + 0.25 * dt * dt * a_new;
  // Discrete energy balance terms (exact for the trapezoidal rule, see header).
  const double v_bar = 0.5 * (v_ + v_new);
  dissipated_ += dt * c * v_bar * v_bar;
  input_work_ += dt * v_bar * 0.5 * (force_eff_ + force_eff);
  x_ = x_new;
  v_ = v_new;
  a_ = a_new;
  force_eff_ = force_eff;
  external_force_ = external_force;
  ground_acceleration_ = ground_acceleration;
  time_ += dt;
}

double Sdof::mechanical_energy() const { return 0.5 * total_mass() * v_ * v_ + 0.5 * spec_.stiffness * x_ * x_; }

void Sdof::save_state(StateWriter& w) const {
  const double state[] = {added_mass_, time_, x_, v_, a_, external_force_, force_eff_, ground_acceleration_,
                          dissipated_, input_work_};
  w.array("sdof.state", std::vector<double>(std::begin(state), std::end(state)));
}

void Sdof::load_state(StateReader& r) {
  const std::vector<double> s = r.array<double>("sdof.state");
  if (s.size() != 10) throw InputError("checkpoint", "", "SDOF state of the wrong size");
  added_mass_ = s[0], time_ = s[1], x_ = s[2], v_ = s[3], a_ = s[4];
  external_force_ = s[5], force_eff_ = s[6], ground_acceleration_ = s[7], dissipated_ = s[8], input_work_ = s[9];
}

}  // namespace sloshsph
