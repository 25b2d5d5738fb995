#pragma once
// Body force per unit mass in the tank frame. The tank frame is fixed to the tank: its
// origin translates with the base and its axes turn with the tank's pitch angle theta(t)
// about a pivot. Newton's law in that non-inertial frame (e.g. Shao et al. 2012, sec. 3.3):
//   a = R(-theta) (g - A)  -  alpha x (r - c)  -  omega x (omega x (r - c))  -  2 omega x u,
// where A is the translational acceleration of the pivot (inertial axes), omega = theta',
// alpha = theta'' (about the out-of-plane axis in 2D; vectors in 3D), c the pivot and u the
// tank-frame velocity.
// The last three terms are the Euler, centrifugal and Coriolis forces.
#include <type_traits>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

// The angular velocity and acceleration of the tank frame: a number (about the out-of-plane axis,
// counter-clockwise) in 2D, a vector in 3D.
template <int D>
using Angular = std::conditional_t<D == 2, double, Vec3>;

template <int D>
struct BasicFrameForce {
  Vec<D> uniform;       // R(-theta) (g - A): gravity and translational inertia, tank axes
  Angular<D> omega{};   // rad/s
  Angular<D> alpha{};   // rad/s^2
  Vec<D> pivot;         // m, tank frame

  Vec<D> at(Vec<D> r, Vec<D> u) const {
    const Vec<D> d = r - pivot;
    if constexpr (D == 2) {
      // In 2D, k x d = perp(d) and omega x (omega x d) = -omega^2 d.
      return uniform - alpha * perp(d) + (omega * omega) * d - (2.0 * omega) * perp(u);
    } else {
      return uniform - cross(alpha, d) - cross(omega, cross(omega, d)) - 2.0 * cross(omega, u);
    }
  }
  bool rotating() const {
    if constexpr (D == 2) return omega != 0.0 || alpha != 0.0;
    else return norm2(omega) != 0.0 || norm2(alpha) != 0.0;
  }
};

using FrameForce = BasicFrameForce<2>;
using FrameForce3 = BasicFrameForce<3>;

}  // namespace sloshsph
