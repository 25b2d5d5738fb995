#pragma once
// Set-up shared by the 3D validation tests (issue 31): no case file reads a 3D tank yet, so the
// tests build the particles of a tank themselves.
#include <algorithm>
#include <cstdint>
#include <vector>

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

// The fluid of `tank` filled to spec.fill.depth and its wall layers, at rest with the hydrostatic
// pressure rho g (depth - z) (walls: of their height, 0 above the level); ids in fill order.
inline Particles3 particles_at_rest(const CaseSpec& spec, const PrismTank& tank) {
  const double dp = spec.particles.dp, rho = spec.fluid.density, g = spec.fluid.gravity, depth = spec.fill.depth;
  const std::vector<Vec3> fluid = fill_fluid(tank, dp, depth);
  const std::vector<WallSample3> walls = sample_walls(tank, dp, spec.particles.wall_layers);
  Particles3 p;
  p.resize(fluid.size() + walls.size());
  p.n_fluid = fluid.size();
  p.volume = dp * dp * dp;
  p.mass = rho * p.volume;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool is_fluid = i < fluid.size();
    p.position[i] = is_fluid ? fluid[i] : walls[i - fluid.size()].position;
    if (!is_fluid) p.normal[i] = walls[i - fluid.size()].normal;
    p.pressure[i] = rho * g * std::max(0.0, depth - p.position[i].z);
    p.density[i] = rho;
    p.id[i] = static_cast<std::int32_t>(i);
  }
  return p;
}

}  // namespace sloshsph::testing
