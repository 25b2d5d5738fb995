#include "sloshsph/structure/beam_loads.hpp"

#include <string>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {

namespace {

void require_one_value_per_node(std::size_t values, std::size_t nodes, const char* key) {
  if (nodes < 2) throw InputError("beam loads", key, "needs at least two nodes");
  if (values != nodes) {
    throw InputError("beam loads", key,
                     "expected " + std::to_string(nodes) + " values (one per node), got " + std::to_string(values));
  }
}

}  // namespace

std::vector<Vec2> line_load_nodal_forces(const std::vector<Vec2>& nodes, const std::vector<Vec2>& load_per_length) {
  require_one_value_per_node(load_per_length.size(), nodes.size(), "load_per_length");
  std::vector<Vec2> forces(nodes.size());
  for (std::size_t e = 0; e + 1 < nodes.size(); ++e) {
    const double length = norm(nodes[e + 1] - nodes[e]);
    const Vec2 q1 = load_per_length[e];
    const Vec2 q2 = load_per_length[e + 1];
    forces[e] += (length / 6.0) * (2.0 * q1 + q2);
    forces[e + 1] += (length / 6.0) * (q1 + 2.0 * q2);
  }
  return forces;
}

std::vector<Vec2> pressure_nodal_forces(const std::vector<Vec2>& nodes, const std::vector<double>& pressure,
                                        int side, double width) {
  require_one_value_per_node(pressure.size(), nodes.size(), "pressure");
  if (side != 1 && side != -1) throw InputError("beam loads", "pressure_side", "must be +1 or -1");
  std::vector<Vec2> forces(nodes.size());
  for (std::size_t e = 0; e + 1 < nodes.size(); ++e) {
    // |d| * unit normal = perp(d): the element length cancels against the normalisation.
    const Vec2 normal_times_length = perp(nodes[e + 1] - nodes[e]);
    const double p1 = pressure[e];
    const double p2 = pressure[e + 1];
    const double scale = -static_cast<double>(side) * width / 6.0;
    forces[e] += (scale * (2.0 * p1 + p2)) * normal_times_length;
    forces[e + 1] += (scale * (p1 + 2.0 * p2)) * normal_times_length;
  }
  return forces;
}

}  // namespace sloshsph
