#pragma once
// What every scheme's step() takes and reports (ISPH, WCSPH).
#include <cstddef>

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/physics/frame.hpp"

namespace sloshsph {

struct StepInput {
  double dt = 0.0;    // s
  FrameForce frame;   // gravity and frame forces in the tank frame
};

struct StepDiagnostics {
  Vec2 wall_force;               // N/m: total force of the walls on the fluid (base shear, thesis eq. 4.21)
  double max_speed = 0.0;        // m/s, fluid, after the step
  std::size_t free_surface = 0;  // particles flagged free surface this step
  int solver_iterations = 0;     // implicit PPE (explicit: sweeps)
  double solver_residual = 0.0;  // implicit PPE, relative
  bool neighbours_rebuilt = false;
};

}  // namespace sloshsph
