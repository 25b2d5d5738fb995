#pragma once
// Linear (potential-flow) sloshing of a tank moved horizontally from rest: the modal solution.
//
// Each sloshing mode n of linear/modal.hpp (any section) is an oscillator driven by the base
// acceleration a(t) of the tank (the tank-frame body force is -a, physics/excitation.hpp):
//   q_n'' + 2 zeta_n omega_n q_n' + omega_n^2 q_n = -horizontal_forcing_n a(t),
//   q_n(0) = q_n'(0) = 0,
// and the free surface is eta(x, t) = sum_n q_n(t) surface_eta_n(x) (Faltinsen & Timokha,
// Sloshing, 2009, ch. 5: the linear modal equations; zeta_n an optional modal damping). The
// horizontal force of the walls on the liquid, per metre of width (the base shear F_w of the
// time series), is the rate of the liquid's momentum: F_w = rho A a + rho sum_n q_n''
// surface_moment_n (A the still-water area); its second part is the sloshing force F_sw.
//
// The damping of a clean rectangular tank's mode from the Stokes boundary layers on its walls
// and bottom, and the bulk viscous dissipation, is rectangular_boundary_layer_damping below.
#include <functional>
#include <vector>

#include "sloshsph/linear/modal.hpp"

namespace sloshsph {

struct LinearResponseInput {
  std::vector<SloshingMode> modes;
  std::vector<double> damping;           // zeta_n per mode (a missing entry is 0)
  std::function<double(double)> base_acceleration;  // a(t), m/s^2, horizontal, tank axes
  double density = 1000.0;               // kg/m^3, for the force
  double still_water_area = 0.0;         // m^2, for the force (rigid-body part)
  std::vector<double> gauge_x;           // m, tank coordinates of the elevation gauges
  double end_time = 0.0;                 // s
  double sample_interval = 0.0;          // s, > 0
  // Optional: adds to acceleration[n] the q_n'' of forces that depend on the modal velocities q'
  // (the screens' pressure loss, linear/screen_drag.hpp); empty: a clean tank.
  std::function<void(const std::vector<double>& velocity, std::vector<double>& acceleration)> modal_drag;
};

struct LinearResponse {
  std::vector<double> time;                    // s, 0, dt, 2 dt, ... up to end_time
  std::vector<std::vector<double>> elevation;  // m, [gauge][sample]
  std::vector<double> wall_force;              // N/m, F_w: x-force of the walls on the liquid
  std::vector<double> sloshing_force;          // N/m, F_sw = F_w - rho A a
  double integration_step = 0.0;               // s, the RK4 step used
};

// The modal solution from rest, integrated by the classical fourth-order Runge-Kutta method
// with a step of at most 1/200 of the shortest modal period and of the sample interval (its
// error is then far below any SPH comparison's: ~1e-8 of the amplitude a period).
LinearResponse linear_response_from_rest(const LinearResponseInput& input);

// The elevation of a mode shape at x (linear interpolation between its surface nodes; the end
// values outside them).
double mode_elevation_at(const SloshingMode& mode, double x);

// Damping ratio of sloshing mode n (1, 2, ...) of a clean rectangular tank of length L, still
// depth h, liquid of kinematic viscosity nu, in 2D (no side walls across the width):
//   zeta_n = sqrt(nu / (2 omega)) k tanh(k h) [L/2 + sinh(2 k h)/(2 k) - h] / (L sinh^2(k h))
//            + 2 nu k^2 / omega,                                  k = n pi / L.
// The first term is the mean dissipation of the laminar Stokes layers under the mode's slip
// velocity, (rho/2) sqrt(nu omega / 2) |U|^2 per unit area of bottom and walls (Landau &
// Lifshitz, Fluid Mechanics, par. 24), over 2 omega times the mode's energy rho g L eta0^2 / 4;
// the second the dissipation of the potential flow in the bulk (Lamb, Hydrodynamics, art. 348).
// A clean free surface adds none. In shallow water (k h -> 0) the first term is
// sqrt(nu / (2 omega)) / (2 h), the 2D, clean-surface limit of the formula the TLD literature
// uses after Keulegan (1959) and Miles (1967), (1 + 2h/b + S) sqrt(nu / (2 omega)) / (2 h) with
// the width b -> infinity and the contamination S = 0 (Sun et al. 1992, J. Wind Eng. Ind. Aerodyn. 43).
double rectangular_boundary_layer_damping(double length, double depth, double gravity, double viscosity,
                                          int n = 1);

}  // namespace sloshsph
