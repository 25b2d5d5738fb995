#include "sloshsph/physics/excitation.hpp"

#include <cmath>
#include <numbers>

namespace sloshsph {
namespace {

BaseMotion harmonic(const ExcitationSpec& e, double t) {
  const double w = e.omega, a = e.amplitude;
  const double s = std::sin(w * t + e.phase), c = std::cos(w * t + e.phase);
  double r = 1.0, dr = 0.0, ddr = 0.0;
  if (e.ramp > 0.0 && t < e.ramp) {
    const double k = std::numbers::pi / e.ramp;
    r = 0.5 * (1.0 - std::cos(k * t));
    dr = 0.5 * k * std::sin(k * t);
    ddr = 0.5 * k * k * std::cos(k * t);
  }
  BaseMotion m;
  m.displacement.x = r * a * s;
  m.velocity.x = dr * a * s + r * a * w * c;
  m.acceleration.x = ddr * a * s + 2.0 * dr * a * w * c - r * a * w * w * s;
  return m;
}

}  // namespace

BaseMotion base_motion(const ExcitationSpec& e, double t) {
  if (e.type == ExcitationType::none) return {};
  if (e.stop >= 0.0 && t > e.stop) {
    // After `stop` the base coasts at the velocity it had: no acceleration, so the fluid
    // feels nothing more (a free-decay test), and the kinematics stay consistent.
    BaseMotion coast = harmonic(e, e.stop);
    coast.displacement += (t - e.stop) * coast.velocity;
    coast.acceleration = {};
    return coast;
  }
  return harmonic(e, t);
}

}  // namespace sloshsph
