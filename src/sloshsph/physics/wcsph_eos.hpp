#pragma once
// Equation of state and artificial sound speed of the weakly compressible scheme.
#include <algorithm>
#include <cmath>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

// Dincer 2019 eq. 10 (linearised Tait): p = c0^2 (rho - rho0). (Shao et al. 2012 eq. 7 prints
// p = c^2 rho, which differs by the constant c^2 rho0: it gives the same pressure gradient but
// a fluid at rest under p = c^2 rho0 everywhere, and free surfaces that do not see p = 0.)
inline double eos_pressure(double rho, double rho0, double c0) { return c0 * c0 * (rho - rho0); }

// The inverse of eos_pressure: the density that carries pressure p.
inline double eos_density(double p, double rho0, double c0) { return rho0 + p / (c0 * c0); }

struct SoundSpeedEstimate {
  double bulk_velocity = 0.0;  // u_b, m/s
  double length = 0.0;         // l, m
  double force = 0.0;          // F, m/s^2 (body force per unit mass)
  double viscosity = 0.0;      // nu, m^2/s
  double variation = 0.0;      // Delta rho / rho0
  double c0 = 0.0;             // m/s
};

// Morris et al. 1997 estimate (Shao eq. 9, Dincer eq. 13):
//   c0^2 = max(u_b^2 / delta, nu u_b / (l delta), F l / delta),   delta = Delta rho / rho0,
// the three terms keep the density variation from the flow speed, from viscous stresses and
// from the body force (hydrostatic head) below delta. (Dincer's extracted eq. 13 writes the
// viscous term as mu u_b / (rho l) rho0 / Delta rho: the same.)
inline double morris_sound_speed(double u_b, double nu, double l, double F, double delta) {
  const double c2 = std::max({u_b * u_b / delta, nu * u_b / (l * delta), F * l / delta});
  return std::sqrt(c2);
}

// The estimate for a case. The case does not know the flow speed, so u_b = sqrt(2 g H) + X0 omega
// (the speed of a particle falling the head H of the fill, its depth or the top of its highest
// block, plus the base velocity amplitude);
// l = tank length, F = g + X0 omega^2 (gravity plus the base acceleration amplitude).
inline SoundSpeedEstimate estimate_sound_speed(const CaseSpec& spec) {
  SoundSpeedEstimate e;
  const double g = spec.fluid.gravity;
  double base_velocity = 0.0, base_acceleration = 0.0;
  if (spec.excitation.type == ExcitationType::harmonic) {
    base_velocity = spec.excitation.amplitude * spec.excitation.omega;
    base_acceleration = spec.excitation.amplitude * spec.excitation.omega * spec.excitation.omega;
  }
  if (spec.excitation_y && spec.excitation_y->type == ExcitationType::harmonic) {  // 3D: both added, an upper bound
    const ExcitationSpec& y = *spec.excitation_y;
    base_velocity += y.amplitude * y.omega;
    base_acceleration += y.amplitude * y.omega * y.omega;
  }
  e.bulk_velocity = std::sqrt(2.0 * g * fill_head(spec.fill)) + std::abs(base_velocity);
  e.length = spec.tank.length;
  e.force = std::abs(g) + std::abs(base_acceleration);
  e.viscosity = spec.fluid.viscosity;
  e.variation = spec.scheme.wcsph.max_density_variation;
  e.c0 = morris_sound_speed(e.bulk_velocity, e.viscosity, e.length, e.force, e.variation);
  return e;
}

// The sound speed the scheme uses: WcsphSpec::sound_speed when given (> 0), else the estimate.
inline double case_sound_speed(const CaseSpec& spec) {
  if (spec.scheme.wcsph.sound_speed > 0.0) return spec.scheme.wcsph.sound_speed;
  return estimate_sound_speed(spec).c0;
}

}  // namespace sloshsph
