// The WCSPH scheme keeps the last rates of every fluid particle between steps (both
// integrators need them). They must follow the particles when the driver removes leaked
// particles between steps, and a first step without initialise() must still work.
#include <gtest/gtest.h>

#include <cmath>

#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/schemes/wcsph.hpp"
#include "wcsph_test_cases.hpp"

namespace sloshsph {
namespace {

FrameForce gravity() {
  FrameForce f;
  f.uniform = {-1.0, -9.81};
  return f;
}

void advance(WcsphScheme& scheme, Particles& p, int steps) {
  StepInput in;
  in.frame = gravity();
  for (int n = 0; n < steps; ++n) {
    in.dt = scheme.stable_dt(p, in.frame);
    scheme.step(p, in);
  }
}

// Two identical runs; in one, three fluid particles are removed between steps (as the driver
// removes leaked particles). One step later, every particle farther than two supports from the
// removed ones (one evaluation reaches a neighbour's neighbour: renormalised gradients, wall
// values) must be where the same particle (by id) is in the other run. Reference: equality up
// to the order of summation (the list is rebuilt after the removal): 1e-12 m and 1e-10 m/s.
// A rate given to the wrong particle would show as ~dt^2 |da| ~ 1e-7 m.
TEST(WcsphState, RatesFollowParticlesThroughRemoval) {
  CaseSpec spec = test::rest_tank_case();
  spec.particles.dp = 0.02;
  Scene a = build_scene(spec), b = build_scene(spec);
  WcsphScheme sa(spec, a.h), sb(spec, b.h);
  sa.initialise(a.particles, gravity());
  sb.initialise(b.particles, gravity());
  advance(sa, a.particles, 10);
  advance(sb, b.particles, 10);
  // Remove the three fluid particles nearest the top-right corner of the fluid in run b.
  Particles& pb = b.particles;
  std::vector<std::uint8_t> remove(pb.n_fluid, 0);
  std::vector<Vec2> removed;
  for (int k = 0; k < 3; ++k) {
    std::size_t best = 0;
    double score = -1e9;
    for (std::size_t i = 0; i < pb.n_fluid; ++i)
      if (!remove[i] && pb.position[i].x + pb.position[i].y > score) {
        score = pb.position[i].x + pb.position[i].y;
        best = i;
      }
    remove[best] = 1;
    removed.push_back(pb.position[best]);
  }
  pb.remove_fluid(remove);
  advance(sa, a.particles, 1);
  advance(sb, b.particles, 1);
  const double far = 2.0 * (2.0 * b.h) * 1.2 + 0.02;  // two supports with skin: no influence within one step
  std::size_t compared = 0;
  for (std::size_t i = 0; i < pb.n_fluid; ++i) {
    bool near = false;
    for (const Vec2& r : removed) near = near || norm(pb.position[i] - r) < far;
    if (near) continue;
    // The same particle (by id) in run a.
    const Particles& pa = a.particles;
    for (std::size_t j = 0; j < pa.n_fluid; ++j)
      if (pa.id[j] == pb.id[i]) {
        EXPECT_NEAR(pa.position[j].x, pb.position[i].x, 1e-12);
        EXPECT_NEAR(pa.position[j].y, pb.position[i].y, 1e-12);
        EXPECT_NEAR(pa.velocity[j].x, pb.velocity[i].x, 1e-10);
        EXPECT_NEAR(pa.velocity[j].y, pb.velocity[i].y, 1e-10);
        ++compared;
        break;
      }
  }
  EXPECT_GT(compared, pb.n_fluid / 2);
}

// Without initialise() the first step evaluates the rates itself; it stays finite.
TEST(WcsphState, StepWithoutInitialise) {
  CaseSpec spec = test::rest_tank_case(WallTreatment::repulsive);
  spec.particles.dp = 0.02;
  Scene s = build_scene(spec);
  WcsphScheme scheme(spec, s.h);
  for (std::size_t i = 0; i < s.particles.n_fluid; ++i)
    s.particles.density[i] = 1000.0 + s.particles.pressure[i] / (scheme.sound_speed() * scheme.sound_speed());
  advance(scheme, s.particles, 20);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    EXPECT_TRUE(std::isfinite(s.particles.position[i].x) && std::isfinite(s.particles.position[i].y));
    EXPECT_TRUE(std::isfinite(s.particles.pressure[i]));
  }
  EXPECT_LT(scheme.diagnostics().max_speed, 0.5);
}

}  // namespace
}  // namespace sloshsph
