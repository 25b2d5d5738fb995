#pragma once
// Imposed motion of the tank (the base). In the tank frame it enters the fluid
// as the body force -X''(t) (DESIGN: "the tank frame").
#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

struct BaseMotion {
  Vec2 displacement;  // m
  Vec2 velocity;      // m/s
  Vec2 acceleration;  // m/s^2
};

// X(t) = r(t) * A sin(omega t + phase), with the smooth ramp r(t) = (1 - cos(pi t / T_ramp)) / 2
// for t < T_ramp, 1 after; derivatives are exact (product rule). After `stop` the base
// rests where it is (a free-decay test): velocity and acceleration are zero.
BaseMotion base_motion(const ExcitationSpec& e, double t);

// Gravity plus the inertial force of the base acceleration, per unit mass, in the tank frame.
inline Vec2 tank_frame_body_force(double gravity, const BaseMotion& m) {
  return Vec2{0.0, -gravity} - m.acceleration;
}

}  // namespace sloshsph
