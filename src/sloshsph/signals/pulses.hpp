#pragma once
// One-cycle acceleration pulses, the idealised near-fault excitations of Dincer (2019), sec. 3.1
// (Fig. 4): a(t) = A sin(2 pi t / T) or A cos(2 pi t / T) for 0 <= t - start <= T, zero otherwise,
// with the same period and peak acceleration for both shapes.
#include "sloshsph/signals/base_motion_record.hpp"

namespace sloshsph {

enum class PulseShape { sine, cosine };

struct PulseSpec {
  PulseShape shape = PulseShape::sine;
  double amplitude = 0.0;  // A, m/s^2 (peak acceleration)
  double period = 1.0;     // T, s
  double start = 0.0;      // s, the pulse occupies [start, start + T]
};

// Exact kinematics, starting from rest at x = 0 (w = 2 pi / T, s = t - start in [0, T]):
//   sine:    a = A sin(w s),  v = (A / w)(1 - cos(w s)),  x = (A / w)(s - sin(w s) / w)
//            at s = T: v = 0, x = A T^2 / (2 pi). The acceleration is continuous (0 at both ends),
//            the velocity is never negative: the table moves one way and ends at rest displaced
//            by A T^2 / (2 pi) (0.159 m for A = 1 m/s^2, T = 1 s).
//   cosine:  a = A cos(w s),  v = (A / w) sin(w s),       x = (A / w^2)(1 - cos(w s))
//            at s = T: v = 0, x = 0: no residual velocity and no residual displacement (the table
//            goes out to 2 A / w^2 and back), but the acceleration jumps from 0 to A at the start
//            and from A to 0 at the end (a step of A, which a real table smooths).
// Neither pulse drifts: both end at rest. After the pulse: a = v = 0, x = final value.
BaseKinematics pulse_kinematics(const PulseSpec& pulse, double t);

// The displacement left after the pulse: A T^2 / (2 pi) for the sine, 0 for the cosine.
double pulse_residual_displacement(const PulseSpec& pulse);

}  // namespace sloshsph
