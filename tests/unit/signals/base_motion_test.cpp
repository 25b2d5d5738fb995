// Sampling, record integration and one-cycle pulses (time_series.hpp, base_motion_record.hpp, pulses.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sloshsph/signals/base_motion_record.hpp"
#include "sloshsph/signals/pulses.hpp"
#include "sloshsph/signals/record_readers.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Sample, LinearInsideZeroOutside) {
  const TimeSeries s{{0.0, 1.0, 3.0}, {2.0, 4.0, 0.0}};
  EXPECT_DOUBLE_EQ(sample(s, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(sample(s, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(sample(s, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(sample(s, 2.5), 1.0);
  EXPECT_DOUBLE_EQ(sample(s, 3.0), 0.0);
  EXPECT_DOUBLE_EQ(sample(s, -0.1), 0.0);  // before the record: zero (documented)
  EXPECT_DOUBLE_EQ(sample(s, 3.1), 0.0);   // after the record: zero
}

TEST(RecordIntegration, ConstantAccelerationIsExact) {
  // a = 2 m/s^2 on a non-uniform grid: v = 2 t, x = t^2 exactly (the scheme is exact for linear a).
  const TimeSeries a{{0.0, 0.1, 0.35, 1.0}, {2.0, 2.0, 2.0, 2.0}};
  const BaseMotionRecord r = integrate_record(a, BaselineCorrection::none);
  for (double t : {0.0, 0.05, 0.2, 0.7, 1.0}) {
    const BaseKinematics k = base_kinematics(r, t);
    EXPECT_NEAR(k.a, 2.0, 1e-14);
    EXPECT_NEAR(k.v, 2.0 * t, 1e-14);
    EXPECT_NEAR(k.x, t * t, 1e-14);
  }
  // After the record: a = 0, the base keeps its final velocity 2 m/s.
  const BaseKinematics after = base_kinematics(r, 1.5);
  EXPECT_DOUBLE_EQ(after.a, 0.0);
  EXPECT_NEAR(after.v, 2.0, 1e-14);
  EXPECT_NEAR(after.x, 1.0 + 2.0 * 0.5, 1e-14);
  const BaseKinematics before = base_kinematics(r, -1.0);
  EXPECT_EQ(before.x, 0.0);
  EXPECT_EQ(before.v, 0.0);
}

TEST(RecordIntegration, SampledSineConvergesToClosedForm) {
  // a = A w^2 sin(w t) from rest: v = A w (1 - cos w t), x = A (w t - sin w t).
  // Linear interpolation of a: error O(dt^2); with 200 samples a period, the relative error
  // of x after one period is ~ (w dt)^2 / 12 ~ 1e-4: tolerance 2e-4 of the peak.
  const double A = 0.01, w = 2.0 * kPi, dt = 1.0 / 200.0;
  std::vector<double> values;
  for (int i = 0; i <= 200; ++i) values.push_back(A * w * w * std::sin(w * i * dt));
  const BaseMotionRecord r = integrate_record(uniform_series(dt, values), BaselineCorrection::none);
  for (double t : {0.25, 0.5, 0.8, 1.0}) {
    const BaseKinematics k = base_kinematics(r, t);
    EXPECT_NEAR(k.v, A * w * (1 - std::cos(w * t)), 2e-4 * 2 * A * w) << t;
    EXPECT_NEAR(k.x, A * (w * t - std::sin(w * t)), 2e-4 * A * w) << t;
  }
}

TEST(RecordIntegration, KinematicsAreConsistentBetweenSamples) {
  // v = dx/dt and a = dv/dt at arbitrary t between samples (central differences, h = 1e-5 s;
  // error ~ h^2 |a''|, and a'' = 0 inside an interval). Times avoid the samples (multiples of
  // 0.02 s), where da/dt jumps and a central difference of v is off by h |jump of da/dt| / 4.
  const GroundRecord rec = read_peer_at2(std::string(SLOSHSPH_SOURCE_DIR) + "/data/records/elcentro_1940_ns.at2", "k");
  const BaseMotionRecord r = integrate_record(rec.acceleration, BaselineCorrection::linear_velocity);
  const double h = 1e-5;
  for (double t : {0.013, 2.017, 5.555, 17.31, 30.99}) {
    const BaseKinematics k = base_kinematics(r, t);
    const BaseKinematics kp = base_kinematics(r, t + h), km = base_kinematics(r, t - h);
    EXPECT_NEAR((kp.x - km.x) / (2 * h), k.v, 1e-8) << t;
    EXPECT_NEAR((kp.v - km.v) / (2 * h), k.a, 1e-6) << t;
  }
}

TEST(RecordIntegration, LinearVelocityCorrectionEndsAtRest) {
  const GroundRecord rec = read_peer_at2(std::string(SLOSHSPH_SOURCE_DIR) + "/data/records/elcentro_1940_ns.at2", "k");
  const BaseMotionRecord raw = integrate_record(rec.acceleration, BaselineCorrection::none);
  const BaseMotionRecord cor = integrate_record(rec.acceleration, BaselineCorrection::linear_velocity);
  const double t_end = rec.acceleration.end();
  // The correction is the constant v_end / T (header): check it, and that v ends at 0 and
  // v_cor(t) = v_raw(t) - v_end t / T everywhere.
  EXPECT_NEAR(cor.correction, raw.velocity.back() / t_end, 1e-15);
  EXPECT_EQ(base_kinematics(cor, t_end + 10.0).v, 0.0);
  for (double t : {1.0, 7.7, 20.0}) {
    EXPECT_NEAR(base_kinematics(cor, t).v, base_kinematics(raw, t).v - raw.velocity.back() * t / t_end, 1e-12);
  }
  // After the record, the corrected base rests where it ended.
  EXPECT_DOUBLE_EQ(base_kinematics(cor, t_end + 5.0).x, cor.displacement.back());
  RecordProperty("raw_v_end_m_per_s", std::to_string(raw.velocity.back()));
  RecordProperty("corrected_x_end_m", std::to_string(cor.displacement.back()));
  std::printf("El Centro: raw end velocity %.6f m/s, raw end displacement %.4f m; corrected end displacement %.4f m\n",
              raw.velocity.back(), raw.displacement.back(), cor.displacement.back());
}

TEST(Pulses, ClosedFormsAreConsistentAndEndAtRest) {
  const double A = 3.0, T = 0.8;
  for (PulseShape shape : {PulseShape::sine, PulseShape::cosine}) {
    const PulseSpec p{shape, A, T, 0.5};
    // Derivatives (central differences, h = 1e-6; truncation ~ h^2 A w^2 ~ 1e-10).
    const double h = 1e-6;
    for (double t : {0.55, 0.7, 0.9, 1.2}) {
      const BaseKinematics k = pulse_kinematics(p, t);
      const BaseKinematics kp = pulse_kinematics(p, t + h), km = pulse_kinematics(p, t - h);
      EXPECT_NEAR((kp.x - km.x) / (2 * h), k.v, 1e-7);
      EXPECT_NEAR((kp.v - km.v) / (2 * h), k.a, 1e-6);
    }
    // Before: rest at 0. At the end of the pulse: v = 0 and x = the residual; after: frozen.
    const BaseKinematics before = pulse_kinematics(p, 0.4);
    EXPECT_EQ(before.x, 0.0);
    const BaseKinematics end = pulse_kinematics(p, 0.5 + T);
    EXPECT_NEAR(end.v, 0.0, 1e-14);
    EXPECT_NEAR(end.x, pulse_residual_displacement(p), 1e-14);
    const BaseKinematics after = pulse_kinematics(p, 5.0);
    EXPECT_EQ(after.v, 0.0);
    EXPECT_EQ(after.a, 0.0);
    EXPECT_NEAR(after.x, pulse_residual_displacement(p), 1e-14);
  }
  // Sine: continuous acceleration, residual displacement A T^2 / (2 pi).
  EXPECT_NEAR(pulse_residual_displacement({PulseShape::sine, A, T, 0.0}), A * T * T / (2 * kPi), 1e-15);
  EXPECT_NEAR(pulse_kinematics({PulseShape::sine, A, T, 0.0}, 1e-12).a, 0.0, 1e-10);
  // Cosine: peak acceleration A at the start (a step from 0), back to x = 0.
  EXPECT_DOUBLE_EQ(pulse_kinematics({PulseShape::cosine, A, T, 0.0}, 0.0).a, A);
  EXPECT_EQ(pulse_residual_displacement({PulseShape::cosine, A, T, 0.0}), 0.0);
  // Cosine peak displacement 2 A / w^2 at T/2.
  const double w = 2 * kPi / T;
  EXPECT_NEAR(pulse_kinematics({PulseShape::cosine, A, T, 0.0}, T / 2).x, 2 * A / (w * w), 1e-14);
}

}  // namespace
}  // namespace sloshsph
