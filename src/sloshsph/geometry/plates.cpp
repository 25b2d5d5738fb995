#include "sloshsph/geometry/plates.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

void check_inside(const TankGeometry& tank, Vec2 point, double dp, const std::string& where, const std::string& key) {
  // An end may sit on the wall surface (a clamped root), not beyond it.
  if (tank.signed_distance(point) < -0.25 * dp || point.y > tank.y_top + 1e-12) {
    std::ostringstream m;
    m << "the plate end (" << point.x << ", " << point.y << ") m lies outside the tank section";
    throw InputError(where, key, m.str());
  }
}

}  // namespace

PlateLayout plate_layout(const PlateSpec& spec, double dp, const TankGeometry& tank, const std::string& where,
                         const std::string& key_prefix) {
  PlateLayout out;
  out.spec = spec;
  PlateSpec& s = out.spec;
  if (s.standing_height > 0.0) {
    if (s.from.x <= tank.x_min || s.from.x >= tank.x_max)
      throw InputError(where, key_prefix + ".x", "the plate stands outside the tank");
    s.from = {s.from.x, tank.bottom_at(s.from.x)};
    s.to = {s.from.x, s.from.y + s.standing_height};
  }
  check_inside(tank, s.from, dp, where, key_prefix + (s.standing_height > 0.0 ? ".x" : ".from"));
  check_inside(tank, s.to, dp, where, key_prefix + (s.standing_height > 0.0 ? ".height" : ".to"));
  const double length = norm(s.to - s.from);
  if (length < 2.0 * dp)
    throw InputError(where, key_prefix + (s.standing_height > 0.0 ? ".height" : ".to"),
                     "the plate is shorter than 2 dp: the particles cannot represent it");
  // Two layers at least: with one, the fluid on either side interacts through the plate and the
  // weakly compressible run blew up (dp = 3 mm, t = 3 mm: 21 m/s at 0.03 s; docs/validation.md).
  if (s.thickness < 1.5 * dp)
    throw InputError(where, key_prefix + ".thickness",
                     "the plate is thinner than 1.5 dp: two particle layers must fit across it "
                     "(particles.dp at most thickness / 1.5)");

  const Vec2 along = (s.to - s.from) / length;
  const Vec2 across = perp(along);
  const double t = s.thickness;
  out.along = std::max(1, static_cast<int>(std::lround(length / dp)));
  out.across = std::max(1, static_cast<int>(std::lround(t / dp)));
  const double da = length / out.along, dt = t / out.across;
  const bool free_from = s.from_support == PlateSupport::free, free_to = s.to_support == PlateSupport::free;
  for (int ia = 0; ia < out.along; ++ia)
    for (int it = 0; it < out.across; ++it) {
      const double a = (ia + 0.5) * da;     // from the `from` end
      const double c = (it + 0.5) * dt - 0.5 * t;  // from the centre line, + towards `across`
      const double to_side = 0.5 * t - std::abs(c);
      const double to_from_end = free_from ? a : 1e300, to_to_end = free_to ? length - a : 1e300;
      WallSample w;
      w.position = s.from + a * along + c * across;
      double face = 0.0, distance = 0.0;
      const bool on_side = to_side < 0.5 * dt + 1e-12 * t;  // outer layer
      const double end = std::min(to_from_end, to_to_end);
      if (end < to_side - 1e-12 * t) {  // nearest face: a free end
        w.normal = to_to_end <= to_from_end ? along : -1.0 * along;
        if (end < 0.5 * da + 1e-12 * length) {
          face = dt;
          distance = 0.5 * da;
        }
      } else {
        w.normal = c >= 0.0 ? across : -1.0 * across;
        if (on_side) {
          face = da;
          distance = 0.5 * dt;
        }
      }
      out.walls.push_back(w);
      out.face_length.push_back(face);
      out.face_distance.push_back(distance);
    }
  return out;
}

}  // namespace sloshsph
