#pragma once
// Geometry of porous elements (screens, baffles, perforated floors): the centre line of an
// element clipped to the tank section, and the rigid slats of an explicitly modelled slat
// screen as wall particles (the "microscopic model" MM of thesis 4.3). The macroscopic
// screen particles and their drag live in physics/porous (they need the kernels).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

// The part of an element's centre line that lies in the tank section: inside the container
// (TankGeometry::signed_distance >= 0) and not above the top of the walls. An element may be
// drawn through a wall or above the top ("to the wall", "to the top"); it is cut there.
struct ClippedLine {
  Vec2 from, to;              // m, ends of the part inside (in the direction from -> to of the spec)
  double length = 0.0;        // m
  bool clipped_from = false;  // the `from` end was cut (it lay outside the section)
  bool clipped_to = false;
  Vec2 direction() const { return length > 0.0 ? (to - from) / length : Vec2{}; }
};

// Clips the segment from -> to to the tank section. Throws InputError(where, key_prefix + ".from")
// when no part of it lies in the section, (key_prefix + ".to") for a zero-length segment, and
// (key_prefix + ".from") when it crosses the section more than once (it would pass through a wall).
ClippedLine clip_to_section(const TankGeometry& tank, Vec2 from, Vec2 to, const std::string& where,
                            const std::string& key_prefix);

// Solidity S of an element (thesis eq. 2.23: porosity n_w = 1 - S): `solidity`, or
// h_slat / (h_slat + h_gap) when slat sizes are given (both must then agree within 1e-6).
// Returns 0 when neither is given. Throws InputError (key_prefix.solidity / .slat_height /
// .slat_gap) for values out of range or in disagreement.
double element_solidity(const ScreenSpec& spec, const std::string& where, const std::string& key_prefix);

// An explicit slat screen: slats of height h_slat (along the centre line) and thickness t_sc
// (across it), separated by gaps h_gap, as blocks of fixed wall particles.
//  * Layout: starting at the (clipped) `from` end with a slat, then gap, slat, ... to the `to`
//    end; the last slat is cut at the end of the line if the line ends inside it. (The thesis
//    does not say where the pattern starts; a screen standing on the floor then has a slat at
//    the floor.)
//  * Each slat is a block of n_a x n_t particles, n_a = max(1, round(slat length / dp)) along the
//    line, n_t = max(1, round(t_sc / dp)) across it, at the centres of equal sub-cells: the
//    particles tile the slat exactly.
//  * Normals: the outward normal of the nearest face of the slat rectangle (for a thin slat, the
//    across-thickness face; the free-slip reflection u - 2 (u.n) n does not depend on its sign).
struct SlatLayout {
  std::vector<WallSample> walls;
  std::vector<std::pair<double, double>> slats;  // m, [start, end) of each slat along the line from `line.from`
  ClippedLine line;
  double solidity = 0.0;   // covered length / line length of the layout
  std::vector<std::string> warnings;  // dp too coarse for the slats or the gaps
};

// Throws InputError (keys under key_prefix) for a bad element: slat_height and slat_gap must be
// positive, thickness positive, the line inside the tank.
SlatLayout explicit_slat_layout(const ScreenSpec& spec, double dp, const TankGeometry& tank,
                                const std::string& where, const std::string& key_prefix);

// The wall particles of explicit_slat_layout (where = "<screen>", key prefix "screens").
std::vector<WallSample> explicit_slat_walls(const ScreenSpec& spec, double dp, const TankGeometry& tank);

}  // namespace sloshsph
