#include "sloshsph/linear/fluid_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace sloshsph {
namespace {

// The closed polygon parametrised by arc length s in [0, perimeter).
class Ring {
 public:
  explicit Ring(const std::vector<Vec2>& points) : p_(points), s_(points.size() + 1, 0.0) {
    for (std::size_t k = 0; k < p_.size(); ++k) s_[k + 1] = s_[k] + norm(p_[(k + 1) % p_.size()] - p_[k]);
  }
  std::size_t size() const { return p_.size(); }
  double perimeter() const { return s_.back(); }
  double s_at(std::size_t vertex) const { return s_[vertex]; }
  Vec2 point(double s) const {
    s = std::clamp(s, 0.0, perimeter());
    const std::size_t k =
        std::min<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin() - 1, p_.size() - 1);
    const double len = s_[k + 1] - s_[k];
    const double t = len > 0.0 ? (s - s_[k]) / len : 0.0;
    return p_[k] + t * (p_[(k + 1) % p_.size()] - p_[k]);
  }
  // Signed turn at a vertex (positive: left turn, a convex vertex of a counter-clockwise ring).
  double turn(std::size_t k) const {
    const std::size_t n = p_.size();
    const Vec2 in = p_[k] - p_[(k + n - 1) % n], out = p_[(k + 1) % n] - p_[k];
    return std::atan2(cross(in, out), dot(in, out));
  }

 private:
  std::vector<Vec2> p_;
  std::vector<double> s_;
};

// Arc-length positions of the boundary nodes: equal spacing (<= size) between corners,
// except that at an acute corner the two edges touching it get the same length, so
// neither end node lies inside the other edge's diametral circle (the triangulation
// then contains both edges; without this, splitting can cycle at a sharp corner).
std::vector<double> boundary_positions(const Ring& ring, double size) {
  std::uint32_t seed = 2024u;
  auto jitter = [&seed] {  // deterministic, in [-0.05, 0.05)
    seed = seed * 1664525u + 1013904223u;
    return 0.1 * (static_cast<double>(seed >> 8) / 16777216.0 - 0.5);
  };
  constexpr double kCornerTurn = 20.0 * std::numbers::pi / 180.0;
  const std::size_t n = ring.size();
  std::vector<std::size_t> corners;
  // Corners: the ends of the free surface, sharp turns, and any turn next to a segment
  // longer than half an element (a real polygon vertex, not a point of a finely
  // discretised curve): a node there keeps the polygon exact.
  for (std::size_t k = 0; k < n; ++k) {
    const double longer = std::max(ring.s_at(k + 1) - ring.s_at(k), k > 0 ? ring.s_at(k) - ring.s_at(k - 1)
                                                                           : ring.perimeter() - ring.s_at(n - 1));
    const double turn = std::abs(ring.turn(k));
    if (k == 0 || k == n - 1 || turn > kCornerTurn || (turn > 1e-6 && longer > 0.5 * size)) corners.push_back(k);
  }
  const std::size_t m = corners.size();
  auto start = [&](std::size_t j) { return ring.s_at(corners[j]); };
  auto end = [&](std::size_t j) { return j + 1 < m ? ring.s_at(corners[j + 1]) : ring.perimeter(); };
  std::vector<double> spacing(m), corner_edge(m, 0.0);
  for (std::size_t j = 0; j < m; ++j) {
    const double len = end(j) - start(j);
    spacing[j] = len / std::max(1.0, std::ceil(len / size - 1e-9));
  }
  for (std::size_t j = 0; j < m; ++j) {
    const double interior_angle = std::numbers::pi - ring.turn(corners[j]);
    if (interior_angle < 0.5 * std::numbers::pi) corner_edge[j] = std::min(spacing[j], spacing[(j + m - 1) % m]);
  }
  std::vector<double> out;
  for (std::size_t j = 0; j < m; ++j) {
    const double s0 = start(j), s1 = end(j);
    const double e0 = corner_edge[j], e1 = corner_edge[(j + 1) % m];
    out.push_back(s0);
    const double a = s0 + e0, b = s1 - e1;
    if (b - a <= 1e-9 * (s1 - s0)) {  // the fixed corner edges fill the piece
      if (e0 > 0.0 && a < s1 - 1e-9 * (s1 - s0)) out.push_back(a);
      continue;
    }
    if (e0 > 0.0) out.push_back(a);
    const int intervals = std::max(1, static_cast<int>(std::ceil((b - a) / size - 1e-9)));
    // Nodes moved along the boundary by up to 5% of the spacing, so that nodes on two
    // parallel walls (a shallow rectangle) are never co-circular.
    for (int k = 1; k < intervals; ++k) out.push_back(a + (b - a) * (k + jitter()) / intervals);
    if (e1 > 0.0) out.push_back(b);
  }
  return out;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = norm2(ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * ab));
}

bool inside_polygon(Vec2 p, const std::vector<Vec2>& poly) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}

