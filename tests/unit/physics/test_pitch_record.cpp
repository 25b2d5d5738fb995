// A pitch from a file (physics/excitation.hpp): the harmonic pitch written to a file and read
// back gives the same theta, theta', theta'' within the cubic spline's interpolation error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "sloshsph/physics/excitation.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

// The harmonic pitch: 4 deg at 0.9 Hz, phase 0.3 rad, no ramp, about (0.3, -0.1) m.
ExcitationSpec harmonic_pitch() {
  ExcitationSpec e;
  e.type = ExcitationType::pitch;
  e.angle = 4.0 * kPi / 180.0;
  e.omega = 2.0 * kPi * 0.9;
  e.phase = 0.3;
  e.pivot = {0.3, -0.1};
  return e;
}

// The same motion as a record in degrees, sampled at `per_period` points a period from t0 to t1,
// written in model time tau = (t - start) / time_scale (Froude scaling, as a measured record would
// be given), with a header line and comments; with `derivatives`, also the rate and acceleration
// columns, in deg per unit of tau (d/dtau = time_scale d/dt).
ExcitationSpec file_pitch(const std::filesystem::path& path, int per_period, double t0, double t1,
                          bool derivatives = false) {
  const ExcitationSpec h = harmonic_pitch();
  ExcitationSpec e = h;
  e.angle = 0.0;
  e.omega = 0.0;
  e.phase = 0.0;
  e.file = path.string();
  e.value_unit = kPi / 180.0;  // unit = "deg"
  e.time_scale = 2.5;
  e.start = t0;
  const double dt = 2.0 * kPi / h.omega / per_period;
  std::ofstream out(path);
  out << "# harmonic pitch, 4 deg, 0.9 Hz, written by test_pitch_record\ntime,angle_deg\n";
  out.precision(17);
  for (int k = 0; t0 + k * dt <= t1 + 1e-12; ++k) {
    const double t = t0 + k * dt;
    const double deg = h.angle * 180.0 / kPi, phase = h.omega * t + h.phase;
    out << (t - e.start) / e.time_scale << ", " << deg * std::sin(phase);
    if (derivatives)
      out << ", " << deg * h.omega * e.time_scale * std::cos(phase) << ", "
          << -deg * h.omega * h.omega * e.time_scale * e.time_scale * std::sin(phase);
    out << "\n";
  }
  return e;
}

struct PitchErrors {
  double angle = 0.0, rate = 0.0, acceleration = 0.0;  // relative to theta0, theta0 w, theta0 w^2
};

PitchErrors largest_errors(const BaseMotionSource& file, const BaseMotionSource& harmonic, double t0, double t1) {
  const ExcitationSpec h = harmonic_pitch();
  PitchErrors e;
  for (int k = 0; k <= 20000; ++k) {
    const double t = t0 + (t1 - t0) * k / 20000.0;
    const BaseMotion a = file.at(t), b = harmonic.at(t);
    e.angle = std::max(e.angle, std::abs(a.angle - b.angle) / h.angle);
    e.rate = std::max(e.rate, std::abs(a.angular_velocity - b.angular_velocity) / (h.angle * h.omega));
    e.acceleration =
        std::max(e.acceleration, std::abs(a.angular_acceleration - b.angular_acceleration) / (h.angle * h.omega * h.omega));
  }
  return e;
}

// Reference: the harmonic pitch itself (closed-form theta, theta', theta''). Tolerance: the cubic
// spline bounds at N samples a period, w h = 2 pi / N, relative to theta0, theta0 w, theta0 w^2:
// 5/384 (w h)^4, 1/24 (w h)^3, 3/8 (w h)^2 (Hall & Meyer 1976; at N = 50: 3.2e-6, 8.3e-5, 5.9e-3),
// times 2.5, 4.5 and 2 for the not-a-knot end intervals (the worst over all phases,
// tests/unit/signals/cubic_spline_test.cpp), plus 1e-9 for the 17 digits of the file. The record
// starts and ends in motion (phase 1.71 rad at its start: near the worst case for the ends).
TEST(PitchRecord, HarmonicPitchWrittenToAFileIsReadBackWithinTheSplineError) {
  const auto path = std::filesystem::temp_directory_path() / "sloshsph_pitch_record_test.csv";
  const double t0 = 0.25, t1 = 0.25 + 3.0 / 0.9;  // three periods from 0.25 s
  const BaseMotionSource harmonic(harmonic_pitch(), 4.0);
  for (const int n : {50, 100}) {
    const BaseMotionSource file(file_pitch(path, n, t0, t1), 4.0);
    const PitchErrors e = largest_errors(file, harmonic, t0, t1);
    const double wh = 2.0 * kPi / n;
    std::printf("  N = %d a period: relative errors theta %.3g, theta' %.3g, theta'' %.3g\n", n, e.angle, e.rate,
                e.acceleration);
    EXPECT_LE(e.angle, 2.5 * 5.0 / 384.0 * std::pow(wh, 4) + 1e-9);
    EXPECT_LE(e.rate, 4.5 / 24.0 * std::pow(wh, 3) + 1e-9);
    EXPECT_LE(e.acceleration, 2.0 * 3.0 / 8.0 * wh * wh + 1e-9);
    EXPECT_EQ(file.at(0.1).pivot.y, -0.1);
  }
  std::filesystem::remove(path);
}

