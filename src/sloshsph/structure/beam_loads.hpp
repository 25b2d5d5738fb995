#pragma once
#include <vector>

#include "sloshsph/core/vec2.hpp"

// Loads on a beam and the conversion of distributed loads to consistent nodal forces.
// The beam elements interpolate the centreline linearly (beam_element.hpp), so the consistent
// nodal forces of a line load q(s) are f_i = integral N_i q ds with N_1 = 1 - s/L, N_2 = s/L
// (Zienkiewicz & Taylor, "The Finite Element Method", vol. 1, consistent load vector).
namespace sloshsph {

struct BeamLoads {
  std::vector<Vec2> nodal_forces;     // [N] one per node, or empty for none
  std::vector<double> nodal_moments;  // [N m] one per node, or empty
  // Follower pressure [Pa] on the face `pressure_side` (+1: the face on the +director side,
  // i.e. to the left when walking from the first node to the last), given at the nodes and
  // linear along each element; it acts normal to the *deformed* centreline (converted by
  // pressure_nodal_forces and linearised in the Newton tangent). Empty for none.
  std::vector<double> nodal_pressure;
  int pressure_side = +1;
  // [m/s^2] uniform body acceleration added to BeamSpec::gravity, e.g. -a_tank for a beam whose
  // support translates with the tank (the solver works in the tank frame).
  Vec2 body_acceleration{};
};

// Consistent nodal forces [N] of a line load [N/m] given at the nodes and linear along each straight
// element of the polyline `nodes` (lengths measured on `nodes`): f_1 += L (2 q_1 + q_2) / 6,
// f_2 += L (q_1 + 2 q_2) / 6. Already the load of the whole width: pass force per unit length of beam.
std::vector<Vec2> line_load_nodal_forces(const std::vector<Vec2>& nodes, const std::vector<Vec2>& load_per_length);

// Consistent nodal forces [N] of a pressure [Pa] acting on face `side` (+1 or -1) of the polyline
// `nodes` (usually Beam::node_positions(), i.e. the deformed centreline), over the out-of-plane width
// [m]. A positive pressure pushes the face inwards: the load per length is -side * p * width * perp(e)
// with e the unit tangent.
std::vector<Vec2> pressure_nodal_forces(const std::vector<Vec2>& nodes, const std::vector<double>& pressure,
                                        int side, double width);

}  // namespace sloshsph