// Incremental Delaunay triangulation (Bowyer-Watson). The cavity of a new point is found
// by a scan of all triangles: O(n^2), fine for the few thousand nodes used here.
class Delaunay {
 public:
  explicit Delaunay(Vec2 lo, Vec2 hi) {
    const Vec2 c = 0.5 * (lo + hi);
    const double r = 100.0 * std::max(hi.x - lo.x, hi.y - lo.y) + 1.0;
    points_ = {c + Vec2{-2.0 * r, -r}, c + Vec2{2.0 * r, -r}, c + Vec2{0.0, 2.0 * r}};
    add_triangle(0, 1, 2);
  }
  static constexpr int kSuper = 3;  // the first three points are the super triangle

  int insert(Vec2 p) {
    const int id = static_cast<int>(points_.size());
    points_.push_back(p);
    std::vector<std::array<int, 2>> edges;
    for (std::size_t t = 0; t < tris_.size();) {
      if (norm2(p - tris_[t].centre) < tris_[t].radius2) {
        const auto& v = tris_[t].v;
        edges.push_back({v[0], v[1]});
        edges.push_back({v[1], v[2]});
        edges.push_back({v[2], v[0]});
        tris_[t] = tris_.back();
        tris_.pop_back();
      } else {
        ++t;
      }
    }
    for (std::size_t i = 0; i < edges.size(); ++i) {
      bool shared = false;
      for (std::size_t j = 0; j < edges.size() && !shared; ++j)
        shared = j != i && edges[j][0] == edges[i][1] && edges[j][1] == edges[i][0];
      if (shared) continue;
      const Vec2 a = points_[edges[i][0]], b = points_[edges[i][1]];
      if (!(cross(b - a, p - a) > 0.0)) throw std::runtime_error("mesh_section: degenerate Delaunay cavity");
      add_triangle(edges[i][0], edges[i][1], id);
    }
    return id;
  }

  const std::vector<Vec2>& points() const { return points_; }
  template <class F>
  void for_each_triangle(F&& f) const {
    for (const Tri& t : tris_) f(t.v);
  }

 private:
  struct Tri {
    std::array<int, 3> v;
    Vec2 centre;
    double radius2;
  };
  void add_triangle(int a, int b, int c) {
    const Vec2 pa = points_[a], ab = points_[b] - pa, ac = points_[c] - pa;
    const double d = 2.0 * cross(ab, ac);
    const Vec2 u{(ac.y * norm2(ab) - ab.y * norm2(ac)) / d, (ab.x * norm2(ac) - ac.x * norm2(ab)) / d};
    tris_.push_back({{a, b, c}, pa + u, norm2(u)});
  }
  std::vector<Vec2> points_;
  std::vector<Tri> tris_;
};

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

