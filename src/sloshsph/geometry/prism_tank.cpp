#include "sloshsph/geometry/prism_tank.hpp"

#include <algorithm>
#include <cmath>

namespace sloshsph {
namespace {

// Lattice planes y = (k + 1/2) dp inside the breadth: dp/2 from the end walls when dp divides it.
int planes_across(const PrismTank& tank, double dp) { return static_cast<int>(std::floor(tank.breadth / dp + 1e-9)); }

}  // namespace

std::vector<WallSample3> sample_walls(const PrismTank& tank, double dp, int layers) {
  std::vector<WallSample3> out;
  const int n_y = planes_across(tank, dp);
  for (const WallSample& w : sample_walls(tank.section, dp, layers))
    for (int k = -layers; k < n_y + layers; ++k)
      out.push_back({at_breadth(w.position, (k + 0.5) * dp), at_breadth(w.normal, 0.0)});
  // The end walls, on the fill's lattice of the section up to the top of the walls.
  const TankGeometry& s = tank.section;
  const int ni = static_cast<int>(std::ceil((s.x_max - s.x_min) / dp));
  const int nj = static_cast<int>(std::ceil((s.y_top - s.y_bottom) / dp));
  for (int layer = 0; layer < layers; ++layer) {
    const double offset = (layer + 0.5) * dp;
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        const Vec2 q{s.x_min + (i + 0.5) * dp, s.y_bottom + (j + 0.5) * dp};
        if (s.signed_distance(q) < 0.5 * dp * (1.0 - 1e-9)) continue;
        out.push_back({at_breadth(q, -offset), {0.0, 1.0, 0.0}});
        out.push_back({at_breadth(q, tank.breadth + offset), {0.0, -1.0, 0.0}});
      }
  }
  return out;
}

std::vector<Vec3> fill_fluid(const PrismTank& tank, double dp, double depth) {
  return on_planes_across(tank, dp, fill_fluid(tank.section, dp, depth));
}

std::vector<Vec3> on_planes_across(const PrismTank& tank, double dp, const std::vector<Vec2>& section_points) {
  std::vector<Vec3> out;
  const int n_y = planes_across(tank, dp);
  for (const Vec2& q : section_points)
    for (int k = 0; k < n_y; ++k) out.push_back(at_breadth(q, (k + 0.5) * dp));
  return out;
}

}  // namespace sloshsph
