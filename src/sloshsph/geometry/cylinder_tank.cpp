#include "sloshsph/geometry/cylinder_tank.hpp"

#include <algorithm>
#include <numbers>

namespace sloshsph {
namespace {

// Lattice lines (i + 1/2) dp across the tank's plan, 0 to 2R.
int lattice_lines(const CylinderTank& tank, double dp) { return static_cast<int>(std::ceil(2.0 * tank.radius / dp - 1e-9)); }

// A lattice node of the plan at least dp/2 inside the side wall (r <= R - dp/2).
bool inside_fill(const CylinderTank& tank, Vec2 q, double dp) {
  return norm(q - tank.axis()) <= tank.radius - 0.5 * dp * (1.0 - 1e-9);
}

}  // namespace

std::vector<WallSample3> sample_walls(const CylinderTank& tank, double dp, int layers) {
  std::vector<WallSample3> out;
  const Vec2 c = tank.axis();
  const int levels = static_cast<int>(std::ceil(tank.height / dp - 1e-9));
  for (int k = 0; k < layers; ++k) {
    const double rho = tank.radius + (k + 0.5) * dp;
    const int around = std::max(3, static_cast<int>(std::lround(2.0 * std::numbers::pi * rho / dp)));
    const double shift = (k % 2 == 0) ? 0.0 : 0.5;
    for (int m = -layers; m < levels; ++m)
      for (int j = 0; j < around; ++j) {
        const double theta = 2.0 * std::numbers::pi * (j + shift) / around;
        const double cs = std::cos(theta), sn = std::sin(theta);
        out.push_back({{c.x + rho * cs, c.y + rho * sn, (m + 0.5) * dp}, {-cs, -sn, 0.0}});
      }
  }
  const int n = lattice_lines(tank, dp);
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 q{(i + 0.5) * dp, (j + 0.5) * dp, -(k + 0.5) * dp};
        if (tank.from_axis(q) < tank.radius) out.push_back({q, {0.0, 0.0, 1.0}});
      }
  return out;
}

std::vector<Vec3> fill_fluid(const CylinderTank& tank, double dp, double depth) {
  // One layer of the lattice inside r <= R - dp/2, nearest the axis first (ties in lattice order).
  const int n = lattice_lines(tank, dp);
  std::vector<Vec2> layer;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2 q{(i + 0.5) * dp, (j + 0.5) * dp};
      if (inside_fill(tank, q, dp)) layer.push_back(q);
    }
  std::stable_sort(layer.begin(), layer.end(),
                   [&tank](Vec2 a, Vec2 b) { return norm2(a - tank.axis()) < norm2(b - tank.axis()); });
  const std::size_t wanted = cylinder_fill_count(tank, dp, depth);
  std::vector<Vec3> out;
  out.reserve(wanted);
  for (int k = 0; out.size() < wanted && !layer.empty(); ++k)
    for (std::size_t m = 0; m < layer.size() && out.size() < wanted; ++m)
      out.push_back({layer[m].x, layer[m].y, (k + 0.5) * dp});
  // Back in lattice order within each layer (the order the schemes' first cell sort starts from).
  std::stable_sort(out.begin(), out.end(), [](const Vec3& a, const Vec3& b) {
    if (a.z != b.z) return a.z < b.z;
    if (a.y != b.y) return a.y < b.y;
    return a.x < b.x;
  });
  return out;
}

std::vector<Vec3> fill_blocks(const CylinderTank& tank, double dp, const std::vector<FluidBlock>& blocks) {
  const int n = lattice_lines(tank, dp);
  const int levels = static_cast<int>(std::ceil(tank.height / dp - 1e-9));
  std::vector<Vec3> out;
  for (int k = 0; k < levels; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 q{(i + 0.5) * dp, (j + 0.5) * dp, (k + 0.5) * dp};
        if (in_blocks(blocks, {q.x, q.z}) && inside_fill(tank, {q.x, q.y}, dp)) out.push_back(q);
      }
  return out;
}

std::size_t cylinder_fill_count(const CylinderTank& tank, double dp, double depth) {
  return static_cast<std::size_t>(std::llround(std::numbers::pi * tank.radius * tank.radius * depth / (dp * dp * dp)));
}

double cylinder_convective_mass_fraction(double radius, double depth) {
  const double xi = kCylinderFirstRoot, ratio = depth / radius;
  return 2.0 * std::tanh(xi * ratio) / (xi * (xi * xi - 1.0) * ratio);
}

double cylinder_first_sloshing_omega(double radius, double depth, double gravity) {
  const double k = kCylinderFirstRoot / radius;
  return std::sqrt(gravity * k * std::tanh(k * depth));
}

}  // namespace sloshsph
