#include "sloshsph/geometry/tank.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {
namespace {

constexpr double kFar = 1.0e6;  // "without limit" for the upward extension of the end walls

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = norm2(ab);
  double t = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return norm(p - (a + t * ab));
}

// Calls f(a, b) for every edge of the closed container polygon: the wall chain,
// its ends raised to kFar, and the closing edge far above.
template <class F>
void for_each_container_edge(const std::vector<Vec2>& wall, F&& f) {
  const Vec2 top_left{wall.front().x, kFar}, top_right{wall.back().x, kFar};
  f(top_left, wall.front());
  for (std::size_t k = 0; k + 1 < wall.size(); ++k) f(wall[k], wall[k + 1]);
  f(wall.back(), top_right);
  f(top_right, top_left);
}

void check_positive(double v, const std::string& where, const std::string& key) {
  if (!(v > 0.0) || !std::isfinite(v)) throw InputError(where, key, "must be a positive number");
}

TankGeometry rectangle(const TankSpec& spec, const std::string& where) {
  check_positive(spec.length, where, "tank.length");
  check_positive(spec.height, where, "tank.height");
  TankGeometry t;
  t.wall = {{0.0, spec.height}, {0.0, 0.0}, {spec.length, 0.0}, {spec.length, spec.height}};
  return t;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Appends the curve c(u), u in [u0, u1], as a chain of straight segments no longer
// than max_segment, in equal parameter steps (c(u0) is not appended: it is already the
// chain's last point).
template <class Curve>
void append_curve(std::vector<Vec2>& chain, Curve&& c, double u0, double u1, double max_segment) {
  constexpr int kProbe = 64;
  double longest = 0.0;
  for (int k = 0; k < kProbe; ++k)
    longest = std::max(longest, norm(c(u0 + (u1 - u0) * (k + 1) / kProbe) - c(u0 + (u1 - u0) * k / kProbe)));
  int n = static_cast<int>(std::ceil(1.05 * kProbe * longest / max_segment));  // 5% margin on the chord estimate
  n = std::max(2, n + (n % 2));
  for (int k = 1; k <= n; ++k) chain.push_back(c(u0 + (u1 - u0) * k / n));
}

// Curved walls are discretised much finer than any particle spacing (the sampler then
// places particles at equal arc length along this chain).
double curve_segment(const TankSpec& spec) { return spec.length / 2000.0; }

// Appends p unless it repeats the chain's last point (no zero-length segments).
void append_point(std::vector<Vec2>& chain, Vec2 p) {
  if (norm(p - chain.back()) > 1e-12 * (1.0 + norm(p))) chain.push_back(p);
}

std::vector<Vec2> mirrored_walls(std::vector<Vec2> left_to_bottom, double length) {
  // left_to_bottom runs from the top left to the lowest point at x = length/2; mirror it.
  const std::size_t n = left_to_bottom.size();
  for (std::size_t k = n - 1; k-- > 0;) left_to_bottom.push_back({length - left_to_bottom[k].x, left_to_bottom[k].y});
  return left_to_bottom;
}

// Parabolic bottom y = c (x - L/2)^2 (thesis eq. 3.23 with B = 0, C = L/2), vertical
// walls above the points where it meets x = 0 and x = L if that is below the wall top.
TankGeometry parabolic(const TankSpec& spec, const std::string& where) {
  check_positive(spec.length, where, "tank.length");
  check_positive(spec.height, where, "tank.height");
  check_positive(spec.coefficient, where, "tank.coefficient");
  const double c = spec.coefficient, half = 0.5 * spec.length;
  const double y_end = c * half * half;  // height of the parabola at x = 0 and x = L
  double x_start = 0.0;
  if (y_end > spec.height) {
    // The parabola reaches the wall top inside the section: its top width must be the
    // given length (tank.length is the width at the top of the walls), within 1%.
    const double top_width = 2.0 * std::sqrt(spec.height / c);
    if (top_width < 0.99 * spec.length)
      throw InputError(where, "tank.length",
                       "the parabola y = " + number(c) + " (x - L/2)^2 reaches the wall top (tank.height = " +
                           number(spec.height) + " m) at a width of " + number(top_width) +
                           " m, narrower than tank.length = " + number(spec.length) +
                           " m: set tank.length to that width, or tank.height to at least " + number(y_end) +
                           " m for vertical walls above the parabola");
    x_start = half - 0.5 * top_width;
  }
  TankGeometry t;
  t.wall.push_back({x_start, spec.height});
  if (x_start == 0.0) append_point(t.wall, {0.0, y_end});  // the vertical wall down to the parabola
  auto curve = [&](double x) { return Vec2{x, c * (x - half) * (x - half)}; };
  append_curve(t.wall, curve, x_start, half, curve_segment(spec));
  t.wall.back() = {half, 0.0};  // exact lowest point
  t.wall = mirrored_walls(t.wall, spec.length);
  return t;
}

// Lower half of a circle of diameter L centred at (L/2, L/2), vertical walls above the centre line.
TankGeometry circular(const TankSpec& spec, const std::string& where) {
  check_positive(spec.length, where, "tank.length");
  check_positive(spec.height, where, "tank.height");
  const double r = 0.5 * spec.length;
  if (spec.height < r * (1.0 - 1e-9))
    throw InputError(where, "tank.height",
                     "a circular section is the lower half of a circle of diameter tank.length = " +
                         number(spec.length) + " m: tank.height must be at least its radius (" + number(r) + " m)");
  constexpr double pi = std::numbers::pi;
  TankGeometry t;
  t.wall.push_back({0.0, spec.height});
  append_point(t.wall, {0.0, r});
  auto curve = [&](double a) { return Vec2{r + r * std::cos(a), r + r * std::sin(a)}; };
  append_curve(t.wall, curve, pi, 1.5 * pi, curve_segment(spec));
  t.wall.back() = {r, 0.0};
  t.wall = mirrored_walls(t.wall, spec.length);
  return t;
}

// V (bottom_width = 0) or trapezoidal bottom, slopes at `angle` from the horizontal,
// vertical walls above the slopes. If the slopes reach the wall top before x = 0 and
// x = L, the section ends there and is narrower than tank.length.
TankGeometry sloped(const TankSpec& spec, const std::string& where) {
  check_positive(spec.length, where, "tank.length");
  check_positive(spec.height, where, "tank.height");
  if (!(spec.angle > 0.0 && spec.angle < 90.0))
    throw InputError(where, "tank.angle", "the bottom slope must be between 0 and 90 degrees (got " +
                                              number(spec.angle) + ")");
  if (!(spec.bottom_width >= 0.0 && spec.bottom_width < spec.length))
    throw InputError(where, "tank.bottom_width", "must be at least 0 and less than tank.length (got " +
                                                     number(spec.bottom_width) + " m)");
  if (spec.shape == "triangle" && spec.bottom_width != 0.0)
    throw InputError(where, "tank.bottom_width", "a triangle bottom has no flat part: bottom_width must be 0");
  if (spec.shape == "trapezoid" && !(spec.bottom_width > 0.0))
    throw InputError(where, "tank.bottom_width", "a trapezoid bottom needs a flat part: bottom_width > 0");
  const double slope = std::tan(spec.angle * std::numbers::pi / 180.0);
  const double toe = 0.5 * (spec.length - spec.bottom_width);  // x of the left end of the flat part
  TankGeometry t;
  if (toe * slope < spec.height * (1.0 - 1e-12)) {  // the slope meets x = 0 below the wall top
    t.wall.push_back({0.0, spec.height});
    t.wall.push_back({0.0, toe * slope});
  } else {
    t.wall.push_back({toe - spec.height / slope, spec.height});
  }
  t.wall.push_back({toe, 0.0});
  if (spec.bottom_width > 0.0) t.wall.push_back({spec.length - toe, 0.0});
  const std::size_t n = t.wall.size() - (spec.bottom_width > 0.0 ? 2 : 1);
  for (std::size_t k = n; k-- > 0;) t.wall.push_back({spec.length - t.wall[k].x, t.wall[k].y});
  return t;
}

bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  auto orient = [](Vec2 p, Vec2 q, Vec2 r) { return cross(q - p, r - p); };
  auto on_segment = [](Vec2 p, Vec2 q, Vec2 r) {  // r collinear with pq: within its box?
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  const double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) || (d3 == 0 && on_segment(a, b, c)) ||
         (d4 == 0 && on_segment(a, b, d));
}