FluidMesh mesh_section(const std::vector<Vec2>& section, double size) {
  if (section.size() < 3 || !(size > 0.0)) throw std::runtime_error("mesh_section: bad section or size");
  const Ring ring(section);
  std::vector<double> boundary_s = boundary_positions(ring, size);
  const double surface_start = ring.s_at(section.size() - 1);

  Vec2 lo = section[0], hi = section[0];
  for (const Vec2& p : section) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  std::vector<Vec2> boundary;
  for (double s : boundary_s) boundary.push_back(ring.point(s));

  // Interior nodes: a triangular lattice, jittered by up to 5% of the size so that no four
  // nodes are co-circular, kept at >= 0.6 size from the boundary (then no interior node
  // lies in the diametral circle of a boundary edge, which is at most `size` long).
  std::vector<Vec2> interior;
  const double row = size * std::sqrt(3.0) / 2.0;
  std::uint32_t seed = 12345u;
  auto jitter = [&seed, size] {
    seed = seed * 1664525u + 1013904223u;
    return 0.1 * size * (static_cast<double>(seed >> 8) / 16777216.0 - 0.5);
  };
  for (int j = 0; lo.y + (j + 0.5) * row < hi.y; ++j) {
    for (int i = 0; lo.x + (i + 0.5 * (j % 2)) * size < hi.x; ++i) {
      Vec2 p{lo.x + (i + 0.5 * (j % 2)) * size, lo.y + (j + 0.5) * row};
      p += Vec2{jitter(), jitter()};
      if (!inside_polygon(p, boundary)) continue;
      double d = std::numeric_limits<double>::max();
      for (std::size_t k = 0; k < boundary.size() && d >= 0.6 * size; ++k)
        d = std::min(d, distance_to_segment(p, boundary[k], boundary[(k + 1) % boundary.size()]));
      if (d >= 0.6 * size) interior.push_back(p);
    }
  }

  // Interior nodes first, then the free surface, then the walls: the nodes of a circular
  // wall are co-circular, and inserted last they never meet a triangle whose circumcircle
  // is that circle (the interior and surface nodes inside it prevent such triangles).
  Delaunay dt(lo, hi);
  for (const Vec2& p : interior) dt.insert(p);
  std::vector<int> boundary_id(boundary.size(), -1);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t k = 0; k < boundary.size(); ++k)
      if ((boundary_s[k] >= surface_start - 1e-12 * ring.perimeter() || k == 0) == (pass == 0))
        boundary_id[k] = dt.insert(boundary[k]);

  // Recover missing boundary edges by inserting the arc-length midpoint.
  for (int pass = 0;; ++pass) {
    std::unordered_set<std::uint64_t> edges;
    dt.for_each_triangle([&](const std::array<int, 3>& v) {
      for (int e = 0; e < 3; ++e) edges.insert(edge_key(v[e], v[(e + 1) % 3]));
    });
    std::vector<std::size_t> missing;
    for (std::size_t k = 0; k < boundary_id.size(); ++k)
      if (!edges.count(edge_key(boundary_id[k], boundary_id[(k + 1) % boundary_id.size()]))) missing.push_back(k);
    if (missing.empty()) break;
    if (pass > 50) throw std::runtime_error("mesh_section: could not recover the boundary edges");
    for (std::size_t m = missing.size(); m-- > 0;) {
      const std::size_t k = missing[m];
      const double s1 = k + 1 < boundary_s.size() ? boundary_s[k + 1] : ring.perimeter();
      const double s = 0.5 * (boundary_s[k] + s1);
      const Vec2 p = ring.point(s);
      boundary_s.insert(boundary_s.begin() + static_cast<std::ptrdiff_t>(k + 1), s);
      boundary.insert(boundary.begin() + static_cast<std::ptrdiff_t>(k + 1), p);
      boundary_id.insert(boundary_id.begin() + static_cast<std::ptrdiff_t>(k + 1), dt.insert(p));
    }
  }

  // Keep the triangles inside the section; renumber their vertices.
  FluidMesh mesh;
  std::vector<int> new_id(dt.points().size(), -1);
  std::vector<std::array<int, 3>> kept;
  dt.for_each_triangle([&](const std::array<int, 3>& v) {
    if (v[0] < Delaunay::kSuper || v[1] < Delaunay::kSuper || v[2] < Delaunay::kSuper) return;
    const Vec2 c = (dt.points()[v[0]] + dt.points()[v[1]] + dt.points()[v[2]]) / 3.0;
    if (inside_polygon(c, boundary)) kept.push_back(v);
  });
  for (auto& v : kept)
    for (int& i : v) {
      if (new_id[i] < 0) {
        new_id[i] = static_cast<int>(mesh.nodes.size());
        mesh.nodes.push_back(dt.points()[i]);
      }
      i = new_id[i];
    }
  mesh.vertex_count = mesh.nodes.size();

  // Boundary edges (consecutive boundary nodes): their mid-node goes on the boundary curve.
  std::unordered_map<std::uint64_t, double> boundary_mid_s;
  std::unordered_set<std::uint64_t> surface;
  for (std::size_t k = 0; k < boundary_id.size(); ++k) {
    const int a = new_id[boundary_id[k]], b = new_id[boundary_id[(k + 1) % boundary_id.size()]];
    if (a < 0 || b < 0) throw std::runtime_error("mesh_section: a boundary node has no triangle");
    const double s1 = k + 1 < boundary_s.size() ? boundary_s[k + 1] : ring.perimeter();
    boundary_mid_s[edge_key(a, b)] = 0.5 * (boundary_s[k] + s1);
    if (boundary_s[k] >= surface_start - 1e-12 * ring.perimeter()) surface.insert(edge_key(a, b));
  }
  std::unordered_map<std::uint64_t, int> mid_of;
  for (const auto& v : kept) {
    std::array<int, 6> e{v[0], v[1], v[2], 0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      const int a = v[k], b = v[(k + 1) % 3];
      const std::uint64_t key = edge_key(a, b);
      auto it = mid_of.find(key);
      if (it == mid_of.end()) {
        auto on_boundary = boundary_mid_s.find(key);
        const Vec2 p = on_boundary != boundary_mid_s.end() ? ring.point(on_boundary->second)
                                                           : 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
        it = mid_of.emplace(key, static_cast<int>(mesh.nodes.size())).first;
        mesh.nodes.push_back(p);
        if (surface.count(key)) {
          const bool a_left = mesh.nodes[a].x < mesh.nodes[b].x;
          mesh.surface_edges.push_back({a_left ? a : b, it->second, a_left ? b : a});
        }
      }
      e[3 + k] = it->second;
    }
    mesh.elements.push_back(e);
  }
  std::sort(mesh.surface_edges.begin(), mesh.surface_edges.end(),
            [&](const auto& l, const auto& r) { return mesh.nodes[l[0]].x < mesh.nodes[r[0]].x; });
  return mesh;
}

}  // namespace sloshsph
