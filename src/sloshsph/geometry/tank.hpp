#pragma once
// Tank sections as wall curves, and the particles that discretise them.
// The wall is an open polyline (the wall surface) running from the top of the
// left wall, down through the bottom, to the top of the right wall. The fluid
// lies on its left-hand side, so the inward normal of a segment with direction
// t is perp(t).
#include <cstddef>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

struct TankGeometry {
  std::vector<Vec2> wall;  // wall surface, top-left -> bottom -> top-right
  double x_min = 0.0, x_max = 0.0;  // horizontal extent of the section
  double y_bottom = 0.0;            // lowest point of the wall
  double y_top = 0.0;               // top of the walls

  std::size_t segments() const { return wall.size() - 1; }
  Vec2 inward_normal(std::size_t segment) const;

  // Exact signed distance to the container: the wall polyline with its two end
  // points extended straight up without limit (a splash above the walls is still
  // inside). Positive inside the fluid region. O(number of segments).
  double signed_distance(Vec2 p) const;

  // Height of the wall below x (the lowest wall crossing of the vertical line at x).
  double bottom_at(double x) const;

  // The segment of the wall polyline nearest to p (the first of equally near ones, e.g. at a
  // corner). For placing a sensor face on the wall (geometry/scene.cpp).
  std::size_t nearest_segment(Vec2 p) const;
};

// Builds the section of `spec.shape`. Throws InputError for an unknown shape or bad sizes.
//  rectangle  flat bottom, length x height.
//  parabolic  bottom y = coefficient (x - length/2)^2 (thesis eq. 3.23, B = 0, C = L/2), vertical
//             walls above x = 0 and x = length if the parabola meets them below `height`;
//             otherwise the parabola up to `height`, whose top width must then be `length`
//             within 1% (InputError tank.length).
//  circular   lower half of a circle of diameter `length` centred at (L/2, L/2), vertical walls
//             above the centre line up to `height` (>= L/2, else InputError tank.height).
//  sloped     (aliases triangle: bottom_width = 0, trapezoid: bottom_width > 0) flat part of
//             `bottom_width` centred, slopes at `angle` degrees from the horizontal, vertical walls
//             above them. If the slopes reach `height` before x = 0 / length, the walls end
//             there: the section is then narrower than `length`.
//  polyline   `points` from the top left, down, to the top right, kept as given (y_bottom is
//             the lowest point); validated: >= 3 points, the ends highest, no self-intersection,
//             fluid on the left of the travel (InputError tank.points).
// Curved bottoms are chains of straight segments no longer than length/2000.
TankGeometry make_tank(const TankSpec& spec, const std::string& where);

// The still-water region below the level y_bottom + depth: a counter-clockwise polygon
// (the wall chain from the left crossing of the level down to the right crossing; the
// closing edge is the free surface). Throws InputError (key fill.depth) when the depth is
// not positive, the level is above the top of a wall, or the level meets the wall more
// than twice (several pools).
std::vector<Vec2> still_water_polygon(const TankGeometry& tank, double depth);

// Area (m^2, per metre of width) of the still-water region below `depth`.
double section_area(const TankGeometry& tank, double depth);

// Signed distance sampled on a grid (spacing ~dp/2) for O(1) look-ups in hot paths
// (leak detection). Outside the sampled box it falls back to the exact distance.
class ContainerDistance {
 public:
  ContainerDistance() = default;
  ContainerDistance(const TankGeometry& tank, double spacing, double margin);
  double operator()(Vec2 p) const;

 private:
  const TankGeometry* tank_ = nullptr;
  Vec2 origin_;
  double spacing_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<double> value_;
};

struct WallSample {
  Vec2 position;
  Vec2 normal;  // inward unit normal of the wall at this particle
};

// Dummy wall particles: `layers` copies of the wall, offset outward by
// (k + 1/2) dp, each sampled at equal arc length with spacing <= dp
// (the "nonlinear curved grid" of thesis 3.3.2.1). Straight end walls are
// sampled at exactly dp from the bottom corner so a rectangular tank gets a
// lattice-aligned wall.
std::vector<WallSample> sample_walls(const TankGeometry& tank, double dp, int layers);

// Fluid particles on the lattice ((i + 1/2) dp, (j + 1/2) dp) above the lowest
// point, below `depth`, inside the section and at least dp/2 from the wall.
std::vector<Vec2> fill_fluid(const TankGeometry& tank, double dp, double depth);

// Fluid particles on the same lattice inside the union of the blocks (a lattice node x is in
// a block when from <= x < to), inside the section and at least dp/2 from the wall.
std::vector<Vec2> fill_blocks(const TankGeometry& tank, double dp, const std::vector<FluidBlock>& blocks);

// Whether some block holds the lattice node p (from <= p < to, as fill_blocks counts it).
bool in_blocks(const std::vector<FluidBlock>& blocks, Vec2 p);

// The free surface above p of the water at rest in the blocks: the highest top of the blocks
// that contain p (p.y if none does). For the initial hydrostatic pressure of a block.
double block_surface(const std::vector<FluidBlock>& blocks, Vec2 p);

// Still-water free-surface width at `depth` (the lattice-independent length of the surface).
double surface_width(const TankGeometry& tank, double depth);

}  // namespace sloshsph