// The wall given point by point, from the top left, down, to the top right.
TankGeometry polyline(const TankSpec& spec, const std::string& where) {
  const std::vector<Vec2>& p = spec.points;
  auto fail = [&](const std::string& why) { throw InputError(where, "tank.points", why); };
  if (p.size() < 3) fail("a polyline wall needs at least 3 points (top left, bottom, top right)");
  for (const Vec2& q : p)
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) fail("every point must be finite");
  const double top = std::min(p.front().y, p.back().y);
  for (std::size_t k = 1; k + 1 < p.size(); ++k)
    if (!(p[k].y < top))
      fail("point " + std::to_string(k + 1) + " is not below both end points: the first and the last point must be "
           "the highest (the tops of the walls)");
  for (std::size_t k = 0; k + 1 < p.size(); ++k)
    if (norm(p[k + 1] - p[k]) <= 0.0) fail("points " + std::to_string(k + 1) + " and " + std::to_string(k + 2) + " coincide");
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    // Adjacent segments share a point: they intersect elsewhere only if they fold back.
    if (i + 2 < p.size() && std::abs(cross(p[i + 1] - p[i], p[i + 2] - p[i + 1])) == 0.0 &&
        dot(p[i + 1] - p[i], p[i + 2] - p[i + 1]) < 0.0)
      fail("the wall folds back on itself at point " + std::to_string(i + 2));
    for (std::size_t j = i + 2; j + 1 < p.size(); ++j)
      if (segments_intersect(p[i], p[i + 1], p[j], p[j + 1]))
        fail("segments " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + " of the wall intersect");
  }
  // The container (the chain, its ends raised, closed far above) must wind
  // counter-clockwise: the fluid on the left of the travel, i.e. going down the left wall
  // the interior is at +x.
  const double y_far = std::max(p.front().y, p.back().y) + 1.0;
  double area2 = 0.0;
  std::vector<Vec2> ring = p;
  ring.push_back({p.back().x, y_far});
  ring.push_back({p.front().x, y_far});
  for (std::size_t k = 0; k < ring.size(); ++k) area2 += cross(ring[k], ring[(k + 1) % ring.size()]);
  if (!(area2 > 0.0))
    fail("the points must run from the top of the LEFT wall, down through the bottom, to the top of the RIGHT "
         "wall (the fluid on the left-hand side of the travel)");
  TankGeometry t;
  t.wall = p;
  return t;
}

