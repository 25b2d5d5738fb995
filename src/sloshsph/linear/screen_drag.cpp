#include "sloshsph/linear/screen_drag.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sloshsph {

void gauss_legendre(int points, double a, double b, std::vector<double>& nodes, std::vector<double>& weights) {
  if (points < 1) throw std::invalid_argument("gauss_legendre: points < 1");
  nodes.assign(static_cast<std::size_t>(points), 0.0);
  weights.assign(static_cast<std::size_t>(points), 0.0);
  for (int i = 0; i < points; ++i) {
    // Newton's method on P_points from the Chebyshev-like first guess of root i.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (points + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; the recurrence up to P_points
      for (int k = 2; k <= points; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = points * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    nodes[static_cast<std::size_t>(i)] = 0.5 * (a + b) - 0.5 * (b - a) * x;
    weights[static_cast<std::size_t>(i)] = (b - a) / ((1.0 - x * x) * derivative * derivative);
  }
}

RectangularScreenDrag::RectangularScreenDrag(double length, double depth, double density,
                                             std::vector<LinearScreen> screens, int modes)
    : density_(density), screens_(std::move(screens)) {
  if (!(length > 0.0 && depth > 0.0 && modes >= 1)) throw std::invalid_argument("RectangularScreenDrag: bad tank");
  for (int n = 1; n <= modes; ++n) {
    const double k = n * std::numbers::pi / length;
    modal_mass_.push_back(density * length / (2.0 * k * std::tanh(k * depth)));
  }
  constexpr int kPoints = 24;  // the velocity is a sum of cosh: smooth over the depth
  std::vector<double> z, w;
  for (std::size_t s = 0; s < screens_.size(); ++s) {
    const LinearScreen& sc = screens_[s];
    if (!(sc.x > 0.0 && sc.x < length) || !(sc.z_from >= 0.0 && sc.z_to <= depth && sc.z_from < sc.z_to))
      throw std::invalid_argument("RectangularScreenDrag: a screen outside the tank or its depth");
    gauss_legendre(kPoints, sc.z_from, sc.z_to, z, w);
    for (std::size_t g = 0; g < z.size(); ++g) {
      Node node{s, w[g], {}};
      for (int n = 1; n <= modes; ++n) {
        const double k = n * std::numbers::pi / length;
        node.shape.push_back(-std::sin(k * sc.x) * std::cosh(k * z[g]) / std::sinh(k * depth));
      }
      nodes_.push_back(std::move(node));
    }
  }
}

void RectangularScreenDrag::add_accelerations(const std::vector<double>& velocity,
                                              std::vector<double>& acceleration) const {
  const std::size_t modes = std::min(velocity.size(), modal_mass_.size());
  for (const Node& node : nodes_) {
    double u = 0.0;
    for (std::size_t n = 0; n < modes; ++n) u += velocity[n] * node.shape[n];
    const LinearScreen& sc = screens_[node.screen];
    const double loss = sc.linear_resistance * u + 0.5 * density_ * sc.loss_coefficient * std::abs(u) * u;
    for (std::size_t n = 0; n < modes; ++n) acceleration[n] -= node.weight * loss * node.shape[n] / modal_mass_[n];
  }
}

}  // namespace sloshsph
