// Thread-count independence and momentum conservation of the WCSPH scheme.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <random>

#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/schemes/wcsph.hpp"
#include "wcsph_test_cases.hpp"

namespace sloshsph {
namespace {

// 50 steps of the rest tank (at dp = 0.02 m, 360 particles, to keep the test fast) under a
// tilted body force (the fluid starts to slosh), from the same start, with a given number of threads.
Particles run_threads(const CaseSpec& spec, int threads) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Scene scene = build_scene(spec);
  WcsphScheme scheme(spec, scene.h);
  FrameForce frame;
  frame.uniform = {-2.0, -9.81};
  scheme.initialise(scene.particles, frame);
  StepInput in;
  in.frame = frame;
  for (int n = 0; n < 50; ++n) {
    in.dt = scheme.stable_dt(scene.particles, frame);
    scheme.step(scene.particles, in);
  }
  omp_set_num_threads(before);
  return scene.particles;
}

bool bitwise_equal(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2)) == 0;
}

// Reference: gather loops (each particle writes only itself) and fixed-order reductions make
// the result independent of the thread count: bitwise identical positions and velocities.
TEST(WcsphDeterminism, TwoThreadsMatchOneThreadBitwise) {
  CaseSpec plain = test::rest_tank_case(WallTreatment::adami);
  plain.particles.dp = 0.02;
  CaseSpec options = test::rest_tank_case(WallTreatment::repulsive);
  options.particles.dp = 0.02;
  options.scheme.wcsph.kernel_gradient_correction = true;
  options.scheme.wcsph.xsph = 0.05;
  options.scheme.wcsph.shepard_interval = 10;
  options.scheme.wcsph.turbulence = WcsphTurbulence::smagorinsky;
  options.scheme.wcsph.integrator = Integrator::leapfrog;
  for (const CaseSpec& spec : {plain, options}) {
    const Particles one = run_threads(spec, 1);
    const Particles two = run_threads(spec, 2);
    EXPECT_TRUE(bitwise_equal(one.position, two.position));
    EXPECT_TRUE(bitwise_equal(one.velocity, two.velocity));
    EXPECT_EQ(one.id, two.id);
  }
}

// A free disc of fluid (radius 0.1 m, dp = 0.01 m), zero gravity, random velocities up to
// 0.1 m/s, no wall particles: every force is a pair force, antisymmetric in i, j.
Particles free_blob() {
  const double dp = 0.01, radius = 0.1;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  Particles p;
  for (int a = -10; a <= 10; ++a)
    for (int b = -10; b <= 10; ++b) {
      const Vec2 x{a * dp, b * dp};
      if (norm(x) <= radius) {
        p.position.push_back(x);
        p.velocity.push_back({u(rng), u(rng)});
      }
    }
  const std::size_t n = p.position.size();
  p.n_fluid = n;
  p.resize(n);  // every per-particle array, at the length of position
  p.density.assign(n, 1000.0);
  for (std::size_t i = 0; i < n; ++i) p.id[i] = static_cast<std::int32_t>(i);
  p.volume = dp * dp;
  p.mass = 1000.0 * p.volume;
  return p;
}

Vec2 momentum(const Particles& p) {
  Vec2 m;
  for (std::size_t i = 0; i < p.n_fluid; ++i) m += p.mass * p.velocity[i];
  return m;
}

