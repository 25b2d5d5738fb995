#include "sloshsph/signals/base_motion_record.hpp"

#include <algorithm>

namespace sloshsph {
namespace {

// Velocity and displacement at the samples for a piecewise-linear acceleration (see header).
void integrate_samples(BaseMotionRecord& r) {
  const auto& t = r.acceleration.t;
  const auto& a = r.acceleration.value;
  r.velocity.assign(t.size(), 0.0);
  r.displacement.assign(t.size(), 0.0);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i];
    r.velocity[i + 1] = r.velocity[i] + 0.5 * h * (a[i] + a[i + 1]);
    r.displacement[i + 1] = r.displacement[i] + h * r.velocity[i] + h * h * (a[i] / 3.0 + a[i + 1] / 6.0);
  }
}

}  // namespace

BaseMotionRecord integrate_record(TimeSeries acceleration, BaselineCorrection correction) {
  check_time_series(acceleration, "base acceleration record");
  BaseMotionRecord r;
  r.acceleration = std::move(acceleration);
  integrate_samples(r);
  if (correction == BaselineCorrection::linear_velocity) {
    // a constant shift of a changes v by -c (t - t0): choose c so that v(t_end) = 0.
    r.correction = r.velocity.back() / (r.acceleration.end() - r.acceleration.start());
    for (double& a : r.acceleration.value) a -= r.correction;
    integrate_samples(r);
    r.velocity.back() = 0.0;  // exact in arithmetic; remove the rounding residue
  }
  return r;
}

BaseKinematics base_kinematics(const BaseMotionRecord& r, double t) {
  const auto& ts = r.acceleration.t;
  const auto& a = r.acceleration.value;
  if (t < ts.front()) return {};
  if (t > ts.back()) {
    const double v_end = r.velocity.back();
    return {r.displacement.back() + v_end * (t - ts.back()), v_end, 0.0};
  }
  // Interval [t_i, t_i+1] holding t (the last interval for t == t_end).
  const std::size_t upper = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  const std::size_t i = std::min(upper, ts.size() - 1) - 1;
  const double h = ts[i + 1] - ts[i];
  const double s = t - ts[i];
  const double slope = (a[i + 1] - a[i]) / h;  // da/dt on the interval
  BaseKinematics k;
  k.a = a[i] + slope * s;
  k.v = r.velocity[i] + a[i] * s + 0.5 * slope * s * s;
  k.x = r.displacement[i] + r.velocity[i] * s + 0.5 * a[i] * s * s + slope * s * s * s / 6.0;
  return k;
}

}  // namespace sloshsph
