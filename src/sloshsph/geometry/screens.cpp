#include "sloshsph/geometry/screens.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {

namespace {

std::string metres(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v << " m";
  return s.str();
}

// Distance into the section: > 0 inside the container and below the top of the walls.
double section_margin(const TankGeometry& tank, Vec2 p) {
  return std::min(tank.signed_distance(p), tank.y_top - p.y);
}

}  // namespace

ClippedLine clip_to_section(const TankGeometry& tank, Vec2 from, Vec2 to, const std::string& where,
                            const std::string& key_prefix) {
  const double length = norm(to - from);
  const double scale = std::max({1.0, tank.x_max - tank.x_min, tank.y_top - tank.y_bottom});
  if (!(length > 1e-12 * scale))
    throw InputError(where, key_prefix + ".to", "the element has zero length (from = to)");
  // Round-off tolerance, so that an end drawn exactly on a wall counts as inside.
  const double eps = 1e-9 * scale;
  auto point = [&](double t) { return from + t * (to - from); };
  auto inside = [&](double t) { return section_margin(tank, point(t)) >= -eps; };

  // Sample finely enough to see every crossing of a wall (curved bottoms are chains of segments
  // no longer than length/2000), then bisect the crossings.
  const int samples = std::clamp(static_cast<int>(std::ceil(2000.0 * length / scale)), 64, 8192);
  std::vector<char> in(samples + 1);
  for (int k = 0; k <= samples; ++k) in[k] = inside(double(k) / samples) ? 1 : 0;
  int first = -1, last = -1, runs = 0;
  for (int k = 0; k <= samples; ++k) {
    if (in[k] && (k == 0 || !in[k - 1])) ++runs;
    if (in[k]) {
      if (first < 0) first = k;
      last = k;
    }
  }
  if (runs == 0)
    throw InputError(where, key_prefix + ".from",
                     "the element lies outside the tank section (from and to are both outside the walls)");
  if (runs > 1)
    throw InputError(where, key_prefix + ".from",
                     "the element crosses a wall of the tank (it enters the section more than once)");

  // Bisection between an outside parameter `out` and an inside one `inn`, to the wall itself
  // (margin >= 0, no tolerance), so that the clipped ends lie on the wall to round-off.
  auto boundary = [&](double out, double inn) {
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (out + inn);
      (section_margin(tank, point(mid)) >= 0.0 ? inn : out) = mid;
    }
    return inn;
  };
  ClippedLine c;
  const double t0 = first == 0 ? 0.0 : boundary(double(first - 1) / samples, double(first) / samples);
  const double t1 = last == samples ? 1.0 : boundary(double(last + 1) / samples, double(last) / samples);
  c.from = point(t0);
  c.to = point(t1);
  c.length = norm(c.to - c.from);
  c.clipped_from = first != 0;
  c.clipped_to = last != samples;
  if (!(c.length > 1e-9 * scale))
    throw InputError(where, key_prefix + ".from", "the element only touches the tank section at a point");
  return c;
}

double element_solidity(const ScreenSpec& spec, const std::string& where, const std::string& key_prefix) {
  if (spec.slat_height < 0.0) throw InputError(where, key_prefix + ".slat_height", "must not be negative");
  if (spec.slat_gap < 0.0) throw InputError(where, key_prefix + ".slat_gap", "must not be negative");
  if ((spec.slat_height > 0.0) != (spec.slat_gap > 0.0))
    throw InputError(where, key_prefix + (spec.slat_height > 0.0 ? ".slat_gap" : ".slat_height"),
                     "give both slat_height and slat_gap, or neither");
  if (spec.solidity < 0.0 || spec.solidity >= 1.0)
    throw InputError(where, key_prefix + ".solidity", "must be in [0, 1) (porosity n_w = 1 - S, thesis eq. 2.23)");
  if (spec.slat_height > 0.0) {
    const double s = spec.slat_height / (spec.slat_height + spec.slat_gap);
    if (spec.solidity > 0.0 && std::abs(spec.solidity - s) > 1e-6)
      throw InputError(where, key_prefix + ".solidity",
                       "disagrees with slat_height / (slat_height + slat_gap) = " + std::to_string(s));
    return s;
  }
  return spec.solidity;
}

