#pragma once
// Three-dimensional tanks made by extruding a tank section over a breadth (issue 31, section 2): a
// box is the rectangle section extruded, and every other section sloshsph has (sloped, parabolic,
// circular, polyline) gives a prismatic tank the same way. Axes: x along the length (the section's
// x), y across the breadth (0 to `breadth`), z up (the section's y), as the probes have them.
//
// Cases with tank.dimensions = 3 are built on it (geometry/scene.cpp build_scene3).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

// The point of the section at `s` (x, height) at the breadth coordinate y.
inline constexpr Vec3 at_breadth(Vec2 s, double y) { return {s.x, y, s.y}; }
// The section coordinates (x, height) of a point.
inline constexpr Vec2 in_section(Vec3 p) { return {p.x, p.z}; }

// The signed distance of a tank `section` extruded over `breadth` (positive inside): the smaller
// of the section's distance of (x, z) and the distances y and breadth - y to the end walls. Exact
// inside and on the walls; outside, its magnitude is the larger of the two distances (at an edge,
// at most the true distance). In 2D, the section's own distance (breadth unused).
template <int D>
double container_signed_distance(const TankGeometry& section, double breadth, Vec<D> p) {
  if constexpr (D == 2) {
    (void)breadth;
    return section.signed_distance(p);
  } else {
    return std::min(section.signed_distance(in_section(p)), std::min(p.y, breadth - p.y));
  }
}

struct PrismTank {
  TankGeometry section;  // in the x-z plane, as TankGeometry's (x, y)
  double breadth = 0.0;  // m, between the end walls y = 0 and y = breadth

  // container_signed_distance of the prism.
  double signed_distance(Vec3 p) const { return container_signed_distance<3>(section, breadth, p); }
};

struct WallSample3 {
  Vec3 position;
  Vec3 normal;  // inward unit normal of the wall at this particle
};

// Dummy wall particles, `layers` deep:
//  * the section's wall layers (sample_walls) repeated at y = (k + 1/2) dp along the breadth, and
//    through the end walls' layers (k from -layers to n_y + layers - 1, n_y = breadth/dp rounded
//    down), so that the edges where side and end walls meet are filled; their normals lie in the
//    section plane;
//  * the end walls: `layers` planes at y = -(k + 1/2) dp and breadth + (k + 1/2) dp, each on the
//    fill's lattice of the section (x_min + (i + 1/2) dp, z_bottom + (j + 1/2) dp) wherever that
//    lattice is at least dp/2 inside the section, up to the top of the walls; normals +y and -y.
// For a box whose length, breadth and height dp divides, every wall particle stands on the fluid's
// lattice continued through the walls.
std::vector<WallSample3> sample_walls(const PrismTank& tank, double dp, int layers);

// Fluid particles: the section's fill (fill_fluid: lattice points below `depth`, at least dp/2 from
// the wall) at y = (k + 1/2) dp, k = 0 .. n_y - 1.
std::vector<Vec3> fill_fluid(const PrismTank& tank, double dp, double depth);

// Points of the section (x, height) on the fill's lattice planes across the breadth, y = (k + 1/2)
// dp, k = 0 .. n_y - 1, point by point (3D fill blocks: the section's block fill over the breadth).
std::vector<Vec3> on_planes_across(const PrismTank& tank, double dp, const std::vector<Vec2>& section_points);

// Particles at rest from a fill and its wall samples (WallSample or WallSample3), in 2 or 3
// dimensions: the fluid first, in fill order, then the walls; volume dp^D, mass rho dp^D, the
// hydrostatic pressure rho g (level - height) below the still level (walls too, 0 above it; the
// height is y in 2D, z in 3D; the level is a height, the depth when the bottom is at 0); ids in
// that order.
template <int D, class WallSampleType>
BasicParticles<D> particles_at_rest(const std::vector<Vec<D>>& fluid, const std::vector<WallSampleType>& walls,
                                    double dp, double level, double rho, double g) {
  BasicParticles<D> p;
  p.resize(fluid.size() + walls.size());
  p.n_fluid = fluid.size();
  p.volume = D == 2 ? dp * dp : dp * dp * dp;
  p.mass = rho * p.volume;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool is_fluid = i < fluid.size();
    p.position[i] = is_fluid ? fluid[i] : walls[i - fluid.size()].position;
    if (!is_fluid) p.normal[i] = walls[i - fluid.size()].normal;
    p.pressure[i] = rho * g * std::max(0.0, level - component(p.position[i], D - 1));
    p.density[i] = rho;
    p.id[i] = static_cast<std::int32_t>(i);
  }
  return p;
}

// The particles of `tank` at rest, filled to `depth` with `layers` of wall (for the 3D tests and
// benchmarks that build a tank without a case).
inline Particles3 particles_at_rest(const PrismTank& tank, double dp, double depth, int layers, double rho, double g) {
  return particles_at_rest<3>(fill_fluid(tank, dp, depth), sample_walls(tank, dp, layers), dp,
                              tank.section.y_bottom + depth, rho, g);
}

}  // namespace sloshsph
