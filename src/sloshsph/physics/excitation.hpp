#pragma once
// Imposed motion of the tank (the base). In the tank frame it enters the fluid
// as the body force -X''(t) (DESIGN: "the tank frame").
#include "sloshsph/core/case_spec.hpp"
#include <cmath>

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/physics/frame.hpp"

namespace sloshsph {

struct BaseMotion {
  Vec2 displacement;  // m, of the pivot, inertial axes
  Vec2 velocity;      // m/s
  Vec2 acceleration;  // m/s^2
  double angle = 0.0;                 // rad, pitch of the tank (counter-clockwise)
  double angular_velocity = 0.0;      // rad/s
  double angular_acceleration = 0.0;  // rad/s^2
  Vec2 pivot;                         // m, tank frame: the axis of the pitch
};

// X(t) = r(t) * A sin(omega t + phase), with the smooth ramp r(t) = (1 - cos(pi t / T_ramp)) / 2
// for t < T_ramp, 1 after; derivatives are exact (product rule). After `stop` the base coasts
// at the velocity it had (zero acceleration: the fluid then decays freely).
BaseMotion base_motion(const ExcitationSpec& e, double t);

// The tank-frame body force of a base motion (physics/frame.hpp): gravity and the
// translational acceleration turned into tank axes, plus the rotation terms.
inline FrameForce frame_force(double gravity, const BaseMotion& m) {
  const double c = std::cos(m.angle), s = std::sin(m.angle);
  const Vec2 inertial = Vec2{0.0, -gravity} - m.acceleration;
  FrameForce f;
  f.uniform = {c * inertial.x + s * inertial.y, -s * inertial.x + c * inertial.y};  // R(-theta)
  f.omega = m.angular_velocity;
  f.alpha = m.angular_acceleration;
  f.pivot = m.pivot;
  return f;
}

}  // namespace sloshsph
