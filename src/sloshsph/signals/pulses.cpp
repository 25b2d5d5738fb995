#include "sloshsph/signals/pulses.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sloshsph {
namespace {

// Kinematics at s in [0, T] (see the header for the closed forms).
BaseKinematics inside(const PulseSpec& p, double s) {
  const double w = 2.0 * std::numbers::pi / p.period;
  const double A = p.amplitude;
  const double sn = std::sin(w * s), cs = std::cos(w * s);
  if (p.shape == PulseShape::sine) return {(A / w) * (s - sn / w), (A / w) * (1.0 - cs), A * sn};
  return {(A / (w * w)) * (1.0 - cs), (A / w) * sn, A * cs};
}

}  // namespace

double pulse_residual_displacement(const PulseSpec& p) {
  if (p.shape == PulseShape::cosine) return 0.0;
  return p.amplitude * p.period * p.period / (2.0 * std::numbers::pi);
}

BaseKinematics pulse_kinematics(const PulseSpec& p, double t) {
  if (!(p.period > 0.0)) throw std::invalid_argument("pulse period must be > 0");
  const double s = t - p.start;
  if (s < 0.0) return {};
  if (s > p.period) return {pulse_residual_displacement(p), 0.0, 0.0};
  return inside(p, s);
}

}  // namespace sloshsph
