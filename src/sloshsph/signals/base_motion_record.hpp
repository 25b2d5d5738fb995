#pragma once
// Base (shake table / ground) kinematics from a sampled acceleration record: the simulator
// needs x(t), v(t), a(t) of the base at any time, mutually consistent.
#include "sloshsph/signals/time_series.hpp"

namespace sloshsph {

// Displacement, velocity and acceleration of the base along one axis.
struct BaseKinematics {
  double x = 0.0;  // m
  double v = 0.0;  // m/s
  double a = 0.0;  // m/s^2
};

enum class BaselineCorrection {
  none,             // integrate the record as it is (the base may end with a residual velocity)
  linear_velocity,  // remove the linear trend v_end * (t - t0) / (t_end - t0) from the velocity
};

// The acceleration record and its exact integrals. The acceleration is taken as the linear
// interpolant of the samples, so on each interval [t_i, t_i+1] (h = t_i+1 - t_i):
//   v_i+1 = v_i + h (a_i + a_i+1) / 2                      (trapezoid: exact for linear a)
//   x_i+1 = x_i + h v_i + h^2 (a_i / 3 + a_i+1 / 6)        (exact cubic)
// and base_kinematics() evaluates the same polynomials between samples, so v = dx/dt and
// a = dv/dt hold exactly at every t (no drift between what the fluid feels and where the tank is).
//
// Baseline correction `linear_velocity`: a constant c = v_end / (t_end - t0) is subtracted from
// every acceleration sample. This removes exactly the linear trend v_end (t - t0)/(t_end - t0)
// from the velocity, so the base starts and ends at rest (v = 0 at both ends), and keeps x, v, a
// consistent. The final displacement is generally not zero: the table ends displaced and rests
// there. We chose this one-parameter correction because it is the smallest change that stops
// the table drifting at constant speed after the record, and it keeps the kinematics exact.
struct BaseMotionRecord {
  TimeSeries acceleration;  // m/s^2 (corrected if a correction was chosen)
  std::vector<double> velocity;      // m/s at the sample times
  std::vector<double> displacement;  // m at the sample times
  double correction = 0.0;           // m/s^2 subtracted from the record (0 without correction)
};

// Integrates a record (>= 2 samples, strictly increasing times; uniform spacing not needed).
// The base is at rest at x = 0 at the first sample time. Throws std::invalid_argument on a bad series.
BaseMotionRecord integrate_record(TimeSeries acceleration, BaselineCorrection correction);

// Kinematics at time t. Before the record: at rest at x = 0. At t_end: the last sample. After: a = 0, the base
// keeps its final velocity (0 with the linear_velocity correction), x = x_end + v_end (t - t_end).
// Inside: the exact piecewise polynomials described above. O(log n).
BaseKinematics base_kinematics(const BaseMotionRecord& record, double t);

}  // namespace sloshsph
