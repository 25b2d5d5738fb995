// Static checks of the beam solver (beam.hpp) against closed forms and the elastica.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/structure/beam.hpp"

namespace sloshsph {
namespace {

// The elastic plate of Dincer 2019 (Table 1): 8 cm high, 0.3 cm thick, E = 10 MPa, rubber-like
// (rho = 1100, nu = 0.45), clamped at the bottom, standing vertically. L/t = 26.7.
BeamSpec dincer_plate(int elements) {
  BeamSpec spec;
  spec.start = {0.3, 0.0};
  spec.end = {0.3, 0.08};
  spec.elements = elements;
  spec.thickness = 0.003;
  spec.youngs_modulus = 10e6;
  spec.poisson_ratio = 0.45;
  spec.density = 1100.0;
  return spec;
}

// A slender horizontal beam (L/t = 100) for the large-deflection and clamped-clamped checks, where
// shear and axial flexibility are negligible (Euler-Bernoulli / inextensible elastica references).
BeamSpec slender_beam(int elements) {
  BeamSpec spec;
  spec.start = {0.0, 0.0};
  spec.end = {1.0, 0.0};
  spec.elements = elements;
  spec.thickness = 0.01;
  spec.youngs_modulus = 1e9;
  spec.poisson_ratio = 0.3;
  spec.density = 1000.0;
  return spec;
}

// Test 1a. Reference: Euler-Bernoulli cantilever, tip load P: delta = P L^3 / (3 E I). Tolerance 1 %.
// Load P gives delta/L = 1e-4 (geometrically linear). 20 elements; the model also has shear flexibility
// (Timoshenko), about +0.1 % here, and the O(1/N^2) error of linear elements, about -0.06 %.
TEST(BeamStatic, CantileverTipLoadSmall) {
  Beam beam(dincer_plate(20));
  const double ei = beam.section().bending;
  const double length = 0.08;
  const double load = 1e-4 * 3.0 * ei / (length * length);
  BeamLoads loads = beam.zero_loads();
  loads.nodal_forces.back() = {load, 0.0};
  beam.static_solve(loads);
  const double reference = load * std::pow(length, 3) / (3.0 * ei);
  const double tip = beam.node_displacements().back().x;
  std::printf("cantilever tip load: %.6e m vs P L^3/(3EI) = %.6e m (ratio %.5f)\n", tip, reference, tip / reference);
  EXPECT_NEAR(tip / reference, 1.0, 0.01);
}

// Test 1b. Reference: Euler-Bernoulli cantilever, uniform load q: delta = q L^4 / (8 E I). Tolerance 1 %.
// Applied twice: as consistent nodal forces (line_load_nodal_forces) and as a body acceleration a with
// q = rho b t a (the path the tank-frame inertia load will take).
TEST(BeamStatic, CantileverUniformLoadSmall) {
  const BeamSpec spec = dincer_plate(20);
  Beam beam(spec);
  const double ei = beam.section().bending;
  const double length = 0.08;
  const double q = 1e-4 * 8.0 * ei / std::pow(length, 3);  // delta/L = 1e-4
  const double reference = q * std::pow(length, 4) / (8.0 * ei);

  BeamLoads loads = beam.zero_loads();
  loads.nodal_forces =
      line_load_nodal_forces(beam.initial_positions(), std::vector<Vec2>(beam.initial_positions().size(), {q, 0.0}));
  beam.static_solve(loads);
  const double tip = beam.node_displacements().back().x;

  Beam inertial(spec);
  BeamLoads body = inertial.zero_loads();
  body.body_acceleration = {q / inertial.mass_per_length(), 0.0};
  inertial.static_solve(body);
  const double tip_body = inertial.node_displacements().back().x;
  std::printf("cantilever uniform load: %.6e m (line load), %.6e m (body force) vs q L^4/(8EI) = %.6e m\n", tip,
              tip_body, reference);
  EXPECT_NEAR(tip / reference, 1.0, 0.01);
  EXPECT_NEAR(tip_body / reference, 1.0, 0.01);
}

// Test 2. Reference: the elastica of a cantilever with a vertical dead tip load, Bisshopp & Drucker
// (1945), Q. Appl. Math. 3, 272-275, in the tabulation of Mattiasson (1981), Int. J. Numer. Meth. Eng.
// 17, 145-153: P L^2/(E I) = 1: v/L = 0.30172, (L - x)/L = 0.05643, tip rotation 0.46135 rad;
// P L^2/(E I) = 10: v/L = 0.81061, (L - x)/L = 0.55500, tip rotation 1.43029 rad. (We re-derived the four
// lengths by shooting on theta'' = -lambda cos(theta): 0.301721, 0.056433, 0.810609, 0.554996.)
// Tolerance 1 % on each. 40 elements, 10 load increments.
TEST(BeamStatic, CantileverLargeDeflectionElastica) {
  struct Case {
    double lambda, vertical, horizontal, rotation;
  };
  for (const Case c : {Case{1.0, 0.30172, 0.05643, 0.46135}, Case{10.0, 0.81061, 0.55500, 1.43029}}) {
    Beam beam(slender_beam(40));
    const double ei = beam.section().bending;
    BeamLoads loads = beam.zero_loads();
    loads.nodal_forces.back() = {0.0, -c.lambda * ei};  // L = 1
    const BeamSolveReport report = beam.static_solve(loads, 10);
    const Vec2 tip = beam.node_displacements().back();
    const double rotation = -beam.node_rotations().back();
    std::printf("elastica PL^2/EI = %g: v/L %.5f (%.5f), (L-x)/L %.5f (%.5f), rotation %.5f (%.5f); %d Newton its\n",
                c.lambda, -tip.y, c.vertical, -tip.x, c.horizontal, rotation, c.rotation, report.iterations);
    EXPECT_NEAR(-tip.y / c.vertical, 1.0, 0.01);
    EXPECT_NEAR(-tip.x / c.horizontal, 1.0, 0.01);
    EXPECT_NEAR(rotation / c.rotation, 1.0, 0.01);
  }
}

// Test 6. Reference: Euler-Bernoulli clamped-clamped beam under uniform load q: mid-span deflection
// q L^4 / (384 E I). Tolerance 1 %. Small load (delta/L = 1e-5, membrane stiffening negligible).
// The load is applied (a) as dead consistent nodal forces and (b) as a follower pressure on face +1
// (the upper face: the beam runs along +x, so its director is +y), i.e. a water column above it.
TEST(BeamStatic, ClampedClampedUniformLoad) {
  BeamSpec spec = slender_beam(40);
  spec.end_support = BeamSupport::kClamped;
  Beam beam(spec);
  const double ei = beam.section().bending;
  const double q = 1e-5 * 384.0 * ei;  // L = 1
  const double reference = q / (384.0 * ei);

  BeamLoads loads = beam.zero_loads();
  loads.nodal_forces =
      line_load_nodal_forces(beam.initial_positions(), std::vector<Vec2>(beam.initial_positions().size(), {0.0, -q}));
  beam.static_solve(loads);
  const double mid = -beam.node_displacements()[20].y;

  Beam pressed(spec);
  BeamLoads pressure = pressed.zero_loads();
  pressure.nodal_pressure.assign(pressed.initial_positions().size(), q / spec.width);
  pressure.pressure_side = +1;
  pressed.static_solve(pressure);
  const double mid_pressure = -pressed.node_displacements()[20].y;
  std::printf("clamped-clamped: mid-span %.6e m (dead load), %.6e m (pressure) vs qL^4/(384EI) = %.6e m\n", mid,
              mid_pressure, reference);
  EXPECT_NEAR(mid / reference, 1.0, 0.01);
  EXPECT_NEAR(mid_pressure / reference, 1.0, 0.01);
}

// A follower pressure large enough to bend the plate far (linear estimate tip = 3/8 L): Newton with the
// load stiffness must converge in a few iterations per increment (no reference value: a smoke test).
TEST(BeamStatic, FollowerPressureLargeDeflectionConverges) {
  Beam beam(dincer_plate(20));
  const double ei = beam.section().bending;
  BeamLoads loads = beam.zero_loads();
  const double p = 3.0 * ei / std::pow(0.08, 3);  // linear estimate: tip/L = 3/8
  loads.nodal_pressure.assign(beam.initial_positions().size(), p);
  loads.pressure_side = +1;  // the plate runs along +y, so its director is -x: face +1 faces -x, pushed to +x
  const BeamSolveReport report = beam.static_solve(loads, 5);
  const Vec2 tip = beam.node_displacements().back();
  std::printf("follower pressure: tip (%.5f, %.5f) m after %d Newton iterations\n", tip.x, tip.y, report.iterations);
  EXPECT_LT(report.iterations, 60);
  EXPECT_GT(tip.x, 0.2 * 0.08);
}

// Polyline geometry with a rigid 90-degree joint: an L-frame, column of height a clamped at the bottom,
// arm of length c at the top, vertical tip load P. Reference (Euler-Bernoulli, unit-load method): tip
// deflection P c^3/(3EI) + P c^2 a/(EI) downwards (arm bending + column rotation under the moment P c),
// and the joint moves sideways by P c a^2/(2EI). Tolerance 1 %, 20 + 20 elements, small load.
TEST(BeamStatic, LFrameWithRigidJoint) {
  BeamSpec spec = slender_beam(1);
  const double a = 0.6, c = 0.4;
  spec.node_points.clear();
  for (int i = 0; i <= 20; ++i) spec.node_points.push_back({0.0, a * i / 20.0});
  for (int i = 1; i <= 20; ++i) spec.node_points.push_back({c * i / 20.0, a});
  Beam beam(spec);
  const double ei = beam.section().bending;
  const double p = 1e-5 * ei;
  BeamLoads loads = beam.zero_loads();
  loads.nodal_forces.back() = {0.0, -p};
  beam.static_solve(loads);
  const double tip = -beam.node_displacements().back().y;
  const double sway = beam.node_displacements()[20].x;
  const double tip_reference = p * c * c * c / (3.0 * ei) + p * c * c * a / ei;
  const double sway_reference = p * c * a * a / (2.0 * ei);
  std::printf("L-frame: tip %.6e (%.6e), joint sway %.6e (%.6e)\n", tip, tip_reference, sway, sway_reference);
  EXPECT_NEAR(tip / tip_reference, 1.0, 0.01);
  EXPECT_NEAR(sway / sway_reference, 1.0, 0.01);
}

TEST(BeamStatic, MaterialPointsFollowTheBody) {
  Beam beam(dincer_plate(10));
  BeamLoads loads = beam.zero_loads();
  loads.nodal_forces.back() = {0.05, 0.0};
  beam.static_solve(loads, 4);
  // A point of face +1 at node 4 in the undeformed plate stays on surface(+1).
  const Vec2 reference_point = beam.initial_positions()[4] + Vec2{-0.5 * 0.003, 0.0};
  const BeamMaterialPoint point = beam.material_point(reference_point);
  EXPECT_NEAR(point.offset, 0.0015, 1e-15);
  const Vec2 expected = beam.surface(+1)[4];
  const Vec2 actual = beam.position(point);
  EXPECT_NEAR(actual.x, expected.x, 1e-12);
  EXPECT_NEAR(actual.y, expected.y, 1e-12);
}

TEST(BeamStatic, BadSpecIsAnInputError) {
  BeamSpec spec = dincer_plate(10);
  spec.thickness = 0.0;
  EXPECT_THROW(Beam{spec}, InputError);
  spec = dincer_plate(10);
  spec.poisson_ratio = 0.5;
  EXPECT_THROW(Beam{spec}, InputError);
  spec = dincer_plate(10);
  spec.hht_alpha = -0.5;
  EXPECT_THROW(Beam{spec}, InputError);
  Beam beam(dincer_plate(10));
  BeamLoads loads;
  loads.nodal_forces.assign(3, Vec2{});
  EXPECT_THROW(beam.static_solve(loads), InputError);
}

}  // namespace
}  // namespace sloshsph
