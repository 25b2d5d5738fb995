#include "sloshsph/structure/beam_element.hpp"

#include <cmath>

namespace sloshsph {

namespace {

constexpr int kX1 = 0, kY1 = 1, kTheta1 = 2, kX2 = 3, kY2 = 4, kTheta2 = 5;

// Sets the symmetric (position, rotation) block of a strain Hessian: d^2/dx2 dtheta_i = g,
// d^2/dx1 dtheta_i = -g, for both rotations (each enters beta with weight 1/2).
void set_position_rotation_block(BeamElementMatrix& h, Vec2 g) {
  for (const int rot : {kTheta1, kTheta2}) {
    h(kX2, rot) = h(rot, kX2) = g.x;
    h(kY2, rot) = h(rot, kY2) = g.y;
    h(kX1, rot) = h(rot, kX1) = -g.x;
    h(kY1, rot) = h(rot, kY1) = -g.y;
  }
}

void set_rotation_block(BeamElementMatrix& h, double value) {
  h(kTheta1, kTheta1) = h(kTheta1, kTheta2) = h(kTheta2, kTheta1) = h(kTheta2, kTheta2) = value;
}

}  // namespace

BeamElementKinematics beam_element_kinematics(const BeamElementGeometry& geometry, const BeamElementState& state) {
  const double inv_length = 1.0 / geometry.length;
  const double mean_rotation = 0.5 * (state.theta1 + state.theta2);
  const double beta = geometry.angle + mean_rotation;
  const Vec2 t{std::cos(beta), std::sin(beta)};  // section normal (beam axis if unsheared)
  const Vec2 n = perp(t);                        // director across the thickness
  const Vec2 du = state.relative_displacement;
  // d = d0 + du with d0 = L0 (cos alpha0, sin alpha0): d0.t = L0 cos(mean_rotation) and
  // d0.n = -L0 sin(mean_rotation); cos - 1 = -2 sin^2(./2) avoids cancellation for small strains.
  const double half_sine = std::sin(0.5 * mean_rotation);
  const double axial = -2.0 * half_sine * half_sine + dot(du, t) * inv_length;
  const double shear = -std::sin(mean_rotation) + dot(du, n) * inv_length;
  const double stretch = 1.0 + axial;

  BeamElementKinematics k;
  k.strain = {axial, shear, (state.theta2 - state.theta1) * inv_length};

  // First derivatives: dt/dbeta = n, dn/dbeta = -t, dbeta/dtheta_i = 1/2.
  k.b_matrix.setZero();
  k.b_matrix.row(0) << -t.x * inv_length, -t.y * inv_length, 0.5 * shear, t.x * inv_length, t.y * inv_length,
      0.5 * shear;
  k.b_matrix.row(1) << -n.x * inv_length, -n.y * inv_length, -0.5 * stretch, n.x * inv_length, n.y * inv_length,
      -0.5 * stretch;
  k.b_matrix.row(2) << 0.0, 0.0, -inv_length, 0.0, 0.0, inv_length;

  for (auto& h : k.hessian) h.setZero();
  set_position_rotation_block(k.hessian[0], (0.5 * inv_length) * n);
  set_rotation_block(k.hessian[0], -0.25 * stretch);
  set_position_rotation_block(k.hessian[1], (-0.5 * inv_length) * t);
  set_rotation_block(k.hessian[1], -0.25 * shear);
  // kappa is linear in q: zero Hessian.
  return k;
}

BeamElementResponse beam_element_response(const BeamElementGeometry& geometry, const SectionStiffness& section,
                                          const BeamElementKinematics& kinematics) {
  const Eigen::Vector3d stiffness{section.axial, section.shear, section.bending};
  const Eigen::Vector3d resultants = stiffness.cwiseProduct(kinematics.strain);  // N, V, M
  const double l0 = geometry.length;

  BeamElementResponse r;
  r.internal_force = l0 * kinematics.b_matrix.transpose() * resultants;
  r.material_tangent = l0 * kinematics.b_matrix.transpose() * stiffness.asDiagonal() * kinematics.b_matrix;
  r.tangent = r.material_tangent;
  for (int k = 0; k < 2; ++k) r.tangent += (l0 * resultants[k]) * kinematics.hessian[k];  // geometric stiffness
  r.strain_energy = 0.5 * l0 * kinematics.strain.dot(resultants);
  return r;
}

}  // namespace sloshsph

