#pragma once
// Geometry of an elastic plate ([[plates]]): its centre line resolved in the tank section and
// the wall particles that stand for it in the fluid. The plate's motion and loads live in
// run/plate_coupling (they need the beam solver).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

// One face of the plate's rectangle that a particle stands for: its outward normal (undeformed),
// the length of the face it covers and the distance from the particle to the face. length = 0: none.
struct PlateFace {
  Vec2 normal;
  double length = 0.0;    // m
  double distance = 0.0;  // m
};

// The wall particles of one plate, as a block tiling its undeformed rectangle (length L along
// the centre line, thickness t across it), like an explicit slat (geometry/screens.hpp):
//  * n_a = max(1, round(L / dp)) particles along, n_t = max(1, round(t / dp)) across, at the centres
//    of equal sub-cells (t + dp >= 2h gives n_t >= 2 for h >= 1.25 dp);
//  * the faces that can meet fluid: the two long faces and a free end (a supported end sits on a
//    wall). A particle of the outer layers stands for L / n_a of a long face (side_face), one of
//    the row at a free end for t / n_t of it (end_face), a corner particle for both; the fluid load
//    on the plate is the integral of the face pressure over them (run/plate_coupling.hpp);
//  * normal (for the wall model): its face's outward normal; at a corner the diagonal (the two
//    faces' normals summed), so fluid beyond the free end and beside the plate both face it; inside
//    the block (n_t >= 3), the normal of the nearest face.
struct PlateLayout {
  PlateSpec spec;                  // from/to resolved (a standing plate: from the bottom at x, up)
  std::vector<WallSample> walls;   // in the undeformed position
  std::vector<PlateFace> side_face;
  std::vector<PlateFace> end_face;
  int along = 0, across = 0;       // n_a, n_t
};

// Throws InputError (keys under key_prefix, e.g. "plates.0") when the plate does not lie in the
// tank section, is shorter than 2 dp, or is so thin for the kernel support (2h) that the fluid on
// its two sides would interact through it (thickness + dp < support).
// `where(key)` gives the location (file:line) of a dotted key for the messages.
using KeyLocation = std::function<std::string(const std::string& key)>;
PlateLayout plate_layout(const PlateSpec& spec, double dp, double support, const TankGeometry& tank,
                         const KeyLocation& where, const std::string& key_prefix);

}  // namespace sloshsph
