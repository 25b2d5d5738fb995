#pragma once
// Upright circular cylinders (issue 31, section 2): `[tank] dimensions = 3, shape = "cylinder"`,
// radius R and wall height. Axes as for the prism tanks: x and y horizontal, z up; the axis of the
// cylinder stands at (R, R), so that the tank fills 0 <= x, y <= 2R like a box of side 2R, and the
// bottom is z = 0.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/geometry/prism_tank.hpp"

namespace sloshsph {

struct CylinderTank {
  double radius = 0.0;  // m, inner radius R
  double height = 0.0;  // m, wall height above the bottom

  Vec2 axis() const { return {radius, radius}; }
  // The horizontal distance of p from the axis.
  double from_axis(Vec3 p) const { return std::hypot(p.x - radius, p.y - radius); }
  // Positive inside: the smaller of R - r and z (the wall extended up without limit, as the
  // sections' are). Exact inside; below the bottom and outside the side at once, the larger of
  // the two distances (at the edge, at most the true distance).
  double signed_distance(Vec3 p) const { return std::min(radius - from_axis(p), p.z); }
};

// The tank an upright cylinder stands in, as the section of a box in the plane (x, z): the rectangle
// 2R x height (the case reader sets its length and breadth to 2R). Any other tank is its own section.
// The scene builds the cylinder's section on it, and the case reader checks fill blocks against it.
inline TankSpec plane_section(const TankSpec& spec) {
  TankSpec section = spec;
  if (section.shape == "cylinder") section.shape = "rectangle";
  return section;
}

// The cylinder of a case's tank (shape "cylinder").
inline CylinderTank cylinder_of(const TankSpec& spec) { return {spec.radius, spec.height}; }

// The signed distance (positive inside) of a case's tank in D dimensions: in 2D its section
// (TankGeometry::signed_distance); in 3D the upright cylinder's, or the section extruded over the
// breadth (container_signed_distance). For what marks wall particles by their depth in the wall
// (the repulsive layers of both schemes). Throws InputError(where, "tank...") for a bad tank.
template <int D>
std::function<double(Vec<D>)> tank_signed_distance(const TankSpec& spec, const std::string& where) {
  if constexpr (D == 2) {
    return [tank = make_tank(spec, where)](Vec2 p) { return tank.signed_distance(p); };
  } else if (spec.shape == "cylinder") {
    return [tank = cylinder_of(spec)](Vec3 p) { return tank.signed_distance(p); };
  } else {
    return [tank = PrismTank{make_tank(spec, where), spec.breadth}](Vec3 p) { return tank.signed_distance(p); };
  }
}

// Dummy wall particles, `layers` deep:
//  * the side: layer k (0 .. layers - 1) on the cylinder of radius R + (k + 1/2) dp, n_k =
//    round(2 pi (R + (k + 1/2) dp) / dp) particles around (the arc spacing within a few per cent of
//    dp; odd layers turned by half a spacing), on the levels z = (m + 1/2) dp from below the bottom's
//    layers (m = -layers) up to the top of the wall, so that the edge with the bottom is filled;
//    inward normal towards the axis;
//  * the bottom: `layers` planes z = -(k + 1/2) dp of the fill's lattice ((i + 1/2) dp, (j + 1/2) dp)
//    with r < R; normal +z.
std::vector<WallSample3> sample_walls(const CylinderTank& tank, double dp, int layers);

// Fluid particles on the cubic lattice ((i + 1/2) dp, (j + 1/2) dp, (k + 1/2) dp) at least dp/2 inside
// the side wall (r <= R - dp/2), as many as hold the water of `depth` (cylinder_fill_count: their
// volume n dp^3 is pi R^2 depth to half a particle): whole layers from the bottom, and of the last
// one the points nearest the axis. The square lattice does not reach the round wall everywhere (a
// ring of gaps about dp/2 to dp wide, some dp/R of the water), so the fill stands higher than
// `depth` and settles to it, filling the ring (time.settle). When dp divides 2R the whole layers
// are symmetric about the axis.
std::vector<Vec3> fill_fluid(const CylinderTank& tank, double dp, double depth);

// Fluid particles of [[fill.blocks]] (issue 31): the nodes of the same lattice inside r <= R - dp/2
// whose (x, z) a block holds (in_blocks), in lattice order. A block is a rectangle of the plane
// (x, z) over every y inside the circle, as in a box it is over the whole breadth.
std::vector<Vec3> fill_blocks(const CylinderTank& tank, double dp, const std::vector<FluidBlock>& blocks);

// round(pi R^2 depth / dp^3): the particles of volume dp^3 that hold the water of `depth`.
std::size_t cylinder_fill_count(const CylinderTank& tank, double dp, double depth);

// The level that `particles` of volume dp^3 settle to in the cylinder: their volume over pi R^2
// (the fill's depth, to half a particle).
inline double cylinder_settled_level(const CylinderTank& tank, std::size_t particles, double dp) {
  return static_cast<double>(particles) * dp * dp * dp / (3.141592653589793 * tank.radius * tank.radius);
}

// 1.8412, the first zero of J1': k_1 R of the first mode of an upright cylinder.
inline constexpr double kCylinderFirstRoot = 1.8412;

// The first sloshing mode of an upright cylinder of radius R filled to h (linear potential
// theory; e.g. Ibrahim 2005, ch. 2): omega^2 = g k tanh(k h), k = 1.8412 / R, 1.8412 the first
// zero of J1'.
double cylinder_first_sloshing_omega(double radius, double depth, double gravity);

// The first mode's convective (sloshing) mass as a fraction of the liquid's, under a horizontal
// motion (linear potential theory; Abramson 1966, NASA SP-106, ch. 6; Ibrahim 2005, ch. 2):
//   m_1 / m = 2 tanh(xi h / R) / (xi (xi^2 - 1) h / R),   xi = 1.8412.
double cylinder_convective_mass_fraction(double radius, double depth);

}  // namespace sloshsph
