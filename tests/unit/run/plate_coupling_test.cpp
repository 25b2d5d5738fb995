// Elastic plate coupling (run/plate_coupling) without fluid: face pressures written into the wall
// particles must load the beam as the pressure integral, and the plate must carry its particles.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/run/plate_coupling.hpp"

namespace sloshsph {
namespace {

KeyLocation at(const std::string& where) {
  return [where](const std::string&) { return where; };
}

TankGeometry box(double length, double height) {
  TankSpec s;
  s.shape = "rectangle";
  s.length = length;
  s.height = height;
  return make_tank(s, "test");
}

PlateSpec floor_plate() {
  PlateSpec p;
  p.name = "floor";
  p.from = {0.0, 0.21};
  p.to = {2.0, 0.21};
  p.thickness = 0.06;
  p.youngs_modulus = 1.0e10;
  p.density = 2700.0;
  p.elements = 40;
  p.to_support = PlateSupport::clamped;
  p.rayleigh_mass = 400.0;  // about critical for the first mode: the static state is reached quickly
  return p;
}

// Wall particles only (no fluid), with pressure p0 on the particles whose normal points up.
Particles plate_particles(const PlateLayout& l, double p0) {
  Particles p;
  p.resize(l.walls.size());
  p.n_fluid = 0;
  for (std::size_t k = 0; k < l.walls.size(); ++k) {
    p.position[k] = l.walls[k].position;
    p.normal[k] = l.walls[k].normal;
    p.pressure[k] = l.walls[k].normal.y > 0.5 ? p0 : 0.0;
  }
  p.wall_motion_velocity.assign(p.size(), Vec2{});
  p.wall_motion_acceleration.assign(p.size(), Vec2{});
  return p;
}

// Reference: clamped-clamped beam under a uniform load q, w = q L^4 / (384 E I) plus Timoshenko's
// shear part q L^2 / (8 k G A) (k = 5/6, G = E / (2 (1 + nu))).
double clamped_midspan(const PlateSpec& s, double q) {
  const double L = norm(s.to - s.from), I = std::pow(s.thickness, 3) / 12.0;
  const double G = s.youngs_modulus / (2.0 * (1.0 + s.poisson_ratio));
  return q * std::pow(L, 4) / (384.0 * s.youngs_modulus * I) + q * L * L / (8.0 * 5.0 / 6.0 * G * s.thickness);
}

double settle_midspan(PlateCoupling& plate, Particles& p, double p0) {
  const FrameForce no_gravity{};
  for (int step = 0; step < 3000; ++step) {
    for (std::size_t w = 0; w < p.size(); ++w) p.pressure[w] = p.normal[w].y > 0.5 ? p0 : 0.0;
    plate.fluid_force(p, no_gravity, 1000.0);
    plate.advance(p, 1.0e-3, no_gravity);
  }
  return plate.displacement_at(0.5).y;
}

TEST(PlateCoupling, FacePressureIsThePressureIntegral) {
  const PlateLayout l = plate_layout(floor_plate(), 0.02, 2.66 * 0.02, box(2.0, 1.6), at("test"), "plates.0");
  PlateCoupling plate(l, 0);
  Particles p = plate_particles(l, 9810.0);
  const Vec2 f = plate.fluid_force(p, FrameForce{}, 1000.0);
  EXPECT_NEAR(f.y, -9810.0 * 2.0, 1e-9);  // p0 times the 2 m upper face, pushing down
  EXPECT_NEAR(f.x, 0.0, 1e-9);
  // With gravity the wall pressure is carried from the particle (dp/2 inside) up to the face; the
  // lower face has no fluid (wall pressure 0) and carries nothing.
  FrameForce g;
  g.uniform = {0.0, -9.81};
  const Vec2 fg = plate.fluid_force(p, g, 1000.0);
  EXPECT_NEAR(fg.y, -(9810.0 - 1000.0 * 9.81 * 0.01) * 2.0, 1e-9);
}

TEST(PlateCoupling, UniformFaceLoadGivesTheClampedBeamDeflection) {
  {
    const PlateSpec spec = floor_plate();
    const PlateLayout l = plate_layout(spec, 0.02, 2.66 * 0.02, box(2.0, 1.6), at("test"), "plates.0");
    PlateCoupling plate(l, 0);
    Particles p = plate_particles(l, 9810.0);
    const double w = settle_midspan(plate, p, 9810.0);
    const double reference = clamped_midspan(spec, 9810.0);
    EXPECT_NEAR(-w / reference, 1.0, 0.01);  // 1%: beam FEM and load transfer
    // The particles follow the plate: the mid-span particles moved down with it, at rest.
    double lowest = 1.0;
    for (std::size_t k = 0; k < p.size(); ++k) lowest = std::min(lowest, p.position[k].y - l.walls[k].position.y);
    EXPECT_NEAR(lowest, w, 0.05 * reference);
    for (const Vec2& v : p.wall_motion_velocity) EXPECT_LT(norm(v), 1e-4);  // m/s: settled (w is 2.3 mm)
  }
}

TEST(PlateCoupling, CheckpointRoundTripIsBitwise) {
  const PlateLayout l = plate_layout(floor_plate(), 0.02, 2.66 * 0.02, box(2.0, 1.6), at("test"), "plates.0");
  PlateCoupling a(l, 0), b(l, 0);
  Particles pa = plate_particles(l, 5000.0), pb = pa;
  for (int s = 0; s < 20; ++s) {
    a.fluid_force(pa, FrameForce{}, 1000.0);
    a.advance(pa, 1e-3, FrameForce{});
  }
  StateWriter w;
  a.save_state(w, "plate.0");
  StateReader r(w.bytes(), "memory");
  b.load_state(r, "plate.0");
  pb = pa;
  for (int s = 0; s < 20; ++s) {
    a.fluid_force(pa, FrameForce{}, 1000.0);
    a.advance(pa, 1e-3, FrameForce{});
    b.fluid_force(pb, FrameForce{}, 1000.0);
    b.advance(pb, 1e-3, FrameForce{});
  }
  EXPECT_EQ(a.tip_displacement().x, b.tip_displacement().x);
  EXPECT_EQ(a.displacement_at(0.5).y, b.displacement_at(0.5).y);
  for (std::size_t k = 0; k < pa.size(); ++k) EXPECT_EQ(pa.position[k].y, pb.position[k].y);
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// A fluid particle driven into a standing plate is put back on its side with its velocity into
// the plate removed, its tangential velocity kept (Dincer 2019, 2.3).
TEST(PlateCoupling, ContactPutsAnInvadingParticleBackWithSlip) {
  PlateSpec spec;
  spec.name = "p";
  spec.from = {0.15, 0.0};
  spec.standing_height = 0.08;
  spec.thickness = 0.003;
  spec.youngs_modulus = 1e7;
  spec.density = 1100.0;
  const double dp = 0.0015;
  TankSpec ts;
  ts.shape = "rectangle";
  ts.length = 0.3;
  ts.height = 0.2;
  const PlateLayout l = plate_layout(spec, dp, 2.66 * dp, make_tank(ts, "test"), at("test"), "plates.0");
  Particles p;
  p.resize(2 + l.walls.size());
  p.n_fluid = 2;
  p.mass = 1000.0 * dp * dp;
  p.position[0] = {0.15 - 0.0010, 0.04};  // inside the plate (t/2 = 1.5 mm), came from the left
  p.velocity[0] = {0.3, 0.1};
  p.position[1] = {0.15 - 0.0040, 0.05};  // well clear of it
  p.velocity[1] = {0.3, 0.0};
  for (std::size_t k = 0; k < l.walls.size(); ++k) {
    p.position[2 + k] = l.walls[k].position;
    p.normal[2 + k] = l.walls[k].normal;
  }
  p.id = {0, 1};
  for (std::size_t k = 0; k < l.walls.size(); ++k) p.id.push_back(static_cast<std::int32_t>(2 + k));
  p.wall_motion_velocity.assign(l.walls.size(), Vec2{});
  p.wall_motion_acceleration.assign(l.walls.size(), Vec2{});
  NeighbourList nl(2.66 * dp, 0.5 * dp);
  nl.build(p.position, p.n_fluid);
  PlateCoupling plate(l, 0);
  EXPECT_EQ(plate.keep_fluid_out(p, nl, dp, 1e-5, 0.0), 1u);
  const double contact = 0.0015 + 0.25 * dp;
  EXPECT_NEAR(p.position[0].x, 0.15 - 0.0015 - 0.5 * (contact - 0.0015), 1e-12);  // out of the left face
  EXPECT_NEAR(p.position[0].y, 0.04, 1e-12);           // slip: not moved along the plate
  EXPECT_NEAR(p.velocity[0].x, 0.0, 1e-12);            // no velocity into the (resting) plate
  EXPECT_NEAR(p.velocity[0].y, 0.1, 1e-12);            // tangential velocity kept
  EXPECT_EQ(p.position[1].x, 0.15 - 0.0040);           // the clear particle is untouched
  EXPECT_EQ(p.velocity[1].x, 0.3);
  EXPECT_EQ(plate.contacts(), 1u);
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// Issue 31: a plate across the breadth of a 3D tank. Its section particles stand on `planes`
// lattice planes (y = (m + 1/2) dp), particle k * planes + m; the beam is the 2D one, per metre of
// breadth.
Particles3 plate_particles_3d(const PlateLayout& l, const std::vector<double>& planes, double p0) {
  Particles3 p;
  p.resize(l.walls.size() * planes.size());
  p.n_fluid = 0;
  for (std::size_t k = 0; k < l.walls.size(); ++k)
    for (std::size_t m = 0; m < planes.size(); ++m) {
      const std::size_t w = k * planes.size() + m;
      p.position[w] = {l.walls[k].position.x, planes[m], l.walls[k].position.y};
      p.normal[w] = {l.walls[k].normal.x, 0.0, l.walls[k].normal.y};
      p.pressure[w] = l.walls[k].normal.y > 0.5 ? p0 : 0.0;
    }
  p.wall_motion_velocity.assign(p.size(), Vec3{});
  p.wall_motion_acceleration.assign(p.size(), Vec3{});
  return p;
}

// Reference: the same face pressure gives the same load per metre of breadth as in 2D, -p0 L on
// the 2 m upper face (1e-9 N/m), whatever the number of planes; with gravity the pressure carried
// dp/2 to the face as in 2D; the width is planes x dp.
TEST(PlateCoupling, ThreeDimensionalPlateCarriesThePressureIntegralPerMetre) {
  const double dp = 0.02;
  const PlateLayout l = plate_layout(floor_plate(), dp, 2.66 * dp, box(2.0, 1.6), at("test"), "plates.0");
  const std::vector<double> planes = {0.01, 0.03, 0.05, 0.07};
  PlateCoupling3 plate(l, 0, planes, dp);
  EXPECT_EQ(plate.count(), 4 * l.walls.size());
  EXPECT_DOUBLE_EQ(plate.width(), 0.08);
  Particles3 p = plate_particles_3d(l, planes, 9810.0);
  const Vec2 f = plate.fluid_force(p, FrameForce3{}, 1000.0);
  EXPECT_NEAR(f.y, -9810.0 * 2.0, 1e-9);
  EXPECT_NEAR(f.x, 0.0, 1e-9);
  FrameForce3 g;
  g.uniform = {0.0, 0.0, -9.81};
  EXPECT_NEAR(plate.fluid_force(p, g, 1000.0).y, -(9810.0 - 1000.0 * 9.81 * 0.01) * 2.0, 1e-9);
  // A pressure on one plane only is a quarter of the load per metre.
  for (std::size_t w = 0; w < p.size(); ++w)
    if (w % planes.size() != 0) p.pressure[w] = 0.0;
  EXPECT_NEAR(plate.fluid_force(p, FrameForce3{}, 1000.0).y, -9810.0 * 2.0 / 4.0, 1e-9);
}

// Reference: under a uniform face load the 3D plate deflects as the 2D one to round-off (the same
// beam), and every plane's particles follow the beam: at mid-span the particles of all four planes
// stand at the same height, moved down with it.
TEST(PlateCoupling, ThreeDimensionalPlateDeflectsAsTheTwoDimensionalOne) {
  const double dp = 0.02;
  const PlateSpec spec = floor_plate();
  const PlateLayout l = plate_layout(spec, dp, 2.66 * dp, box(2.0, 1.6), at("test"), "plates.0");
  const std::vector<double> planes = {0.01, 0.03, 0.05, 0.07};
  PlateCoupling flat(l, 0);
  Particles p2 = plate_particles(l, 9810.0);
  const double w2 = settle_midspan(flat, p2, 9810.0);
  PlateCoupling3 plate(l, 0, planes, dp);
  Particles3 p = plate_particles_3d(l, planes, 9810.0);
  for (int step = 0; step < 3000; ++step) {
    for (std::size_t w = 0; w < p.size(); ++w) p.pressure[w] = p.normal[w].z > 0.5 ? 9810.0 : 0.0;
    plate.fluid_force(p, FrameForce3{}, 1000.0);
    plate.advance(p, 1.0e-3, FrameForce3{});
  }
  const double w3 = plate.displacement_at(0.5).y;
  EXPECT_NEAR(w3, w2, 1e-12 + 1e-9 * std::abs(w2));
  EXPECT_NEAR(-w3 / clamped_midspan(spec, 9810.0), 1.0, 0.01);
  for (std::size_t k = 0; k < l.walls.size(); ++k)
    for (std::size_t m = 0; m < planes.size(); ++m) {
      const std::size_t w = k * planes.size() + m;
      EXPECT_DOUBLE_EQ(p.position[w].z, p2.position[k].y);
      EXPECT_DOUBLE_EQ(p.position[w].x, p2.position[k].x);
      EXPECT_EQ(p.position[w].y, planes[m]);
      EXPECT_EQ(p.normal[w].y, 0.0);
    }
}

}  // namespace
}  // namespace sloshsph
