#include "sloshsph/geometry/tank.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
  } else {
    throw InputError(where, "tank.shape", "unknown shape '" + spec.shape + "' (expected: rectangle)");
  }
  finish(t);
  return t;
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