void finish(TankGeometry& t) {
  t.x_min = t.x_max = t.wall.front().x;
  t.y_bottom = t.y_top = t.wall.front().y;
  for (const Vec2& p : t.wall) {
    t.x_min = std::min(t.x_min, p.x);
    t.x_max = std::max(t.x_max, p.x);
    t.y_bottom = std::min(t.y_bottom, p.y);
    t.y_top = std::max(t.y_top, p.y);
  }
}

// Offset of the wall chain by distance d outward, with mitred joins.
std::vector<Vec2> offset_chain(const TankGeometry& tank, double d) {
  const std::size_t n = tank.wall.size();
  std::vector<Vec2> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k == 0) {
      out[k] = tank.wall[k] - d * tank.inward_normal(0);
    } else if (k == n - 1) {
      out[k] = tank.wall[k] - d * tank.inward_normal(n - 2);
    } else {
      const Vec2 na = tank.inward_normal(k - 1), nb = tank.inward_normal(k);
      const double c = 1.0 + dot(na, nb);
      // Mitre point; for very sharp turns fall back to the bisector (bounded length).
      const Vec2 shift = c > 0.25 ? (na + nb) / c : normalized(na + nb) * std::sqrt(2.0 / 0.25);
      out[k] = tank.wall[k] - d * shift;
    }
  }
  return out;
}

