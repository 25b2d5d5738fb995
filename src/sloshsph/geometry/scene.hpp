#pragma once
// The initial particle set of a case: fluid filled into the tank section, dummy wall
// particles along its walls, hydrostatic pressure. Built before any output exists,
// so a bad geometry fails without leaving a half-written run directory.
#include <memory>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/particles.hpp"
#include <optional>

#include "sloshsph/geometry/cylinder_tank.hpp"
#include "sloshsph/geometry/plates.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

// Where a pressure probe reads: the point `from` (== `to`), or the mean over the face from
// `from` to `to` (observe/probes.hpp pressure_on_face). In 3D a point only, so far.
template <int D>
struct BasicPressureSensor {
  Vec<D> from, to;
  bool face = false;
};
using PressureSensor = BasicPressureSensor<2>;

// The particles and geometry of a case, in 2 or 3 dimensions. In 3D the tank is `tank` (the
// section, in the x-z plane) extruded over `breadth` (geometry/prism_tank.hpp), and so are the
// porous screens (ergun, morison; physics/porous.hpp), the explicit slats and the plates (on the
// lattice planes across the breadth; in a cylinder no plates).
template <int D>
struct BasicScene {
  // The section; shared: ContainerDistance points into it. For a cylinder, the rectangle 2R x
  // height that it stands in (its bounds and flat bottom).
  std::shared_ptr<const TankGeometry> tank;
  double breadth = 0.0;        // m, 3D: the tank spans 0 <= y <= breadth
  std::optional<CylinderTank> cylinder;  // 3D, shape "cylinder": the tank is this, not the extruded section
  BasicParticles<D> particles;
  double dp = 0.0;
  double h = 0.0;              // kernel smoothing length, kernel_ratio * dp
  double still_level = 0.0;    // height (y in 2D, z in 3D) of the still free surface
  double initial_fluid_mass = 0.0;  // kg per metre of width (2D), kg (3D)
  std::size_t initial_fluid_count = 0;
  std::vector<ScreenSpec> screens;  // the case's screens, full-height ones resolved to from/to
  // Elastic plates: their layouts and where their wall particles start in the particle store
  // (plate k holds particles [plate_first[k], plate_first[k] + plates[k].walls.size() x the planes
  // across the breadth in 3D, below)). They
  // are the last wall particles, after the tank walls and the explicit slats.
  std::vector<PlateLayout> plates;
  std::vector<std::size_t> plate_first;
  // 3D: the y of the lattice planes across the breadth the plates' section particles stand on
  // (plate k's particle j * plate_planes.size() + m is section particle j on plane m).
  std::vector<double> plate_planes;
  std::vector<BasicPressureSensor<D>> pressure_sensors;  // one per [[probes.pressure]], in case order
  std::vector<std::string> warnings;  // set-up remarks for the user (e.g. slats too fine for dp)
};
using Scene = BasicScene<2>;
using Scene3 = BasicScene<3>;

// Throws InputError (naming the key) when the geometry cannot hold the case.
Scene build_scene(const CaseSpec& spec);
// The 3D scene of a case with tank.dimensions = 3: the section extruded over the breadth, filled
// to fill.depth; the gauges and probes checked to lie in the tank. Throws InputError.
Scene3 build_scene3(const CaseSpec& spec);

template <int D>
BasicScene<D> build_scene_in(const CaseSpec& spec) {
  if constexpr (D == 2) return build_scene(spec);
  else return build_scene3(spec);
}

}  // namespace sloshsph
