#pragma once
// Wave gauges and pressure probes: kernel interpolation of the particle state at fixed
// points of the tank frame. Methods and their limits are in docs/physics.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {

// Height of the free surface on the vertical line through `column` (its height component is
// ignored; in 2D the line x = column.x, in 3D x = column.x, y = column.y): the highest height at
// which the kernel-interpolated fluid fraction phi = c_f / (c_full - c_w) reaches 1/2, where c_f
// and c_w are the kernel sums sum_j V W over fluid and wall particles and c_full is that sum in
// undisturbed fluid. The wall term keeps the fraction right within 2h of a wall. Returns
// `floor` if the line is dry. Heights are y in 2D, z in 3D.
template <class K, int D>
double free_surface_height(const K& k, const BasicParticles<D>& p, Vec<D> column, double floor, double c_full) {
  const double reach = k.support();
  auto near_line = [&](Vec<D> r) {
    if constexpr (D == 2) {
      return std::abs(r.x - column.x) < reach;
    } else {
      const double dx = r.x - column.x, dy = r.y - column.y;
      return dx * dx + dy * dy < reach * reach;
    }
  };
  std::vector<Vec<D>> fluid, wall;
  double top = floor;
  for (std::size_t j = 0; j < p.n_fluid; ++j)
    if (near_line(p.position[j])) {
      fluid.push_back(p.position[j]);
      top = std::max(top, component(p.position[j], D - 1));
    }
  if (fluid.empty()) return floor;
  for (std::size_t j = p.n_fluid; j < p.size(); ++j)
    if (near_line(p.position[j])) wall.push_back(p.position[j]);

  auto fraction = [&](double height) {
    Vec<D> q = column;
    component_ref(q, D - 1) = height;
    double cf = 0.0, cw = 0.0;
    for (const Vec<D>& r : fluid) cf += k.w(norm(q - r));
    for (const Vec<D>& r : wall) cw += k.w(norm(q - r));
    cf *= p.volume;
    cw *= p.volume;
    return cf / std::max(c_full - cw, 0.5 * c_full);
  };
  const double step = 0.05 * k.h;
  double y_prev = top + reach, f_prev = fraction(y_prev);
  for (double y = y_prev - step; y > floor - step; y -= step) {
    const double f = fraction(y);
    if (f >= 0.5) {
      const double t = (0.5 - f_prev) / (f - f_prev);  // linear between the bracketing samples
      return y_prev + t * (y - y_prev);
    }
    y_prev = y;
    f_prev = f;
  }
  return floor;
}

// The 2D gauge at x.
template <class K>
double free_surface_height(const K& k, const Particles& p, double x, double y_floor, double c_full) {
  return free_surface_height<K, 2>(k, p, Vec2{x, 0.0}, y_floor, c_full);
}

// Shepard interpolation of pressure at a point over fluid and wall particles (wall
// particles carry the Adami pressure, the fluid pressure continued through the wall).
// A probe with almost no fluid in its kernel (fluid kernel sum below 0.1) reads 0.
template <class K, int D>
double pressure_at(const K& k, const BasicParticles<D>& p, const BasicCellGrid<D>& grid, Vec<D> point) {
  double num = 0.0, den = 0.0, fluid = 0.0;
  grid.for_each_candidate(point, k.support(), [&](std::uint32_t j) {
    const double W = k.w(norm(point - p.position[j]));
    num += W * p.pressure[j];
    den += W;
    if (p.is_fluid(j)) fluid += W;
  });
  if (fluid * p.volume < 0.1 || den <= 0.0) return 0.0;
  return num / den;
}

// A pressure sensor with a face (a transducer or force panel): the mean of pressure_at over the
// segment from `a` to `b`, sampled at evenly spaced points no more than `spacing` apart, ends
// included. A dry part of the face reads 0 (atmospheric), as it would on the real sensor.
template <class K>
double pressure_on_face(const K& k, const Particles& p, const CellGrid& grid, Vec2 a, Vec2 b, double spacing) {
  const double length = norm(b - a);
  const int intervals = std::max(1, static_cast<int>(std::ceil(length / spacing)));
  double sum = 0.0;
  for (int i = 0; i <= intervals; ++i)
    sum += pressure_at(k, p, grid, a + (b - a) * (static_cast<double>(i) / intervals));
  return sum / (intervals + 1);
}

// Surge front (dam-break tip): the largest (rightward) or smallest x of the fluid particles at
// most `band` above y_floor, moved dp/2 outward (the edge of that particle's own volume). The
// height is y in 2D and z in 3D (where the front is the furthest particle across the breadth).
// Returns NaN when no fluid particle lies in the band.
template <int D>
double front_position(const BasicParticles<D>& p, double y_floor, double band, bool rightward, double dp) {
  double edge = rightward ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < p.n_fluid; ++j) {
    if (component(p.position[j], D - 1) - y_floor > band) continue;
    edge = rightward ? std::max(edge, p.position[j].x) : std::min(edge, p.position[j].x);
  }
  if (!std::isfinite(edge)) return std::numeric_limits<double>::quiet_NaN();
  return edge + (rightward ? 0.5 * dp : -0.5 * dp);
}

}  // namespace sloshsph