double turn_angle(const std::vector<Vec2>& chain, std::size_t k) {
  const Vec2 a = normalized(chain[k] - chain[k - 1]);
  const Vec2 b = normalized(chain[k + 1] - chain[k]);
  return std::acos(std::clamp(dot(a, b), -1.0, 1.0));
}

struct Piece {
  std::size_t first, last;  // vertex range in the chain
};

// Pieces between sharp vertices (turn > 15 degrees): sampled independently so corners get a particle.
std::vector<Piece> split_at_corners(const std::vector<Vec2>& chain) {
  constexpr double kSharp = 15.0 * 3.14159265358979323846 / 180.0;
  std::vector<Piece> pieces;
  std::size_t start = 0;
  for (std::size_t k = 1; k + 1 < chain.size(); ++k) {
    if (turn_angle(chain, k) > kSharp) {
      pieces.push_back({start, k});
      start = k;
    }
  }
  pieces.push_back({start, chain.size() - 1});
  return pieces;
}

// Point at arc length s along chain[first..last], and the segment index it lies on.
std::pair<Vec2, std::size_t> point_at(const std::vector<Vec2>& chain, const Piece& piece, double s) {
  for (std::size_t k = piece.first; k < piece.last; ++k) {
    const double len = norm(chain[k + 1] - chain[k]);
    if (s <= len || k + 1 == piece.last) {
      const double t = len > 0.0 ? std::clamp(s / len, 0.0, 1.0) : 0.0;
      return {chain[k] + t * (chain[k + 1] - chain[k]), k};
    }
    s -= len;
  }
  return {chain[piece.last], piece.last - 1};
}

double piece_length(const std::vector<Vec2>& chain, const Piece& piece) {
  double len = 0.0;
  for (std::size_t k = piece.first; k < piece.last; ++k) len += norm(chain[k + 1] - chain[k]);
  return len;
}

}  // namespace

Vec2 TankGeometry::inward_normal(std::size_t segment) const {
  return perp(normalized(wall[segment + 1] - wall[segment]));
}

double TankGeometry::signed_distance(Vec2 p) const {
  double d = std::numeric_limits<double>::max();
  bool inside = false;
  for_each_container_edge(wall, [&](Vec2 a, Vec2 b) {
    if (a.y < kFar || b.y < kFar) d = std::min(d, distance_to_segment(p, a, b));
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  });
  return inside ? d : -d;
}

std::size_t TankGeometry::nearest_segment(Vec2 p) const {
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k + 1 < wall.size(); ++k) {
    const double d = distance_to_segment(p, wall[k], wall[k + 1]);
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  return best;
}

double TankGeometry::bottom_at(double x) const {
  double y = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k + 1 < wall.size(); ++k) {
    const Vec2 a = wall[k], b = wall[k + 1];
    const double lo = std::min(a.x, b.x), hi = std::max(a.x, b.x);
    if (x < lo || x > hi) continue;
    const double yk = hi > lo ? a.y + (x - a.x) * (b.y - a.y) / (b.x - a.x) : std::min(a.y, b.y);
    y = std::min(y, yk);
  }
  return y == std::numeric_limits<double>::max() ? y_bottom : y;
}

TankGeometry make_tank(const TankSpec& spec, const std::string& where) {
  TankGeometry t;
  if (spec.shape == "rectangle") {
    t = rectangle(spec, where);
  } else if (spec.shape == "parabolic") {
    t = parabolic(spec, where);
  } else if (spec.shape == "circular") {
    t = circular(spec, where);
  } else if (spec.shape == "sloped" || spec.shape == "triangle" || spec.shape == "trapezoid") {
    t = sloped(spec, where);
  } else if (spec.shape == "polyline") {
    t = polyline(spec, where);
  } else if (spec.shape == "cylinder") {
    throw InputError(where, "tank.shape",
                     "an upright cylinder (3D) has no tank section: the 2D tools (modes, tuning, the linear model) "
                     "do not take it");
  } else {
    throw InputError(where, "tank.shape",
                     "unknown shape '" + spec.shape +
                         "' (expected: rectangle, sloped, triangle, trapezoid, parabolic, circular, polyline)");
  }
  finish(t);
  return t;
}

