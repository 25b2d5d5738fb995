// A tank at rest with the WCSPH scheme: the hydrostatic pressure is held, nothing moves much,
// nothing blows up, for both wall treatments.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/schemes/wcsph.hpp"
#include "wcsph_test_cases.hpp"

namespace sloshsph {
namespace {

struct RestResult {
  double mean_pressure = 0.0;     // Pa, the particle row at mid-depth (|y - H/2| < dp/2, 0.1 < x < 0.4 m),
                                  // averaged over the last 0.2 s
  double mean_hydrostatic = 0.0;  // Pa, rho0 g (H - y) of the same particles
  double max_speed_late = 0.0;    // m/s, max over the last 0.2 s
  double max_speed = 0.0;         // m/s, max over the run
  double mean_wall_force_y = 0.0; // N/m, over the last 0.2 s
  double fluid_weight = 0.0;      // N/m
  std::size_t steps = 0;
  double seconds = 0.0;           // wall time of the loop
  std::size_t particles = 0;
  bool finite = true;
};

RestResult run_rest(WallTreatment walls, double duration) {
  const CaseSpec spec = test::rest_tank_case(walls);
  Scene scene = build_scene(spec);
  Particles& p = scene.particles;
  WcsphScheme scheme(spec, scene.h);
  FrameForce frame;
  frame.uniform = {0.0, -spec.fluid.gravity};
  scheme.initialise(p, frame);

  RestResult r;
  r.particles = p.size();
  r.fluid_weight = p.mass * static_cast<double>(p.n_fluid) * spec.fluid.gravity;
  const double H = scene.still_level, y_mid = 0.5 * H, rho_g = spec.fluid.density * spec.fluid.gravity;
  double t = 0.0, p_sum = 0.0, ph_sum = 0.0, fy_sum = 0.0;
  std::size_t samples = 0, force_samples = 0;
  const auto start = std::chrono::steady_clock::now();
  StepInput in;
  in.frame = frame;
  while (t < duration) {
    in.dt = scheme.stable_dt(p, frame);
    scheme.step(p, in);
    t += in.dt;
    ++r.steps;
    r.max_speed = std::max(r.max_speed, scheme.diagnostics().max_speed);
    if (!std::isfinite(scheme.diagnostics().max_speed)) {
      r.finite = false;
      break;
    }
    if (t > duration - 0.2) {
      r.max_speed_late = std::max(r.max_speed_late, scheme.diagnostics().max_speed);
      fy_sum += scheme.diagnostics().wall_force.y;
      ++force_samples;
      for (std::size_t i = 0; i < p.n_fluid; ++i) {
        const Vec2 x = p.position[i];
        if (std::abs(x.y - y_mid) < 0.5 * spec.particles.dp && x.x > 0.1 && x.x < 0.4) {
          p_sum += p.pressure[i];
          ph_sum += rho_g * (H - x.y);
          ++samples;
        }
      }
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isfinite(p.position[i].x) || !std::isfinite(p.position[i].y) || !std::isfinite(p.pressure[i]) ||
        !std::isfinite(p.velocity[i].x) || !std::isfinite(p.velocity[i].y))
      r.finite = false;
  if (samples > 0) {
    r.mean_pressure = p_sum / static_cast<double>(samples);
    r.mean_hydrostatic = ph_sum / static_cast<double>(samples);
  }
  if (force_samples > 0) r.mean_wall_force_y = fy_sum / static_cast<double>(force_samples);
  std::printf("[rest %s] %zu particles, %zu steps, %.2f s wall (%.3g us per step per particle); "
              "p(mid) = %.2f Pa vs rho g (H - y) = %.2f Pa (%.3f%%); max speed %.3g m/s (last 0.2 s %.3g); "
              "wall force y %.2f N/m vs weight %.2f N/m\n",
              walls == WallTreatment::adami ? "adami" : "repulsive", r.particles, r.steps, r.seconds,
              1e6 * r.seconds / (static_cast<double>(r.steps) * static_cast<double>(r.particles)), r.mean_pressure,
              r.mean_hydrostatic, 100.0 * (r.mean_pressure / r.mean_hydrostatic - 1.0), r.max_speed,
              r.max_speed_late, r.mean_wall_force_y, r.fluid_weight);
  return r;
}

// Reference: hydrostatics, p = rho0 g (H - y) at mid-depth (H = 0.25 m, the still level),
// time-averaged over the last 0.2 s of a 1 s run; tolerance 3%. (Measured: +1.5%, the lattice
// moment of the kernel at h = 1.4 dp: the uncorrected pressure gradient is ~1.5% weak, so the
// balance needs a 1.5% larger pressure; see sph/operators.hpp.) The fluid should stay still:
// the max speed over the last 0.2 s is required below 1% of sqrt(g H) = 1.57 m/s (measured
// ~0.003 m/s, the decaying start-up acoustic ripple). Momentum balance: averaged over 0.2 s
// the walls carry the weight of the fluid (the fluid's momentum change over 0.2 s is
// negligible); tolerance 1%.
void check_rest(WallTreatment walls) {
  const RestResult r = run_rest(walls, 1.0);
  ASSERT_TRUE(r.finite);
  EXPECT_NEAR(r.mean_pressure, r.mean_hydrostatic, 0.03 * r.mean_hydrostatic);
  EXPECT_LT(r.max_speed_late, 0.01 * std::sqrt(9.81 * 0.25));
  EXPECT_NEAR(r.mean_wall_force_y, r.fluid_weight, 0.01 * r.fluid_weight);
}

TEST(WcsphRest, AdamiWallsHoldHydrostaticPressure) { check_rest(WallTreatment::adami); }

TEST(WcsphRest, RepulsiveWallsHoldHydrostaticPressure) { check_rest(WallTreatment::repulsive); }

}  // namespace
}  // namespace sloshsph
