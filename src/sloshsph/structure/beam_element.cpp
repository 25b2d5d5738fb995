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

BeamElementKinematics beam_element_kinematics(const BeamElementGeometry& geometry, Vec2 x1, double theta1,
                                              Vec2 x2, double theta2) {
  const double inv_length = 1.0 / geometry.length;
  const double beta = geometry.angle + 0.5 * (theta1 + theta2);
  const Vec2 t{std::cos(beta), std::sin(beta)};  // section normal (beam axis if unsheared)
  const Vec2 n = perp(t);                        // director across the thickness
  const Vec2 d = x2 - x1;
  const double stretch = dot(d, t) * inv_length;  // 1 + Gamma1

  BeamElementKinematics k;
  k.strain = {stretch - 1.0, dot(d, n) * inv_length, (theta2 - theta1) * inv_length};
  const double shear = k.strain[1];

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
