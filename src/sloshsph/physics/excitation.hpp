#pragma once
// Imposed motion of the tank (the base). In the tank frame it enters the fluid as a body
// force (physics/frame.hpp; DESIGN: "the tank frame").
#include <cmath>
#include <memory>

#include "sloshsph/core/case_spec.hpp"
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
  // 3D (issue 31): the horizontal motion along y (the tank's breadth); x above is then the motion
  // along x, y above the vertical one (in_tank_axes). Zero in 2D.
  double displacement_y = 0.0, velocity_y = 0.0, acceleration_y = 0.0;
  // 3D: the rotation's axis (excitation.axis) and the pivot's y; the pivot above is (x, z).
  Vec3 axis{0.0, -1.0, 0.0};
  double pivot_across = 0.0;
};

// The base motion of an excitation at any time, with exactly consistent displacement,
// velocity and acceleration. Built once per run: record files are read and integrated, noise
// generated, at construction (InputError for a bad record, naming excitation.file).
//  harmonic: X = r(t) A sin(w t + phase), r(t) = (1 - cos(pi t / T_ramp)) / 2 for t < T_ramp
//            (1 after), exact derivatives (product rule); after `stop` the base coasts at the
//            velocity it had (zero acceleration: the fluid then decays freely).
//  pitch:    theta = r(t) theta0 sin(w t + phase) about the pivot, the same ramp and stop;
//            or, with a file, the angle record at t = time_scale tau + start: its own rate and
//            acceleration columns, or the not-a-knot cubic spline through its angles, joined by
//            quintic Hermite pieces; held still outside the record (excitation.cpp).
//  record:   the record's acceleration from `start` on, integrated exactly (signals/
//            base_motion_record.hpp), with the optional drift-velocity correction.
//  pulse:    one-cycle sine or cosine acceleration pulse (signals/pulses.hpp).
//  noise:    band-limited white-noise acceleration over [0, time.end], integrated as a record.
class BaseMotionSource {
 public:
  BaseMotionSource() = default;
  BaseMotionSource(const ExcitationSpec& spec, double end_time);
  BaseMotion at(double t) const;
  // Largest |base acceleration| over the motion (sampled), for time-step and sound-speed bounds.
  double peak_acceleration() const { return peak_acceleration_; }

 private:
  struct Record;
  ExcitationSpec spec_;
  std::shared_ptr<const Record> record_;
  double peak_acceleration_ = 0.0;
};

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

// 3D (issue 31): the base translates along the horizontal unit vector `direction` = (d_x, d_y)
// (excitation.direction): BaseMotionSource gives the motion along it in x and the vertical one in
// y. The same motion with its horizontal parts along the tank's x and y axes (a structure's
// sway is then added to each).
inline BaseMotion in_tank_axes(BaseMotion m, Vec2 direction) {
  m.displacement_y = m.displacement.x * direction.y;
  m.velocity_y = m.velocity.x * direction.y;
  m.acceleration_y = m.acceleration.x * direction.y;
  m.displacement.x *= direction.x;
  m.velocity.x *= direction.x;
  m.acceleration.x *= direction.x;
  return m;
}

// A vector of a motion in tank axes (in_tank_axes) as a 3D vector: (x, y, vertical).
inline Vec3 displacement3(const BaseMotion& m) { return {m.displacement.x, m.displacement_y, m.displacement.y}; }
inline Vec3 acceleration3(const BaseMotion& m) { return {m.acceleration.x, m.acceleration_y, m.acceleration.y}; }

// v turned by -theta about the unit axis n (Rodrigues' formula): the inertial vector v in the axes
// of a tank turned by theta about n.
inline Vec3 turned_back(Vec3 v, Vec3 n, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return c * v - s * cross(n, v) + ((1.0 - c) * dot(n, v)) * n;
}

// The body force of a 3D tank (its motion in tank axes): gravity (-z) less the base acceleration,
// turned into the tank's axes when it is turned by theta about m.axis through the pivot (x,
// pivot_across, z), with the rotation's terms omega = theta' n and alpha = theta'' n (the axis is
// fixed, so n is the same in both frames). With n = (0, -1, 0) this is the 2D frame_force of the
// section (x, z): the same uniform force and a 2D omega of theta'.
inline FrameForce3 frame_force3(double gravity, const BaseMotion& m) {
  FrameForce3 f;
  const Vec3 inertial = Vec3{0.0, 0.0, -gravity} - acceleration3(m);
  if (m.angle == 0.0 && m.angular_velocity == 0.0 && m.angular_acceleration == 0.0) {
    f.uniform = inertial;  // a translation: the 3D code before rotations, the same bits
    return f;
  }
  f.uniform = turned_back(inertial, m.axis, m.angle);
  f.omega = m.angular_velocity * m.axis;
  f.alpha = m.angular_acceleration * m.axis;
  f.pivot = {m.pivot.x, m.pivot_across, m.pivot.y};
  return f;
}

// The body force of a motion: in 2D as the excitation gives it, in 3D in tank axes.
template <int D>
BasicFrameForce<D> frame_force_in(double gravity, const BaseMotion& m) {
  if constexpr (D == 2) return frame_force(gravity, m);
  else return frame_force3(gravity, m);
}

}  // namespace sloshsph
