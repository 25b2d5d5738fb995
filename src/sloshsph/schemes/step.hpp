#pragma once
// What every scheme's step() takes and reports (ISPH, WCSPH), in 2 or 3 dimensions.
#include <cstddef>
#include <functional>
#include <vector>

#include "sloshsph/core/particles.hpp"

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/physics/frame.hpp"

namespace sloshsph {

// Fills `acceleration` (one entry per fluid particle, m/s^2) with forces the driver adds to
// the momentum equation, e.g. the porous drag of screens (thesis eq. 2.28). The scheme calls it
// at the start of a step, after any reordering of the particles, with the state u(t).
template <int D>
using BasicExtraAcceleration = std::function<void(const BasicParticles<D>&, std::vector<Vec<D>>& acceleration)>;
using ExtraAcceleration = BasicExtraAcceleration<2>;

template <int D>
struct BasicStepInput {
  double dt = 0.0;            // s
  BasicFrameForce<D> frame;   // gravity and frame forces in the tank frame
  BasicExtraAcceleration<D> extra;  // optional
};
using StepInput = BasicStepInput<2>;

template <int D>
struct BasicStepDiagnostics {
  Vec<D> wall_force;             // N/m (N in 3D): total force of the walls on the fluid (base shear, thesis eq. 4.21)
  // N m/m (N m in 3D): the moment of that force about the tank frame's origin, sum_i r_i x m a_wall,i
  // with r_i where the force on fluid particle i was evaluated (the pair forces of the walls' pressure
  // act along r_ij, so taking them at the fluid particle instead of the wall particle changes nothing).
  Moment<D> wall_moment{};
  double max_speed = 0.0;        // m/s, fluid, after the step
  std::size_t free_surface = 0;  // particles flagged free surface this step
  int solver_iterations = 0;     // implicit PPE (explicit: sweeps)
  double solver_residual = 0.0;  // implicit PPE, relative
  std::size_t pinned_particles = 0;  // implicit PPE: fluid of blocks no p = 0 reaches, set to p = 0
  bool neighbours_rebuilt = false;
  std::size_t shifts_limited = 0;    // scheme.shifting: shifts cut by the length cap or a wall
};
using StepDiagnostics = BasicStepDiagnostics<2>;

// The memory of a scheme's arrays by part (their capacity, bytes): summary.json's
// memory_bytes_per_particle and its breakdown memory_bytes_per_particle_by_part.
struct MemoryPart {
  const char* name;
  std::size_t bytes;
};
using MemoryParts = std::vector<MemoryPart>;

inline std::size_t total_bytes(const MemoryParts& parts) {
  std::size_t n = 0;
  for (const MemoryPart& part : parts) n += part.bytes;
  return n;
}

}  // namespace sloshsph