std::vector<Vec2> still_water_polygon(const TankGeometry& tank, double depth) {
  const std::vector<Vec2>& w = tank.wall;
  const double level = tank.y_bottom + depth;
  if (!(depth > 0.0) || !std::isfinite(depth)) throw InputError("", "fill.depth", "the depth must be a positive number");
  if (level > std::min(w.front().y, w.back().y))
    throw InputError("", "fill.depth", "the still level (depth " + number(depth) + " m) is above the top of the walls");
  // Crossings of the level by the chain: a vertex exactly at the level counts as above.
  std::vector<std::pair<std::size_t, Vec2>> crossings;
  for (std::size_t k = 0; k + 1 < w.size(); ++k) {
    const bool a_below = w[k].y < level, b_below = w[k + 1].y < level;
    if (a_below == b_below) continue;
    const double t = (level - w[k].y) / (w[k + 1].y - w[k].y);
    crossings.push_back({k, {w[k].x + t * (w[k + 1].x - w[k].x), level}});
  }
  if (crossings.size() != 2)
    throw InputError("", "fill.depth",
                     "the still level (depth " + number(depth) + " m) meets the wall " +
                         std::to_string(crossings.size()) +
                         " times: only a single pool with one free surface is supported");
  std::vector<Vec2> poly{crossings[0].second};
  for (std::size_t k = crossings[0].first + 1; k <= crossings[1].first; ++k) poly.push_back(w[k]);
  poly.push_back(crossings[1].second);
  // Drop repeated points (a crossing on a vertex).
  std::vector<Vec2> out;
  for (const Vec2& q : poly)
    if (out.empty() || norm(q - out.back()) > 1e-14 * (1.0 + norm(q))) out.push_back(q);
  return out;
}

double section_area(const TankGeometry& tank, double depth) {
  const std::vector<Vec2> poly = still_water_polygon(tank, depth);
  double area2 = 0.0;
  for (std::size_t k = 0; k < poly.size(); ++k) area2 += cross(poly[k], poly[(k + 1) % poly.size()]);
  return 0.5 * area2;
}

ContainerDistance::ContainerDistance(const TankGeometry& tank, double spacing, double margin)
    : tank_(&tank), spacing_(spacing) {
  origin_ = {tank.x_min - margin, tank.y_bottom - margin};
  nx_ = static_cast<int>((tank.x_max - tank.x_min + 2.0 * margin) / spacing) + 2;
  ny_ = static_cast<int>((tank.y_top - tank.y_bottom + 2.0 * margin) / spacing) + 2;
  value_.resize(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
#pragma omp parallel for schedule(static)
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i)
      value_[static_cast<std::size_t>(j) * nx_ + i] = tank.signed_distance(origin_ + Vec2{i * spacing, j * spacing});
}

double ContainerDistance::operator()(Vec2 p) const {
  const double fx = (p.x - origin_.x) / spacing_, fy = (p.y - origin_.y) / spacing_;
  const int i = static_cast<int>(std::floor(fx)), j = static_cast<int>(std::floor(fy));
  if (i < 0 || j < 0 || i + 1 >= nx_ || j + 1 >= ny_) return tank_->signed_distance(p);
  const double tx = fx - i, ty = fy - j;
  auto v = [&](int a, int b) { return value_[static_cast<std::size_t>(b) * nx_ + a]; };
  return (1 - ty) * ((1 - tx) * v(i, j) + tx * v(i + 1, j)) + ty * ((1 - tx) * v(i, j + 1) + tx * v(i + 1, j + 1));
}

