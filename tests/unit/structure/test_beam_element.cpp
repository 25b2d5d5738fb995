// Element-level checks of the geometrically exact beam element (beam_element.hpp) and of the load
// helpers (beam_loads.hpp): derivatives against central finite differences, invariance under rigid
// motions, and the exactness of the discrete gradient used by the energy-conserving integrator.
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/structure/banded_lu.hpp"
#include "sloshsph/structure/beam_element.hpp"
#include "sloshsph/structure/beam_loads.hpp"

namespace sloshsph {
namespace {

const BeamElementGeometry kGeometry{0.05, 0.3};
const SectionStiffness kSection{2.0e5, 7.0e4, 3.0};

BeamElementState state_of(const BeamElementVector& q) {
  return {{q[3] - q[0], q[4] - q[1]}, q[2], q[5]};
}

double energy_of(const BeamElementVector& q) {
  return beam_element_response(kGeometry, kSection, beam_element_kinematics(kGeometry, state_of(q))).strain_energy;
}

BeamElementVector force_of(const BeamElementVector& q) {
  return beam_element_response(kGeometry, kSection, beam_element_kinematics(kGeometry, state_of(q))).internal_force;
}

// A deformed state with a large rotation (0.7 rad) and large strains (~5 %, so that every term of the
// geometric stiffness, some of which are products of two strains, is visible to the check).
BeamElementVector sample_state() {
  BeamElementVector q;
  const double rot = 0.7;
  const Vec2 d0{kGeometry.length * std::cos(kGeometry.angle), kGeometry.length * std::sin(kGeometry.angle)};
  const Vec2 d_rot{std::cos(rot) * d0.x - std::sin(rot) * d0.y, std::sin(rot) * d0.x + std::cos(rot) * d0.y};
  const Vec2 du = 1.05 * d_rot - d0 + Vec2{2e-3, -3e-3};
  q << 0.01, -0.02, rot - 0.04, 0.01 + du.x, -0.02 + du.y, rot + 0.06;
  return q;
}

// Reference: central differences, step 1e-7 (truncation negligible, round-off ~1e-10 of the largest
// entry); tolerance 1e-7 (force) and 1e-8 (tangents) of the largest entry, tight enough to see the
// geometric stiffness, which is ~1e-4 of the largest (axial) entry here.
TEST(BeamElement, InternalForceIsTheEnergyGradient) {
  const BeamElementVector q = sample_state();
  const BeamElementVector f = force_of(q);
  for (int i = 0; i < 6; ++i) {
    const double h = 1e-7;
    BeamElementVector qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    const double numeric = (energy_of(qp) - energy_of(qm)) / (2 * h);
    EXPECT_NEAR(f[i], numeric, 1e-7 * f.cwiseAbs().maxCoeff()) << "dof " << i;
  }
}

TEST(BeamElement, TangentIsTheForceJacobian) {
  const BeamElementVector q = sample_state();
  const auto response = beam_element_response(kGeometry, kSection, beam_element_kinematics(kGeometry, state_of(q)));
  const double scale = response.tangent.cwiseAbs().maxCoeff();
  for (int j = 0; j < 6; ++j) {
    const double h = 1e-7;
    BeamElementVector qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    const BeamElementVector column = (force_of(qp) - force_of(qm)) / (2 * h);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(response.tangent(i, j), column[i], 1e-8 * scale) << i << "," << j;
  }
}

// Objectivity (Simo & Vu-Quoc 1986): a rigid rotation by any angle produces no strain.
TEST(BeamElement, RigidRotationIsStrainFree) {
  for (const double angle : {0.3, 1.5, 3.0, -2.2}) {
    const Vec2 d0{kGeometry.length * std::cos(kGeometry.angle), kGeometry.length * std::sin(kGeometry.angle)};
    const Vec2 d{std::cos(angle) * d0.x - std::sin(angle) * d0.y, std::sin(angle) * d0.x + std::cos(angle) * d0.y};
    const auto kin = beam_element_kinematics(kGeometry, {d - d0, angle, angle});
    EXPECT_NEAR(kin.strain.norm(), 0.0, 1e-14) << angle;
  }
}

// Exact discrete gradient: f_alg . (q1 - q0) = U1 - U0 to round-off, for a large step (0.5 rad).
TEST(BeamElement, MidpointForceWorkEqualsEnergyChange) {
  const BeamElementVector q0 = sample_state();
  BeamElementVector q1 = q0;
  q1 += (BeamElementVector() << 0.003, 0.011, 0.5, -0.004, 0.02, 0.52).finished();
  const auto r = beam_element_midpoint_response(kGeometry, kSection, state_of(q0), state_of(q1), 0.0);
  const double work = r.elastic_force.dot(q1 - q0);
  const double change = energy_of(q1) - energy_of(q0);
  EXPECT_NEAR(work, change, 1e-10 * std::abs(change));
  EXPECT_NEAR(r.strain_energy, energy_of(q1), 1e-14 * energy_of(q1));
}

// The midpoint tangent (with the damping term) is the Jacobian with respect to q1; same FD reference
// and tolerance as above.
TEST(BeamElement, MidpointTangentIsTheJacobian) {
  const BeamElementVector q0 = sample_state();
  BeamElementVector q1 = q0;
  q1 += (BeamElementVector() << 0.001, 0.004, 0.2, -0.002, 0.006, 0.23).finished();
  const double damping_over_dt = 0.3;
  auto total = [&](const BeamElementVector& q) {
    const auto r = beam_element_midpoint_response(kGeometry, kSection, state_of(q0), state_of(q), damping_over_dt);
    return BeamElementVector(r.elastic_force + r.damping_force);
  };
  const auto r = beam_element_midpoint_response(kGeometry, kSection, state_of(q0), state_of(q1), damping_over_dt);
  const double scale = r.tangent.cwiseAbs().maxCoeff();
  for (int j = 0; j < 6; ++j) {
    const double h = 1e-7;
    BeamElementVector qp = q1, qm = q1;
    qp[j] += h;
    qm[j] -= h;
    const BeamElementVector column = (total(qp) - total(qm)) / (2 * h);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(r.tangent(i, j), column[i], 1e-8 * scale) << i << "," << j;
  }
}

// For a vanishing step the midpoint force tends to the exact gradient.
TEST(BeamElement, MidpointForceTendsToInternalForce) {
  const BeamElementVector q = sample_state();
  BeamElementVector q1 = q;
  q1[2] += 1e-9;
  const auto r = beam_element_midpoint_response(kGeometry, kSection, state_of(q), state_of(q1), 0.0);
  const BeamElementVector f = force_of(q);
  EXPECT_LT((r.elastic_force - f).cwiseAbs().maxCoeff(), 1e-6 * f.cwiseAbs().maxCoeff());
}

// Consistent nodal forces of a linear line load (exact integrals of N_i q): totals and first moment.
TEST(BeamLoadsHelper, LineLoadTotalsAndCentroid) {
  const std::vector<Vec2> nodes{{0, 0}, {0.5, 0}, {1.5, 0}};
  // q(x) = (0, -(1 + x)): total -(x + x^2/2) on [0, 1.5] = -2.625, first moment -(x^2/2 + x^3/3) = -2.25.
  const std::vector<Vec2> q{{0, -1.0}, {0, -1.5}, {0, -2.5}};
  const auto f = line_load_nodal_forces(nodes, q);
  double total = 0.0, moment = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    total += f[i].y;
    moment += f[i].y * nodes[i].x;
  }
  EXPECT_NEAR(total, -2.625, 1e-14);
  EXPECT_NEAR(moment, -2.25, 1e-14);
}

// Pressure on face +1 of a segment running along +x (director +y) pushes it towards -y; p b L in total.
TEST(BeamLoadsHelper, PressurePushesTheFaceInwards) {
  const std::vector<Vec2> nodes{{0, 0}, {2, 0}};
  const auto plus = pressure_nodal_forces(nodes, {100.0, 100.0}, +1, 0.5);
  EXPECT_NEAR(plus[0].y + plus[1].y, -100.0, 1e-12);
  EXPECT_NEAR(plus[0].x + plus[1].x, 0.0, 1e-12);
  const auto minus = pressure_nodal_forces(nodes, {100.0, 100.0}, -1, 0.5);
  EXPECT_NEAR(minus[0].y + minus[1].y, 100.0, 1e-12);
  EXPECT_THROW(pressure_nodal_forces(nodes, {1.0}, +1, 1.0), InputError);
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// BandedLu against Eigen's dense partial-pivoting LU on an unsymmetric banded matrix whose diagonal is
// small, so that row interchanges are needed. Reference: the dense solution; tolerance 1e-12 relative.
TEST(BandedLu, MatchesDenseLuWithPivoting) {
  const int n = 40, lower = 5, upper = 5;
  BandedLu banded(n, lower, upper);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - lower); j <= std::min(n - 1, i + upper); ++j) {
      const double value = (i == j) ? 1e-3 : std::sin(1.0 + 7.0 * i + 3.0 * j);
      banded.add(i, j, value);
      dense(i, j) = value;
    }
  }
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) rhs[i] = std::cos(0.3 * i);
  const Eigen::VectorXd expected = dense.partialPivLu().solve(rhs);
  ASSERT_TRUE(banded.factorize());
  Eigen::VectorXd x = rhs;
  banded.solve(x);
  EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm());
  EXPECT_THROW(banded.add(0, 6, 1.0), std::out_of_range);
}

}  // namespace
}  // namespace sloshsph
