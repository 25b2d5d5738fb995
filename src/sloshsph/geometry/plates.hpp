#pragma once
// Geometry of an elastic plate ([[plates]]): its centre line resolved in the tank section and
// the wall particles that stand for it in the fluid. The plate's motion and loads live in
// run/plate_coupling (they need the beam solver).
#include <cstddef>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

// The wall particles of one plate, as a block tiling its undeformed rectangle (length L along
// the centre line, thickness t across it), like an explicit slat (geometry/screens.hpp):
//  * n_a = max(1, round(L / dp)) particles along, n_t = max(1, round(t / dp)) across, at the
//    centres of equal sub-cells;
//  * normal: the outward normal of the nearest face of the rectangle that can meet fluid (the
//    two long faces and a free end; a supported end sits on a wall). Ties go to the long faces.
//  * face_length: the length of that face the particle stands for (L / n_a on a long face,
//    t / n_t on a free end), 0 for a particle inside the block (n_t >= 3): the fluid force on
//    the plate is the integral of the face pressure (run/plate_coupling.hpp);
//  * face_distance: from the particle to its face along the normal (half its cell).
// At least two layers (n_t >= 2, thickness >= 1.5 dp): each particle then faces the fluid of one side.
struct PlateLayout {
  PlateSpec spec;                  // from/to resolved (a standing plate: from the bottom at x, up)
  std::vector<WallSample> walls;   // in the undeformed position
  std::vector<double> face_length;    // m
  std::vector<double> face_distance;  // m
  int along = 0, across = 0;          // n_a, n_t
};

// Throws InputError (keys under key_prefix, e.g. "plates.0") when the plate does not lie in the
// tank section or is too thin or short for dp to represent it.
PlateLayout plate_layout(const PlateSpec& spec, double dp, const TankGeometry& tank, const std::string& where,
                         const std::string& key_prefix);

}  // namespace sloshsph
