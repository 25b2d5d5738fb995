#pragma once
// The sub-particle-scale (SPS) turbulence closure shared by both schemes: from the velocity
// gradient to the turbulent stress tau / rho.
//   S = (grad u + grad u^T) / 2,  |S| = sqrt(2 S:S),  nu_t = l^2 |S|            (Smagorinsky)
//   k_t = (nu_t / (Ct dp))^2,  tau / rho = 2 nu_t S - 2/3 k_t I
// ISPH: thesis eqs. 2.8-2.9 with l = Cs dp. WCSPH: Shao et al. (2012) eqs. 21-23 with l = Cs h and
// no k_t ("smagorinsky"), or the thesis's SPS closure ("sps").
#include <cmath>

#include "sloshsph/sph/operators.hpp"

namespace sloshsph {

// A symmetric tensor (the turbulent stress tau / rho): 3 components in 2D, 6 in 3D.
template <int D>
struct SymTensor;
template <>
struct SymTensor<2> {
  double xx = 0.0, xy = 0.0, yy = 0.0;
};
template <>
struct SymTensor<3> {
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
};
using SymTensor2 = SymTensor<2>;
using SymTensor3 = SymTensor<3>;

// (a + b) r: the pair term of the stress divergence sum_j V (tau_i + tau_j) . grad_i W_ij.
inline Vec2 sum_times(const SymTensor2& a, const SymTensor2& b, Vec2 r) {
  const double sxx = a.xx + b.xx, sxy = a.xy + b.xy, syy = a.yy + b.yy;
  return {sxx * r.x + sxy * r.y, sxy * r.x + syy * r.y};
}
inline Vec3 sum_times(const SymTensor3& a, const SymTensor3& b, Vec3 r) {
  const double sxx = a.xx + b.xx, sxy = a.xy + b.xy, sxz = a.xz + b.xz;
  const double syy = a.yy + b.yy, syz = a.yz + b.yz, szz = a.zz + b.zz;
  return {sxx * r.x + sxy * r.y + sxz * r.z, sxy * r.x + syy * r.y + syz * r.z, sxz * r.x + syz * r.y + szz * r.z};
}

struct SpsClosure {
  double mixing_length2 = 0.0;  // l^2, m^2
  double ct_dp = 0.0;           // Ct dp, m; 0: no turbulent kinetic energy term
};

// tau / rho of one particle (m^2/s^2); its eddy viscosity nu_t (m^2/s) in `nu_t`.
inline SymTensor2 sps_stress_of(const VelocityGradient& g, const SpsClosure& c, double& nu_t) {
  const double sxy = 0.5 * (g.c[0][1] + g.c[1][0]);
  const double s_mag = std::sqrt(2.0 * (g.c[0][0] * g.c[0][0] + g.c[1][1] * g.c[1][1] + 2.0 * sxy * sxy));
  nu_t = c.mixing_length2 * s_mag;
  const double kt = c.ct_dp > 0.0 ? (nu_t / c.ct_dp) * (nu_t / c.ct_dp) : 0.0;
  return {2.0 * nu_t * g.c[0][0] - 2.0 / 3.0 * kt, 2.0 * nu_t * sxy, 2.0 * nu_t * g.c[1][1] - 2.0 / 3.0 * kt};
}

inline SymTensor3 sps_stress_of(const BasicVelocityGradient<3>& g, const SpsClosure& c, double& nu_t) {
  const double sxy = 0.5 * (g.c[0][1] + g.c[1][0]), sxz = 0.5 * (g.c[0][2] + g.c[2][0]);
  const double syz = 0.5 * (g.c[1][2] + g.c[2][1]);
  const double diagonal = g.c[0][0] * g.c[0][0] + g.c[1][1] * g.c[1][1] + g.c[2][2] * g.c[2][2];
  const double s_mag = std::sqrt(2.0 * (diagonal + 2.0 * (sxy * sxy + sxz * sxz + syz * syz)));
  nu_t = c.mixing_length2 * s_mag;
  const double kt = c.ct_dp > 0.0 ? (nu_t / c.ct_dp) * (nu_t / c.ct_dp) : 0.0;
  const double iso = 2.0 / 3.0 * kt;
  return {2.0 * nu_t * g.c[0][0] - iso, 2.0 * nu_t * sxy,          2.0 * nu_t * sxz,
          2.0 * nu_t * g.c[1][1] - iso, 2.0 * nu_t * syz,          2.0 * nu_t * g.c[2][2] - iso};
}

}  // namespace sloshsph