std::vector<WallSample> sample_walls(const TankGeometry& tank, double dp, int layers) {
  std::vector<WallSample> out;
  for (int layer = 0; layer < layers; ++layer) {
    const double d = (layer + 0.5) * dp;
    const std::vector<Vec2> chain = offset_chain(tank, d);
    const std::vector<Piece> pieces = split_at_corners(chain);
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      const Piece& piece = pieces[p];
      const double len = piece_length(chain, piece);
      const bool is_first = p == 0, is_last = p + 1 == pieces.size();
      std::vector<double> arc;  // arc-length positions along this piece
      if (pieces.size() > 1 && (is_first || is_last)) {
        // End wall: exact dp steps from the inner corner up to the free end.
        const int n = static_cast<int>(std::floor(len / dp + 1e-9));
        for (int k = 0; k <= n; ++k) arc.push_back(is_first ? len - k * dp : k * dp);
        if (is_first) std::reverse(arc.begin(), arc.end());
      } else {
        const int n = std::max(1, static_cast<int>(std::ceil(len / dp - 1e-9)));
        for (int k = 0; k <= n; ++k) arc.push_back(len * k / n);
      }
      for (std::size_t k = 0; k < arc.size(); ++k) {
        // Corner points belong to the piece that ends there; skip them at the next start.
        if (p > 0 && k == 0 && arc[k] < 1e-12) continue;
        auto [pos, seg] = point_at(chain, piece, arc[k]);
        Vec2 normal = tank.inward_normal(seg);
        const bool at_vertex_end = std::abs(arc[k] - len) < 1e-12 && !is_last;
        if (at_vertex_end) normal = normalized(tank.inward_normal(piece.last - 1) + tank.inward_normal(piece.last));
        out.push_back({pos, normal});
      }
    }
  }
  return out;
}

std::vector<Vec2> fill_fluid(const TankGeometry& tank, double dp, double depth) {
  std::vector<Vec2> out;
  const double y_level = tank.y_bottom + depth;
  const int ni = static_cast<int>(std::ceil((tank.x_max - tank.x_min) / dp));
  const int nj = static_cast<int>(std::ceil(depth / dp));
  for (int j = 0; j < nj; ++j) {
    const double y = tank.y_bottom + (j + 0.5) * dp;
    if (y >= y_level) break;
    for (int i = 0; i < ni; ++i) {
      const Vec2 p{tank.x_min + (i + 0.5) * dp, y};
      if (tank.signed_distance(p) >= 0.5 * dp * (1.0 - 1e-9)) out.push_back(p);
    }
  }
  return out;
}

namespace {

bool in_block(const FluidBlock& b, Vec2 p) { return p.x >= b.from.x && p.x < b.to.x && p.y >= b.from.y && p.y < b.to.y; }

}  // namespace

std::vector<Vec2> fill_blocks(const TankGeometry& tank, double dp, const std::vector<FluidBlock>& blocks) {
  std::vector<Vec2> out;
  const int ni = static_cast<int>(std::ceil((tank.x_max - tank.x_min) / dp));
  const int nj = static_cast<int>(std::ceil((tank.y_top - tank.y_bottom) / dp));
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i) {
      const Vec2 p{tank.x_min + (i + 0.5) * dp, tank.y_bottom + (j + 0.5) * dp};
      if (in_blocks(blocks, p) && tank.signed_distance(p) >= 0.5 * dp * (1.0 - 1e-9)) out.push_back(p);
    }
  return out;
}

bool in_blocks(const std::vector<FluidBlock>& blocks, Vec2 p) {
  return std::any_of(blocks.begin(), blocks.end(), [&](const FluidBlock& b) { return in_block(b, p); });
}

double block_surface(const std::vector<FluidBlock>& blocks, Vec2 p) {
  double top = p.y;
  for (const FluidBlock& b : blocks)
    if (in_block(b, p)) top = std::max(top, b.to.y);
  return top;
}

double surface_width(const TankGeometry& tank, double depth) {
  const double y = tank.y_bottom + depth;
  double left = std::numeric_limits<double>::max(), right = std::numeric_limits<double>::lowest();
  for (std::size_t k = 0; k + 1 < tank.wall.size(); ++k) {
    const Vec2 a = tank.wall[k], b = tank.wall[k + 1];
    if ((a.y - y) * (b.y - y) > 0.0 || a.y == b.y) continue;
    const double x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
    left = std::min(left, x);
    right = std::max(right, x);
  }
  return right > left ? right - left : 0.0;
}

}  // namespace sloshsph
