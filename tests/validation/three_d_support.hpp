#pragma once
// Set-up shared by the 3D validation tests (issue 31): no case file reads a 3D tank yet, so the
// tests build the particles of a tank themselves.
#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/particles.hpp"
#include "sloshsph/geometry/prism_tank.hpp"

namespace sloshsph::testing {

// A case for a box of length x height (the section) with water to `depth`, particles of dp, the
// scheme's defaults otherwise.
inline CaseSpec box_case(double length, double height, double depth, double dp) {
  CaseSpec spec;
  spec.tank.shape = "rectangle";
  spec.tank.length = length;
  spec.tank.height = height;
  spec.fill.depth = depth;
  spec.particles.dp = dp;
  return spec;
}

// The particles of `tank` at rest for the case (geometry/prism_tank.hpp).
inline Particles3 particles_at_rest(const CaseSpec& spec, const PrismTank& tank) {
  return sloshsph::particles_at_rest(tank, spec.particles.dp, spec.fill.depth, spec.particles.wall_layers,
                                     spec.fluid.density, spec.fluid.gravity);
}

}  // namespace sloshsph::testing
