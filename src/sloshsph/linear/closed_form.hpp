#pragma once
// Closed-form first sloshing frequencies used by the thesis (chapter 3, Tables 3.2-3.10),
// one function per tank shape, and a dispatcher on TankSpec.
//
// Most are long-wave (shallow-water) approximations of Deng & Tait (2009, J. Vib. Acoust.
// 131:041014): the wave length is assumed much larger than the depth, so they overestimate
// omega_1 as the depth grows (linear/modal.hpp gives the exact linear potential-flow value).
#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

// Flat bottom, long-wave limit of eq. 4.29: omega_1 = (pi / L) sqrt(g h) (thesis eq. 3.29).
double flat_long_wave_omega(double length, double depth, double gravity);

// V bottom (slopes meeting at the lowest point), long-wave theory: the surface elevation
// is J0(2 sqrt(kappa x)) and the antisymmetric mode has J0 = 0 at the centre, giving
// omega_1^2 = j01^2 g h / L^2 with j01^2 = 5.783 and L the free-surface length (thesis
// eq. 3.32; Tables 3.2, 3.4, 3.8 use L = L_fluid).
double v_bottom_long_wave_omega(double surface_length, double depth, double gravity);

// Trapezoidal bottom (flat part `bottom_width`, slopes at `angle_deg` from the
// horizontal), long-wave theory: Bessel solution on the slopes, sin on the flat part,
// elevation and flux continuous at the toes: J0(z) cos(k b / 2) = J1(z) sin(k b / 2), with
// z = 2 omega sqrt(h / g) / tan(angle) and k = omega / sqrt(g h). It reduces to eq. 3.32
// for b = 0 and to eq. 3.29 for vertical slopes. (Our extension of Deng & Tait 2009.)
double trapezoid_long_wave_omega(double bottom_width, double angle_deg, double depth, double gravity);

// Parabolic bottom y = c x^2, long-wave theory: omega_1^2 = 2 g h / L0^2 with L0 the half
// free-surface length (thesis eq. 3.34). As L0^2 = h / c this is omega_1^2 = 2 g c,
// independent of the depth (Table 3.9: 4.429-4.430 rad/s for c = 1 at every depth).
double parabolic_long_wave_omega(double half_surface_length, double depth, double gravity);

// Circular bottom of radius R filled to h <= R (thesis eq. 3.36, after Deng & Tait 2008,
// Can. J. Civ. Eng. 35:1088). The extracted eq. 3.36,
// omega^2 = [(h/2R)^3.129 + 1.542 (h/2R)] g / R, is garbled: it gives 1.74 rad/s at
// R = 0.5 m, h = 0.1 m where Table 3.10 has 4.526. We use
//   omega_1^2 = (g / R) [1 + kappa ((h/2R)^3.129 + 1.542 (h/2R))],  kappa = 0.2872,
// which keeps the printed terms, has the exact shallow limit omega^2 -> g/R (the circle
// near its bottom is the parabola y = x^2 / 2R, whose long-wave omega^2 is g/R), and with
// kappa fitted to Table 3.10 reproduces its four omega_1 within 0.001 rad/s. (We could not
// find the original paper's formula.) Exact linear theory (linear/modal.hpp) differs from
// this by +0.0% at h/R = 0.2 to +0.6% at h/R = 0.5 and +8% at h = R.
double circular_fit_omega(double radius, double depth, double gravity);

// omega_1 (rad/s) as the thesis computed it for `spec` filled to `depth`:
//   rectangle        eq. 4.29, (pi g / L) tanh(pi h / L) (Tables 3.4, 3.5, 3.7 use it, not eq. 3.29)
//   sloped/triangle  eq. 3.32 with L the free-surface length; trapezoid: the long-wave
//                    extension above (both need the fluid below the vertical walls)
//   parabolic        eq. 3.34 (needs the fluid below the vertical walls)
//   circular         eq. 3.36 as resolved above (needs h <= R)
// Throws InputError (fill.depth) outside these ranges and (tank.shape) for a polyline.
double thesis_closed_form_omega(const TankSpec& spec, double depth, double gravity);

}  // namespace sloshsph
