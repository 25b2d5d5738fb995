#include "sloshsph/physics/excitation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/signals/base_motion_record.hpp"
#include "sloshsph/signals/pulses.hpp"
#include "sloshsph/signals/record_readers.hpp"
#include "sloshsph/signals/white_noise.hpp"

namespace sloshsph {

struct BaseMotionSource::Record {
  BaseMotionRecord record;
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
    return read_two_column_csv(e.file, "excitation.file", o);
  }
  return read_peer_at2(e.file, "excitation.file", e.scale).acceleration;
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
    throw InputError("", "excitation.band", x.what());
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
      throw InputError(spec.file, "excitation.file", x.what());
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
      const Periodic a = stopped(e, e.angle, t);
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
