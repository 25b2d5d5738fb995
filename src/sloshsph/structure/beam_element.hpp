#pragma once
#include <Eigen/Core>

#include "sloshsph/core/vec2.hpp"

// One two-node geometrically exact plane beam element (Reissner 1972, "On one-dimensional finite-strain
// beam theory: the plane problem", ZAMP 23; Simo & Vu-Quoc 1986, "On the dynamics of flexible beams under
// large overall motions - the plane case", J. Appl. Mech. 53).
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
//
// The element state is given as displacements from the initial configuration (d = d0 + u2 - u1)
// so that the small strains are not computed as differences of large coordinates.
namespace sloshsph {

// Element DOF order: u1x, u1y, theta1, u2x, u2y, theta2.
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

// Deformation of one element: relative displacement of its ends and the two nodal rotations.
struct BeamElementState {
  Vec2 relative_displacement{};  // u2 - u1 [m]
  double theta1 = 0.0;           // [rad] from the initial configuration
  double theta2 = 0.0;
};

// Strains (Gamma1, Gamma2, kappa), their first derivatives B (3 x 6) and second derivatives.
struct BeamElementKinematics {
  Eigen::Vector3d strain;
  Eigen::Matrix<double, 3, 6> b_matrix;
  BeamElementMatrix hessian[3];  // d^2 strain_k / dq^2
};

BeamElementKinematics beam_element_kinematics(const BeamElementGeometry& geometry, const BeamElementState& state);

// Internal force f = dU/dq and tangent K = d^2U/dq^2 (material + geometric parts).
struct BeamElementResponse {
  BeamElementVector internal_force = BeamElementVector::Zero();
  BeamElementMatrix tangent = BeamElementMatrix::Zero();
  BeamElementMatrix material_tangent = BeamElementMatrix::Zero();  // L0 B^T D B
  double strain_energy = 0.0;
};

BeamElementResponse beam_element_response(const BeamElementGeometry& geometry, const SectionStiffness& section,
                                          const BeamElementKinematics& kinematics);

// Energy-conserving midpoint forces over a time step from state 0 to state 1 (the discrete-gradient
// idea of Simo & Tarnow 1992, ZAMP 43, "The discrete energy-momentum method", applied to the
// Reissner strains). The algorithmic strain derivative B_alg(q0, q1) satisfies exactly
//   B_alg (q1 - q0) = strain(q1) - strain(q0),
// using d1.t1 - d0.t0 = (d1 - d0).tbar + dbar.(t1 - t0) and t1 - t0 = 2 sin(dbeta/2) n(beta_mid).
// Elastic force  L0 B_alg^T D (strain0 + strain1)/2: its work over the step equals U1 - U0 exactly.
// Damping force  L0 B_alg^T (b1/dt) D (strain1 - strain0): stiffness-proportional Rayleigh damping
// on the strain rates, whose work over the step is >= 0. Both reduce to B^T D strain (+ b1 K v) for
// small steps. `tangent` is the exact derivative of the sum with respect to q1.
struct BeamElementMidpointResponse {
  BeamElementVector elastic_force = BeamElementVector::Zero();
  BeamElementVector damping_force = BeamElementVector::Zero();
  BeamElementMatrix tangent = BeamElementMatrix::Zero();
  double strain_energy = 0.0;  // at state 1
};

BeamElementMidpointResponse beam_element_midpoint_response(const BeamElementGeometry& geometry,
                                                           const SectionStiffness& section,
                                                           const BeamElementState& state0,
                                                           const BeamElementState& state1,
                                                           double damping_over_dt);

}  // namespace sloshsph
