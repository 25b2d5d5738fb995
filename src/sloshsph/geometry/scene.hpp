#pragma once
// The initial particle set of a case: fluid filled into the tank section, dummy wall
// particles along its walls, hydrostatic pressure. Built before any output exists,
// so a bad geometry fails without leaving a half-written run directory.
#include <memory>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/particles.hpp"
#include "sloshsph/geometry/plates.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

// Where a pressure probe reads: the point `from` (== `to`), or the mean over the face from
// `from` to `to` (observe/probes.hpp pressure_on_face).
struct PressureSensor {
  Vec2 from, to;
  bool face = false;
};

struct Scene {
  std::shared_ptr<const TankGeometry> tank;  // shared: ContainerDistance points into it
  Particles particles;
  double dp = 0.0;
  double h = 0.0;              // kernel smoothing length, kernel_ratio * dp
  double still_level = 0.0;    // y of the still free surface
  double initial_fluid_mass = 0.0;  // kg per metre of width
  std::size_t initial_fluid_count = 0;
  std::vector<ScreenSpec> screens;  // the case's screens, full-height ones resolved to from/to
  // Elastic plates: their layouts and where their wall particles start in the particle store
  // (plate k holds particles [plate_first[k], plate_first[k] + plates[k].walls.size())). They
  // are the last wall particles, after the tank walls and the explicit slats.
  std::vector<PlateLayout> plates;
  std::vector<std::size_t> plate_first;
  std::vector<PressureSensor> pressure_sensors;  // one per [[probes.pressure]], in case order
  std::vector<std::string> warnings;  // set-up remarks for the user (e.g. slats too fine for dp)
};

// Throws InputError (naming the key) when the geometry cannot hold the case.
Scene build_scene(const CaseSpec& spec);

}  // namespace sloshsph
