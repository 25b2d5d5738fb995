#pragma once
// Body force per unit mass in the tank frame. The tank frame is fixed to the tank: its
// origin translates with the base and its axes turn with the tank's pitch angle theta(t)
// about a pivot. Newton's law in that non-inertial frame (e.g. Shao et al. 2012, sec. 3.3):
//   a = R(-theta) (g - A)  -  alpha x (r - c)  -  omega x (omega x (r - c))  -  2 omega x u,
// where A is the translational acceleration of the pivot (inertial axes), omega = theta',
// alpha = theta'' (about the out-of-plane axis), c the pivot and u the tank-frame velocity.
// The last three terms are the Euler, centrifugal and Coriolis forces.
#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

struct FrameForce {
  Vec2 uniform;        // R(-theta) (g - A): gravity and translational inertia, tank axes
  double omega = 0.0;  // rad/s, counter-clockwise
  double alpha = 0.0;  // rad/s^2
  Vec2 pivot;          // m, tank frame

  // In 2D, k x d = perp(d) and omega x (omega x d) = -omega^2 d.
  Vec2 at(Vec2 r, Vec2 u) const {
    const Vec2 d = r - pivot;
    return uniform - alpha * perp(d) + (omega * omega) * d - (2.0 * omega) * perp(u);
  }
  bool rotating() const { return omega != 0.0 || alpha != 0.0; }
};

}  // namespace sloshsph