SlatLayout explicit_slat_layout(const ScreenSpec& spec, double dp, const TankGeometry& tank, const std::string& where,
                                const std::string& key_prefix) {
  if (!(spec.slat_height > 0.0))
    throw InputError(where, key_prefix + ".slat_height", "an explicit slat screen needs slat_height > 0");
  if (!(spec.slat_gap > 0.0))
    throw InputError(where, key_prefix + ".slat_gap", "an explicit slat screen needs slat_gap > 0");
  if (!(spec.thickness > 0.0)) throw InputError(where, key_prefix + ".thickness", "must be positive");
  element_solidity(spec, where, key_prefix);  // consistency of `solidity` with the slats
  if (!(dp > 0.0)) throw InputError(where, "particles.dp", "must be positive");

  SlatLayout out;
  out.line = clip_to_section(tank, spec.from, spec.to, where, key_prefix);
  const double length = out.line.length;
  const Vec2 along = out.line.direction();
  const Vec2 across = perp(along);
  const double t = spec.thickness;
  const double tiny = 1e-12 * length;

  const double period = spec.slat_height + spec.slat_gap;
  for (int k = 0; k * period < length - tiny; ++k)
    out.slats.emplace_back(k * period, std::min(k * period + spec.slat_height, length));

  const int n_t = std::max(1, static_cast<int>(std::lround(t / dp)));
  const double dt = t / n_t;
  double covered = 0.0;
  for (const auto& [a, b] : out.slats) {
    const double len = b - a;
    covered += len;
    const int n_a = std::max(1, static_cast<int>(std::lround(len / dp)));
    const double da = len / n_a;
    for (int ia = 0; ia < n_a; ++ia)
      for (int it = 0; it < n_t; ++it) {
        const double s = a + (ia + 0.5) * da;
        const double c = (it + 0.5) * dt - 0.5 * t;
        WallSample w;
        w.position = out.line.from + s * along + c * across;
        // Nearest face of the slat rectangle; the across-thickness faces win ties (to round-off:
        // a corner particle of a tiled block is equally far from two faces).
        const double tie = 1e-9 * dp;
        double best = 0.5 * t - c;
        w.normal = across;
        if (c + 0.5 * t < best - tie) best = c + 0.5 * t, w.normal = -across;
        if (s - a < best - tie) best = s - a, w.normal = -along;
        if (b - s < best - tie) best = b - s, w.normal = along;
        out.walls.push_back(w);
      }
  }
  out.solidity = covered / length;

  if (dp > t)
    out.warnings.push_back(key_prefix + ".thickness: the slats (t_sc = " + metres(t) + ") are thinner than dp = " +
                           metres(dp) + "; each is one particle thick, i.e. modelled about dp thick");
  if (dp > 0.5 * spec.slat_gap)
    out.warnings.push_back(key_prefix + ".slat_gap: the gaps (h_gap = " + metres(spec.slat_gap) +
                           ") are narrower than 2 dp = " + metres(2.0 * dp) +
                           "; fluid particles barely pass and the wall kernels close the gaps");
  if (dp > spec.slat_height)
    out.warnings.push_back(key_prefix + ".slat_height: the slats (h_slat = " + metres(spec.slat_height) +
                           ") are shorter than dp = " + metres(dp) + "; each is one particle long");
  return out;
}

std::vector<WallSample> explicit_slat_walls(const ScreenSpec& spec, double dp, const TankGeometry& tank) {
  return explicit_slat_layout(spec, dp, tank, "screen '" + spec.name + "'", "screens").walls;
}

}  // namespace sloshsph