// Reference: the harmonic pitch. The file gives the rate and acceleration columns, so theta'' is
// the quintic Hermite interpolant's: error of order h^4 (h^6 on theta). Tolerance, relative to
// theta0, theta0 w, theta0 w^2 at N samples a period (w h = 2 pi / N): (w h)^6 / 46080 on theta
// (the Hermite remainder f^(6)/6! (t - a)^3 (t - b)^3), and (w h)^5 / 100, (w h)^4 / 100 on
// theta' and theta'' (measured well inside, printed); the error ratio of theta'' from N = 25 to
// N = 50 is 12 to 20 (order 4). Also checks the derivative columns' scaling by time_scale.
TEST(PitchRecord, DerivativeColumnsAreUsedWithTheirTimeScale) {
  const auto path = std::filesystem::temp_directory_path() / "sloshsph_pitch_record_derivatives.csv";
  const double t0 = 0.25, t1 = 0.25 + 3.0 / 0.9;
  const BaseMotionSource harmonic(harmonic_pitch(), 4.0);
  double previous = 0.0;
  for (const int n : {25, 50}) {
    const BaseMotionSource file(file_pitch(path, n, t0, t1, true), 4.0);
    const PitchErrors e = largest_errors(file, harmonic, t0, t1);
    const double wh = 2.0 * kPi / n;
    std::printf("  N = %d a period, with rate and acceleration columns: relative errors theta %.3g, theta' %.3g, "
                "theta'' %.3g\n", n, e.angle, e.rate, e.acceleration);
    EXPECT_LE(e.angle, std::pow(wh, 6) / 46080.0 + 1e-9);
    EXPECT_LE(e.rate, std::pow(wh, 5) / 100.0 + 1e-9);
    EXPECT_LE(e.acceleration, std::pow(wh, 4) / 100.0 + 1e-9);
    if (previous > 0.0) {
      EXPECT_GT(previous / e.acceleration, 12.0);
      EXPECT_LT(previous / e.acceleration, 20.0);
    }
    previous = e.acceleration;
  }
  std::filesystem::remove(path);
}

// Reference: docs/case-format.md: before the record the tank is held at its first angle, after it
// at its last, with zero rate and acceleration. Tolerance: the file's 17 digits.
TEST(PitchRecord, TankIsHeldStillOutsideTheRecord) {
  const auto path = std::filesystem::temp_directory_path() / "sloshsph_pitch_record_hold.csv";
  const double t0 = 0.25, t1 = 0.25 + 1.0 / 0.9;  // one period: t1 is the last sample
  const BaseMotionSource file(file_pitch(path, 50, t0, t1), 4.0);
  std::filesystem::remove(path);
  const ExcitationSpec h = harmonic_pitch();
  const BaseMotion before = file.at(0.1), after = file.at(3.0);
  EXPECT_NEAR(before.angle, h.angle * std::sin(h.omega * t0 + h.phase), 1e-12);
  EXPECT_EQ(before.angular_velocity, 0.0);
  EXPECT_EQ(before.angular_acceleration, 0.0);
  EXPECT_NEAR(after.angle, h.angle * std::sin(h.omega * t1 + h.phase), 1e-12);
  EXPECT_EQ(after.angular_velocity, 0.0);
  EXPECT_EQ(after.angular_acceleration, 0.0);
}

// Reference: the harmonic pitch of cases/shao_pitch.toml (6 deg sin(4.34 t)); the example record
// data/records/shao_pitch_6deg.csv holds it every 0.01 s (145 samples a period) to 6 decimals of
// a degree. Tolerance on theta'': the spline bound 3/8 (2 pi/145)^2 = 7.0e-4 of theta0 w^2, twice
// that in the end intervals (not-a-knot, as above), plus the rounding of the file, 5e-7 deg
// amplified by at most ~6/h^2 (the moment equations' right-hand side): 8.7e-9 rad x 6e4 /
// 1.97 rad/s^2 = 2.7e-4; together 1.7e-3. On theta and theta': 1e-6 and 1e-4 (bounds 1.2e-7 and
// 1.5e-5 with the end factors, plus the rounding).
TEST(PitchRecord, ExampleRecordIsTheShaoPitch) {
  ExcitationSpec file;
  file.type = ExcitationType::pitch;
  file.file = std::string(SLOSHSPH_SOURCE_DIR) + "/data/records/shao_pitch_6deg.csv";
  file.value_unit = kPi / 180.0;
  file.pivot = {0.32, -0.1};
  ExcitationSpec harmonic = file;
  harmonic.file.clear();
  harmonic.angle = 6.0 * kPi / 180.0;
  harmonic.omega = 4.34;
  const BaseMotionSource a(file, 10.0), b(harmonic, 10.0);
  double e0 = 0.0, e1 = 0.0, e2 = 0.0;
  for (int k = 0; k <= 100000; ++k) {
    const double t = 1e-4 * k;
    const BaseMotion x = a.at(t), y = b.at(t);
    e0 = std::max(e0, std::abs(x.angle - y.angle) / harmonic.angle);
    e1 = std::max(e1, std::abs(x.angular_velocity - y.angular_velocity) / (harmonic.angle * 4.34));
    e2 = std::max(e2, std::abs(x.angular_acceleration - y.angular_acceleration) / (harmonic.angle * 4.34 * 4.34));
  }
  std::printf("  example record vs 6 deg sin(4.34 t): relative errors theta %.3g, theta' %.3g, theta'' %.3g\n", e0, e1,
              e2);
  EXPECT_LE(e0, 1e-6);
  EXPECT_LE(e1, 1e-4);
  EXPECT_LE(e2, 1.7e-3);
}

}  // namespace
}  // namespace sloshsph
