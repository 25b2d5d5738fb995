// build_scene's warnings for a time step that a scheme option is known not to survive
// (scene.cpp, add_time_step_warnings): the thesis free surface with the implicit solve ran away at
// dt sqrt(g/dp) = 0.031 and 0.050, and ran at 0.022 and 0.0099 (measured; docs/validation/notes.md).
#include <gtest/gtest.h>

#include <string>

#include "sloshsph/geometry/scene.hpp"

namespace sloshsph {
namespace {

CaseSpec tank(FreeSurfaceModel model, double dp, double dt) {
  CaseSpec spec;
  spec.source = "<test>";
  spec.name = "scene_warnings";
  spec.tank.shape = "rectangle";
  spec.tank.length = 0.5;
  spec.tank.height = 0.4;
  spec.fill.depth = 0.25;
  spec.particles.dp = dp;
  spec.time.dt = dt;
  spec.scheme.free_surface = model;
  return spec;
}

bool warns_of_the_time_step(const Scene& scene) {
  for (const std::string& w : scene.warnings)
    if (w.find("time.dt <=") != std::string::npos) return true;
  return false;
}

TEST(SceneWarnings, ThesisFreeSurfaceWithTheImplicitSolveAtALargeStep) {
  // linear_sloshing.toml at dp = 10 mm, dt = 1 ms: ran away at step 50-65.
  EXPECT_TRUE(warns_of_the_time_step(build_scene(tank(FreeSurfaceModel::thesis, 0.01, 1e-3))));
  // The case's own dp = 5 mm, dt = 0.5 ms ran (0.022), and the air model is not concerned.
  EXPECT_FALSE(warns_of_the_time_step(build_scene(tank(FreeSurfaceModel::thesis, 0.005, 5e-4))));
  EXPECT_FALSE(warns_of_the_time_step(build_scene(tank(FreeSurfaceModel::air, 0.01, 1e-3))));
  // The explicit update is the thesis model's own pairing: not concerned either.
  CaseSpec explicit_update = tank(FreeSurfaceModel::thesis, 0.01, 1e-3);
  explicit_update.scheme.pressure = PressureSolve::explicit_update;
  EXPECT_FALSE(warns_of_the_time_step(build_scene(explicit_update)));
}

}  // namespace
}  // namespace sloshsph