// Reference: Newton's third law, sum_i m du_i/dt = 0 for the pair forces (pressure, artificial
// or laminar viscosity, turbulent stress); XSPH moves positions only and Shepard changes only
// densities. Tolerance: round-off, 1e-12 of sum_i m |u_i| after 100 steps. (The kernel gradient
// correction is not antisymmetric, L_i != L_j, and is left out.)
TEST(WcsphConservation, FreeBlobConservesMomentum) {
  CaseSpec av;
  av.particles.dp = 0.01;
  av.scheme.wcsph.sound_speed = 10.0;
  CaseSpec laminar = av;
  laminar.fluid.viscosity = 1e-3;  // large enough to matter over 100 steps
  laminar.scheme.wcsph.artificial_viscosity = 0.0;
  laminar.scheme.wcsph.turbulence = WcsphTurbulence::sps;
  laminar.scheme.wcsph.xsph = 0.05;
  laminar.scheme.wcsph.shepard_interval = 20;
  laminar.scheme.wcsph.integrator = Integrator::leapfrog;
  for (const CaseSpec& spec : {av, laminar}) {
    Particles p = free_blob();
    WcsphScheme scheme(spec, 1.4 * spec.particles.dp);
    const FrameForce none;
    scheme.initialise(p, none);
    const Vec2 start = momentum(p);
    double scale = 0.0;
    for (std::size_t i = 0; i < p.n_fluid; ++i) scale += p.mass * norm(p.velocity[i]);
    StepInput in;
    in.frame = none;
    double max_pressure = 0.0;
    for (int n = 0; n < 100; ++n) {
      in.dt = scheme.stable_dt(p, none);
      scheme.step(p, in);
      for (std::size_t i = 0; i < p.n_fluid; ++i) max_pressure = std::max(max_pressure, std::abs(p.pressure[i]));
    }
    const Vec2 end = momentum(p);
    std::printf("[momentum] %zu particles, |dP| = %.3e of sum m|u| = %.3e (max |p| %.1f Pa)\n", p.n_fluid,
                norm(end - start), scale, max_pressure);
    EXPECT_GT(max_pressure, 1.0);  // the pair forces are not trivially zero
    EXPECT_LT(norm(end - start), 1e-12 * scale);
  }
}

// Two fluid particles at one point (the Faltinsen WCSPH case pressed two into a tank corner at
// t = 31.5 s; at 32.1 s their positions became bitwise equal and the artificial viscosity's
// (u_ij . r_ij) / r^2 made them NaN). Reference: every rate stays finite and the pair's own terms
// vanish by symmetry (same position, same velocity, same density), so both keep moving alike.
TEST(WcsphConservation, CoincidentParticlesStayFinite) {
  CaseSpec spec;
  spec.particles.dp = 0.01;
  spec.scheme.wcsph.sound_speed = 10.0;
  Particles p = free_blob();
  const std::size_t twin = p.n_fluid;  // a copy of particle 0, appended
  p.position.push_back(p.position[0]);
  p.velocity.push_back(p.velocity[0]);
  p.n_fluid = p.position.size();
  p.resize(p.n_fluid);
  p.density.assign(p.n_fluid, 1000.0);
  for (std::size_t i = 0; i < p.n_fluid; ++i) p.id[i] = static_cast<std::int32_t>(i);
  WcsphScheme scheme(spec, 1.4 * spec.particles.dp);
  const FrameForce none;
  scheme.initialise(p, none);
  StepInput in;
  in.frame = none;
  for (int n = 0; n < 20; ++n) {
    in.dt = scheme.stable_dt(p, none);
    scheme.step(p, in);
  }
  std::size_t finite = 0, original = p.n_fluid, copy = p.n_fluid;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    finite += std::isfinite(p.position[i].x) && std::isfinite(p.position[i].y) && std::isfinite(p.velocity[i].x) &&
              std::isfinite(p.velocity[i].y) && std::isfinite(p.density[i]);
    if (p.id[i] == 0) original = i;
    if (p.id[i] == static_cast<std::int32_t>(twin)) copy = i;
  }
  EXPECT_EQ(finite, p.n_fluid);
  ASSERT_LT(original, p.n_fluid);
  ASSERT_LT(copy, p.n_fluid);
  EXPECT_EQ(p.position[original].x, p.position[copy].x);
  EXPECT_EQ(p.position[original].y, p.position[copy].y);
}

}  // namespace
}  // namespace sloshsph
