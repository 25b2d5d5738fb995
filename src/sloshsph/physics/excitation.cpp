#include "sloshsph/physics/excitation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/signals/base_motion_record.hpp"
#include "sloshsph/signals/cubic_spline.hpp"
#include "sloshsph/signals/quintic_hermite.hpp"
#include "sloshsph/signals/pulses.hpp"
#include "sloshsph/signals/record_readers.hpp"
#include "sloshsph/signals/white_noise.hpp"

namespace sloshsph {

struct BaseMotionSource::Record {
  BaseMotionRecord record;  // record, noise
  HermiteSamples angle;     // pitch from a file: theta, theta', theta'' (rad, s) at the samples
};

namespace {

// s(t) = r(t) A sin(w t + phase) and its first two derivatives, with the cosine ramp.
struct Periodic {
  double value, rate, acceleration;
};

Periodic ramped_sine(const ExcitationSpec& e, double amplitude, double t) {
  const double w = e.omega;
  const double sn = std::sin(w * t + e.phase), cs = std::cos(w * t + e.phase);
  double r = 1.0, dr = 0.0, ddr = 0.0;
  if (e.ramp > 0.0 && t < e.ramp) {
    const double k = std::numbers::pi / e.ramp;
    r = 0.5 * (1.0 - std::cos(k * t));
    dr = 0.5 * k * std::sin(k * t);
    ddr = 0.5 * k * k * std::cos(k * t);
  }
  return {r * amplitude * sn, dr * amplitude * sn + r * amplitude * w * cs,
          ddr * amplitude * sn + 2.0 * dr * amplitude * w * cs - r * amplitude * w * w * sn};
}

// After `stop`: the value goes on at the rate it had, with zero acceleration.
Periodic stopped(const ExcitationSpec& e, double amplitude, double t) {
  if (e.stop < 0.0 || t <= e.stop) return ramped_sine(e, amplitude, t);
  Periodic p = ramped_sine(e, amplitude, e.stop);
  p.value += (t - e.stop) * p.rate;
  p.acceleration = 0.0;
  return p;
}

TimeSeries shifted(TimeSeries s, double start) {
  for (double& t : s.t) t += start;
  if (start > 0.0) {  // at rest before the record
    s.t.insert(s.t.begin(), 0.0);
    s.value.insert(s.value.begin(), 0.0);
  }
  return s;
}

TimeSeries load_record(const ExcitationSpec& e) {
  if (e.format == "csv") {
    CsvRecordOptions o;
    o.time_factor = e.time_scale;
    o.value_factor = e.value_unit;
    o.scale = e.scale;
    return read_two_column_csv(e.file, e.table + ".file", o);
  }
  return read_peer_at2(e.file, e.table + ".file", e.scale).acceleration;
}

// Largest angle a pitch record may hold: the harmonic pitch's `angle` limit. A record in
// degrees read with unit = "rad" (57 times too large) is caught by it.
constexpr double kMaxPitchAngle = 45.0 * std::numbers::pi / 180.0;

// The angle record of a pitch from a file: its rows (time, angle) or (time, angle, rate,
// acceleration), in rad at simulation times t = time_scale tau + start (tau: the file's time
// column), checked against the run [0, end_time]. The rate and acceleration columns are per unit
// of the file's time: d/dt = (1/time_scale) d/dtau.
RecordTable read_angle_table(const ExcitationSpec& e, double end_time) {
  CsvRecordOptions o;
  o.time_factor = e.time_scale;
  o.value_factor = e.value_unit;
  RecordTable s = read_record_table(e.file, e.table + ".file", {2, 4},
                              "2 fields (time, angle) or 4 (time, angle, rate, acceleration)", o);
  for (double& t : s.t) t += e.start;
  if (s.values.size() == 1 && s.t.size() < 4)
    throw InputError(e.file, e.table + ".file",
                     "a pitch record needs at least 4 rows (a not-a-knot cubic spline), found " + std::to_string(s.t.size()));
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (std::abs(s.values[0][i]) > kMaxPitchAngle)
      throw InputError(e.file, e.table + ".file",
                       "the angle " + std::to_string(s.values[0][i] * 180.0 / std::numbers::pi) + " deg (row " +
                           std::to_string(i + 1) + " of the data) is beyond 45 deg: is excitation.unit right?");
  if (!(s.t.back() > 0.0))
    throw InputError("", e.table + ".start",
                     "the record ends at t = " + std::to_string(s.t.back()) +
                         " s (time_scale x its last time + start), before the run begins at t = 0");
  if (!(s.t.front() < end_time))
    throw InputError("", e.table + ".start",
                     "the record begins at t = " + std::to_string(s.t.front()) +
                         " s (time_scale x its first time + start), at or after the end of the run (time.end = " +
                         std::to_string(end_time) + " s)");
  return s;
}

// theta, theta', theta'' at the samples (docs/physics.md): the file's own rate and acceleration
// columns when it has them, else those of the not-a-knot cubic spline through the angles
// (signals/cubic_spline.hpp: C2, so the Euler term alpha = theta'' is continuous, O(h^2) error).
HermiteSamples angle_samples(const ExcitationSpec& e, double end_time) {
  RecordTable s = read_angle_table(e, end_time);
  if (s.values.size() == 1) return hermite_samples(not_a_knot_spline(TimeSeries{s.t, s.values[0]}));
  HermiteSamples h{s.t, s.values[0], s.values[1], s.values[2]};
  for (double& v : h.first) v /= e.time_scale;
  for (double& a : h.second) a /= e.time_scale * e.time_scale;
  check_hermite_samples(h, "pitch record");  // a rate or acceleration overflowed by a tiny time_scale
  return h;
}

// The pitch from a file between the samples: the quintic Hermite interpolant of theta, theta',
// theta'' (signals/quintic_hermite.hpp; with the spline's data, the spline itself). Outside the
// record the tank is held still: at the first angle before the first sample, at the last angle
// after the last one (rate and acceleration 0; a record that does not start and end at rest jumps
// in rate there, an impulse the fluid does not feel).
Periodic recorded_angle(const HermiteSamples& angle, double t) {
  if (t < angle.t.front()) return {angle.value.front(), 0.0, 0.0};
  if (t > angle.t.back()) return {angle.value.back(), 0.0, 0.0};
  const SplineSample s = evaluate(angle, t);
  return {s.value, s.first, s.second};
}

TimeSeries noise_record(const ExcitationSpec& e, double end_time) {
  BandLimitedNoiseSpec n;
  n.seed = e.seed;
  n.f_lo = e.band_low;
  n.f_hi = e.band_high;
  n.duration = std::max(end_time, 1.0 / e.band_low);
  n.dt = std::min(0.01, 0.1 / e.band_high);
  n.rms = e.rms;
  try {
    return band_limited_white_noise(n).series;
  } catch (const std::invalid_argument& x) {
    throw InputError("", e.table + ".band", x.what());
  }
}

}  // namespace

BaseMotionSource::BaseMotionSource(const ExcitationSpec& spec, double end_time) : spec_(spec) {
  TimeSeries acceleration;
  if (spec.type == ExcitationType::record) acceleration = shifted(load_record(spec), spec.start);
  if (spec.type == ExcitationType::noise) acceleration = noise_record(spec, end_time);
  if (!acceleration.t.empty()) {
    auto r = std::make_shared<Record>();
    try {
      r->record = integrate_record(acceleration, spec.baseline_correction || spec.type == ExcitationType::noise
                                                     ? BaselineCorrection::linear_velocity
                                                     : BaselineCorrection::none);
    } catch (const std::invalid_argument& x) {
      throw InputError(spec.file, spec.table + ".file", x.what());
    }
    record_ = r;
  }
  if (is_pitch_record(spec)) {
    auto r = std::make_shared<Record>();
    try {
      r->angle = angle_samples(spec, end_time);
    } catch (const std::invalid_argument& x) {
      throw InputError(spec.file, spec.table + ".file", x.what());
    }
    record_ = r;
  }
  const int samples = 4000;
  for (int k = 0; k <= samples; ++k) {
    const BaseMotion m = at(end_time * k / samples);
    peak_acceleration_ = std::max(peak_acceleration_, norm(m.acceleration));
  }
}

BaseMotion BaseMotionSource::at(double t) const {
  const ExcitationSpec& e = spec_;
  BaseMotion m;
  m.pivot = e.pivot;
  m.axis = e.axis;
  m.pivot_across = e.pivot_across;
  switch (e.type) {
    case ExcitationType::none:
      break;
    case ExcitationType::harmonic: {
      const Periodic x = stopped(e, e.amplitude, t);
      m.displacement.x = x.value;
      m.velocity.x = x.rate;
      m.acceleration.x = x.acceleration;
      break;
    }
    case ExcitationType::pitch: {
      const Periodic a = record_ ? recorded_angle(record_->angle, t) : stopped(e, e.angle, t);
      m.angle = a.value;
      m.angular_velocity = a.rate;
      m.angular_acceleration = a.acceleration;
      break;
    }
    case ExcitationType::record:
    case ExcitationType::noise: {
      const BaseKinematics k = base_kinematics(record_->record, t);
      m.displacement.x = k.x;
      m.velocity.x = k.v;
      m.acceleration.x = k.a;
      break;
    }
    case ExcitationType::pulse: {
      PulseSpec p;
      p.shape = e.shape == "cosine" ? PulseShape::cosine : PulseShape::sine;
      p.amplitude = e.acceleration;
      p.period = e.period;
      p.start = e.start;
      const BaseKinematics k = pulse_kinematics(p, t);
      m.displacement.x = k.x;
      m.velocity.x = k.v;
      m.acceleration.x = k.a;
      break;
    }
  }
  return m;
}

}  // namespace sloshsph
