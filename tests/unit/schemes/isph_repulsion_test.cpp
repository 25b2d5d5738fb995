// The repulsive wall force of thesis eq. 3.18 in the ISPH scheme (scheme.repulsive_walls):
// it pushes fluid that comes closer than r0 to the first wall layer, and a tank at rest with
// it switched on stays at rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/physics/wall_repulsion.hpp"
#include "sloshsph/schemes/isph.hpp"

namespace sloshsph {
namespace {

CaseSpec isph_tank(const std::string& shape, double length, double height, double depth, bool repulsive) {
  CaseSpec spec;
  spec.source = "<test>";
  spec.name = "isph_repulsion";
  spec.tank.shape = shape;
  spec.tank.length = length;
  spec.tank.height = height;
  spec.fill.depth = depth;
  spec.particles.dp = 0.01;
  spec.scheme.repulsive_walls = repulsive;
  return spec;
}

FrameForce gravity(const CaseSpec& spec) {
  FrameForce f;
  f.uniform = {0.0, -spec.fluid.gravity};
  return f;
}

// One step of a rectangular tank at rest after one fluid particle has been put 0.6 dp straight
// above a first-layer wall particle of the bottom (0.1 dp inside the wall surface; r0 = 0.7 dp).
// Reference: with the force on, the predictor adds dt sum_w f_iw (eq. 3.18, D = g max(H_w, h))
// to that particle's velocity, upward; the pressure solve then responds to both runs alike.
// Tolerance: the upward velocity gained over the run without the force is at least half of it.
TEST(IsphRepulsion, PushesFluidAwayFromTheWall) {
  const double dp = 0.01, dt = 5.0e-4;
  double vy[2] = {0.0, 0.0}, kick = 0.0;
  for (int on = 0; on < 2; ++on) {
    const CaseSpec spec = isph_tank("rectangle", 0.3, 0.2, 0.1, on == 1);
    Scene scene = build_scene(spec);
    Particles& p = scene.particles;
    IsphScheme scheme(spec, scene.h);
    scheme.initialise(p, gravity(spec));
    std::size_t moved = 0, below = p.n_fluid;
    for (std::size_t i = 0; i < p.n_fluid; ++i)
      if (norm(p.position[i] - Vec2{0.15, 0.0}) < norm(p.position[moved] - Vec2{0.15, 0.0})) moved = i;
    for (std::size_t w = p.n_fluid; w < p.size(); ++w)
      if (p.position[w].y < 0.0 && p.position[w].y > -dp &&
          (below == p.n_fluid || std::abs(p.position[w].x - 0.15) < std::abs(p.position[below].x - 0.15)))
        below = w;
    ASSERT_LT(below, p.size());
    p.position[moved] = p.position[below] + Vec2{0.0, 0.6 * dp};
    const std::int32_t id = p.id[moved];
    if (on == 1) {
      const double range = 0.5 * scene.h;
      for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
        if (!(p.position[w].y < 0.0 && p.position[w].y > -dp)) continue;  // first layer of the bottom
        const double strength = spec.fluid.gravity * std::max(scene.still_level - p.position[w].y, scene.h);
        kick += dt * thesis_wall_repulsion(p.position[moved] - p.position[w], strength, range).y;
      }
    }
    StepInput in;
    in.dt = dt;
    in.frame = gravity(spec);
    scheme.step(p, in);
    for (std::size_t i = 0; i < p.n_fluid; ++i)
      if (p.id[i] == id) vy[on] = p.velocity[i].y;
  }
  std::printf("  measured: v_y without %.5g m/s, with %.5g m/s, dt sum f_iw = %.5g m/s\n", vy[0], vy[1], kick);
  EXPECT_GT(kick, 0.0);
  EXPECT_GT(vy[1] - vy[0], 0.5 * kick);
}

struct RestState {
  double level = 0.0;          // m, H_eff: the still level that holds the fluid's area n dp^2
  double deviation = 0.0;      // mean |p - rho g (H_eff - y)| / (rho g H_eff), particles below H_eff - 2h
  double min_distance = 1.0;   // m, smallest signed distance of a fluid particle to the section
  double max_speed = 0.0;      // m/s
};

RestState circular_tank_at_rest(bool repulsive) {
  const CaseSpec spec = isph_tank("circular", 0.5, 0.3, 0.12, repulsive);
  Scene scene = build_scene(spec);
  Particles& p = scene.particles;
  IsphScheme scheme(spec, scene.h);
  scheme.initialise(p, gravity(spec));
  StepInput in;
  in.dt = 1.0e-3;
  in.frame = gravity(spec);
  for (int k = 0; k < 1000; ++k) scheme.step(p, in);

  const TankGeometry& tank = *scene.tank;
  const double area = static_cast<double>(p.n_fluid) * p.volume;
  double lo = 0.0, hi = spec.fill.depth;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (section_area(tank, mid) < area ? lo : hi) = mid;
  }
  RestState r;
  r.level = lo;
  const double rho_g = spec.fluid.density * spec.fluid.gravity, top = tank.y_bottom + lo;
  std::size_t counted = 0;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    r.min_distance = std::min(r.min_distance, tank.signed_distance(p.position[i]));
    r.max_speed = std::max(r.max_speed, norm(p.velocity[i]));
    if (p.position[i].y > top - 2.0 * scene.h) continue;
    r.deviation += std::abs(p.pressure[i] - rho_g * (top - p.position[i].y));
    ++counted;
  }
  r.deviation /= static_cast<double>(counted) * rho_g * lo;
  std::printf("  measured (repulsive %s): H_eff = %.4f m (requested %.2f), mean |p - p_hydro| / (rho g H_eff) = %.4f, "
              "min signed distance %.4f m, max speed %.4g m/s\n",
              repulsive ? "on" : "off", lo, spec.fill.depth, r.deviation, r.min_distance, r.max_speed);
  return r;
}

// A circular tank (R = 0.25 m, still water 0.12 m deep, dp = 10 mm, dt = 1 ms) at rest for 1 s
// with the force on, and the same without it. References: the hydrostatic pressure
// rho g (H_eff - y), H_eff the still level that holds the fluid's area (the lattice fill leaves
// ~dp/2 gaps along curved walls, so H_eff is below the requested depth and the fluid settles
// into the gaps: that slow settling, not the force, sets the speeds); and the run without the
// force. Tolerances: mean absolute pressure deviation within 2% of rho g H_eff; no particle
// more than dp/2 outside the section; the maximum speed and the pressure deviation within 5%
// of those of the run without the force (the force must not disturb a fluid at rest).
TEST(IsphRepulsion, CircularTankAtRestStaysAtRest) {
  const RestState on = circular_tank_at_rest(true), off = circular_tank_at_rest(false);
  EXPECT_LT(on.deviation, 0.02);
  EXPECT_GT(on.min_distance, -0.005);
  EXPECT_LT(on.max_speed, 1.05 * off.max_speed);
  EXPECT_NEAR(on.deviation, off.deviation, 0.05 * off.deviation);
}

}  // namespace
}  // namespace sloshsph
