#pragma once
#include <Eigen/Dense>

#include "sloshsph/core/vec2.hpp"

// One two-node geometrically exact plane beam element (Reissner 1972; Simo & Vu-Quoc 1986,
// "On the dynamics of flexible beams under large overall motions - the plane case", J. Appl. Mech. 53).
//
// Kinematics: the centreline x(s) and the section rotation theta(s) are interpolated linearly;
// the strains are evaluated at the element midpoint only (one-point reduced integration), which
// removes shear locking for thin beams (Crisfield 1991, "Non-linear FE analysis of solids and
// structures", vol. 1, sec. 7.5). With d = x2 - x1, beta = alpha0 + (theta1 + theta2)/2 (alpha0 the
// element's initial angle), t = (cos beta, sin beta) the section normal and n = perp(t) the director:
//   axial strain     Gamma1 = d.t / L0 - 1
//   shear strain     Gamma2 = d.n / L0
//   curvature        kappa  = (theta2 - theta1) / L0
// Stress resultants N = EA Gamma1, V = GAs Gamma2, M = EI kappa; element energy
//   U = L0/2 (EA Gamma1^2 + GAs Gamma2^2 + EI kappa^2).
// The strains are invariant under rigid motions, so large rotations are exact; only the strains
// must stay small (linear elastic resultants).
namespace sloshsph {

// Element DOF order: x1, y1, theta1, x2, y2, theta2.
using BeamElementVector = Eigen::Matrix<double, 6, 1>;
using BeamElementMatrix = Eigen::Matrix<double, 6, 6>;

// Section stiffnesses (per beam, i.e. already multiplied by the out-of-plane width).
struct SectionStiffness {
  double axial = 0.0;    // EA [N]
  double shear = 0.0;    // k G A [N]
  double bending = 0.0;  // EI [N m^2]
};

// Undeformed element: initial length and initial angle of its axis.
struct BeamElementGeometry {
  double length = 0.0;  // L0 [m]
  double angle = 0.0;   // alpha0 [rad]
};

// Strains (Gamma1, Gamma2, kappa), their first derivatives B (3 x 6) and second derivatives.
struct BeamElementKinematics {
  Eigen::Vector3d strain;
  Eigen::Matrix<double, 3, 6> b_matrix;
  BeamElementMatrix hessian[3];  // d^2 strain_k / dq^2
};

BeamElementKinematics beam_element_kinematics(const BeamElementGeometry& geometry, Vec2 x1, double theta1,
                                              Vec2 x2, double theta2);

// Internal force f = dU/dq and tangent K = d^2U/dq^2 (material + geometric parts).
struct BeamElementResponse {
  BeamElementVector internal_force = BeamElementVector::Zero();
  BeamElementMatrix tangent = BeamElementMatrix::Zero();
  BeamElementMatrix material_tangent = BeamElementMatrix::Zero();  // L0 B^T D B
  double strain_energy = 0.0;
};

BeamElementResponse beam_element_response(const BeamElementGeometry& geometry, const SectionStiffness& section,
                                          const BeamElementKinematics& kinematics);

}  // namespace sloshsph