namespace sloshsph {

namespace {

// sin(x)/x and its derivative, with series near 0.
double sinc(double x) { return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }
double sinc_derivative(double x) {
  return std::abs(x) < 1e-3 ? -x / 3.0 + x * x * x / 30.0 : (x * std::cos(x) - std::sin(x)) / (x * x);
}

}  // namespace

BeamElementMidpointResponse beam_element_midpoint_response(const BeamElementGeometry& geometry,
                                                           const SectionStiffness& section,
                                                           const BeamElementState& state0,
                                                           const BeamElementState& state1,
                                                           double damping_over_dt) {
  const double l0 = geometry.length;
  const double inv_length = 1.0 / l0;
  const BeamElementKinematics kin0 = beam_element_kinematics(geometry, state0);
  const BeamElementKinematics kin1 = beam_element_kinematics(geometry, state1);
  const Eigen::Vector3d stiffness{section.axial, section.shear, section.bending};

  const double beta0 = geometry.angle + 0.5 * (state0.theta1 + state0.theta2);
  const double beta1 = geometry.angle + 0.5 * (state1.theta1 + state1.theta2);
  const double half_step = 0.5 * (beta1 - beta0);
  const double beta_mid = 0.5 * (beta0 + beta1);
  const double s = sinc(half_step);
  const double ds = sinc_derivative(half_step);
  const Vec2 t0{std::cos(beta0), std::sin(beta0)};
  const Vec2 t1{std::cos(beta1), std::sin(beta1)};
  const Vec2 t_mid{std::cos(beta_mid), std::sin(beta_mid)};
  const Vec2 n0 = perp(t0), n1 = perp(t1), n_mid = perp(t_mid);
  const Vec2 t_bar = 0.5 * (t0 + t1);
  const Vec2 n_bar = 0.5 * (n0 + n1);
  const Vec2 initial_chord{l0 * std::cos(geometry.angle), l0 * std::sin(geometry.angle)};
  const Vec2 d_bar = initial_chord + 0.5 * (state0.relative_displacement + state1.relative_displacement);
  // t1 - t0 = dbeta * s * n_mid and n1 - n0 = -dbeta * s * t_mid.
  const Vec2 w_t = s * n_mid;
  const Vec2 w_n = s * t_mid;

  Eigen::Matrix<double, 3, 6> b_alg;
  const double rot_axial = 0.5 * dot(d_bar, w_t) * inv_length;
  const double rot_shear = -0.5 * dot(d_bar, w_n) * inv_length;
  b_alg.row(0) << -t_bar.x * inv_length, -t_bar.y * inv_length, rot_axial, t_bar.x * inv_length,
      t_bar.y * inv_length, rot_axial;
  b_alg.row(1) << -n_bar.x * inv_length, -n_bar.y * inv_length, rot_shear, n_bar.x * inv_length,
      n_bar.y * inv_length, rot_shear;
  b_alg.row(2) << 0.0, 0.0, -inv_length, 0.0, 0.0, inv_length;

  const Eigen::Vector3d elastic_stress = stiffness.cwiseProduct(0.5 * (kin0.strain + kin1.strain));
  const Eigen::Vector3d damping_stress = damping_over_dt * stiffness.cwiseProduct(kin1.strain - kin0.strain);
  BeamElementMidpointResponse r;
  r.elastic_force = l0 * b_alg.transpose() * elastic_stress;
  r.damping_force = l0 * b_alg.transpose() * damping_stress;
  r.strain_energy = 0.5 * l0 * kin1.strain.dot(stiffness.cwiseProduct(kin1.strain));

  // Tangent d/dq1: L0 [B_alg^T dstress/dq1 + (dB_alg^T/dq1) stress], dstress/dq1 = (1/2 + b1/dt) D B(q1).
  r.tangent = l0 * b_alg.transpose() * ((0.5 + damping_over_dt) * stiffness).asDiagonal() * kin1.b_matrix;
  const Eigen::Vector3d stress = elastic_stress + damping_stress;
  const double axial_force = stress[0], shear_force = stress[1];
  // Translational rows: h_x2 = (N tbar + V nbar)/L0 depends on beta1 (dtbar/dbeta1 = n1/2, dnbar/dbeta1 = -t1/2).
  const Vec2 dhx2_dbeta = (0.5 * inv_length) * (axial_force * n1 - shear_force * t1);
  // Rotational rows: R = (N dbar.w_t - V dbar.w_n)/(2 L0) depends on d1 (ddbar/dd1 = 1/2) and beta1.
  const Vec2 dr_dd = (0.25 * inv_length) * (axial_force * w_t - shear_force * w_n);
  const Vec2 dwt_dbeta = (0.5 * ds) * n_mid - (0.5 * s) * t_mid;
  const Vec2 dwn_dbeta = (0.5 * ds) * t_mid + (0.5 * s) * n_mid;
  const double dr_dbeta =
      (0.5 * inv_length) * (axial_force * dot(d_bar, dwt_dbeta) - shear_force * dot(d_bar, dwn_dbeta));
  BeamElementMatrix g = BeamElementMatrix::Zero();
  for (const int rot : {2, 5}) {  // dbeta1/dtheta_i = 1/2
    g(3, rot) = 0.5 * dhx2_dbeta.x;
    g(4, rot) = 0.5 * dhx2_dbeta.y;
    g(0, rot) = -0.5 * dhx2_dbeta.x;
    g(1, rot) = -0.5 * dhx2_dbeta.y;
    g(rot, 3) = dr_dd.x;
    g(rot, 4) = dr_dd.y;
    g(rot, 0) = -dr_dd.x;
    g(rot, 1) = -dr_dd.y;
    g(rot, 2) = g(rot, 5) = 0.5 * dr_dbeta;
  }
  r.tangent += l0 * g;
  return r;
}

}  // namespace sloshsph
