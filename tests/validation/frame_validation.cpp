// The tank frame (issue: pitch and the weakly compressible scheme): gravity turned into a
// tilted tank, and the body force of a tank under a constant acceleration, for both schemes.
// A tank 0.5 m long, 0.25 m deep, dp = 12.5 mm; the tilt or the acceleration is ramped in over
// 3 s (a half cosine, 3.6 sloshing periods, so little sloshing is left), held to 6 s, and the
// free surface and the pressure are averaged over the last 1.5 s.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "run_support.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_at_most;
using testing::check_relative;
using testing::report;

constexpr double kG = 9.81, kRho = 1000.0, kLength = 0.5, kDepth = 0.25, kGaugeGap = 0.3, kProbeY = 0.05;

std::string tank_case(const std::string& excitation) {
  return R"(
[tank]
shape = "rectangle"
length = 0.5
height = 0.4

[fill]
depth = 0.25

[particles]
dp = 0.0125

[time]
end = 6.0
dt = 1.0e-3

[[probes.gauge]]
name = "left"
x = 0.1

[[probes.gauge]]
name = "right"
x = 0.4

[[probes.pressure]]
name = "centre"
x = 0.25
y = 0.05

[output]
sample_interval = 0.01
snapshot_interval = 0
)" + excitation;
}

struct Level {
  double slope = 0.0;     // (eta_right - eta_left) / 0.3 m, in the tank's axes
  double pressure = 0.0;  // Pa at (0.25, 0.05) m
};

Level settled_level(const std::string& name, const std::string& text, const std::string& scheme,
                    const std::string& extra_file = "", const std::string& extra_text = "") {
  const auto dir = std::filesystem::temp_directory_path() / ("sloshsph_frame_" + name + "_" + scheme);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "case.toml") << text;
  if (!extra_file.empty()) std::ofstream(dir / extra_file) << extra_text;
  const auto r = testing::run_file_in_memory((dir / "case.toml").string(), {"scheme.type=" + scheme}, [](const Simulation&) {});
  std::filesystem::remove_all(dir);
  check_at_most("particles leaked from the tank in 6 s, " + name + ", " + (scheme == "isph" ? "ISPH" : "WCSPH"),
                static_cast<double>(r.leaked), 0.0, "none may leave");
  Level level;
  int n = 0;
  for (std::size_t i = 0; i < r["time"].size(); ++i)
    if (r["time"][i] >= 4.5) {
      level.slope += (r["eta:right"][i] - r["eta:left"][i]) / kGaugeGap;
      level.pressure += r["p:centre"][i];
      ++n;
    }
  level.slope /= n;
  level.pressure /= n;
  std::printf("  %s, %s: %zu steps in %.0f s\n", name.c_str(), scheme.c_str(), r.steps, r.wall_seconds);
  return level;
}

// Reference: a tank held at a tilt theta (counter-clockwise) sees gravity (-g sin, -g cos) in its
// axes: the free surface stays level in the inertial frame, i.e. slope -tan(theta) in the tank's
// axes, through the centre of the still surface (a rectangle's area is kept), so the pressure at
// (L/2, y) is rho g cos(theta) (h - y). Tolerance: 2% on the slope and on that pressure (issue).
TEST(Validation, TiltedTankKeepsItsSurfaceLevel) {
  const double theta = 6.0 * std::numbers::pi / 180.0;
  // theta(t) = ramp(t) 6 deg cos(0.001 t): held to within 3e-5 of 6 deg over the run.
  const std::string text = tank_case(R"(
[excitation]
type = "pitch"
angle = 6.0
pivot = [0.25, 0.0]
omega = 0.001
phase = 1.5707963267948966
ramp = 3.0
)");
  for (const std::string scheme : {"isph", "wcsph"}) {
    const Level level = settled_level("tilt", text, scheme);
    const double slope = -std::tan(theta), pressure = kRho * kG * std::cos(theta) * (kDepth - kProbeY);
    report("tilt_surface_slope_ratio_" + scheme, level.slope / slope);
    report("tilt_pressure_ratio_" + scheme, level.pressure / pressure);
    const std::string label = scheme == "isph" ? "ISPH" : "WCSPH";
    check_relative("free-surface slope in the tank's axes, mean over 4.5-6 s, tilt 6 deg, " + label, level.slope, slope,
                   0.02, "level surface in the inertial frame: -tan(theta)");
    check_relative("pressure at (L/2, 0.05 m), mean over 4.5-6 s, tilt 6 deg, " + label, level.pressure, pressure, 0.02,
                   "hydrostatics in the tilted tank: rho g cos(theta) (h - y)", "Pa");
  }
}

// Reference: under a constant base acceleration a (+x) the liquid at rest in the tank has the
// body force -a: its surface is inclined at atan(a/g), slope -a/g in the tank's axes, and the
// pressure at (L/2, y) stays rho g (h - y). a = 0.1 g, as a recorded acceleration (a CSV record,
// no baseline correction). Tolerance: 2% (issue).
TEST(Validation, AcceleratedTankSurfaceInclinesAtAtanAOverG) {
  const double a = 0.1 * kG;
  std::string record = "time,acceleration\n";
  for (int k = 0; k <= 60; ++k) {
    const double t = 0.05 * k;
    record += std::to_string(t) + "," + std::to_string(a * 0.5 * (1.0 - std::cos(std::numbers::pi * t / 3.0))) + "\n";
  }
  record += "10.0," + std::to_string(a) + "\n";
  const std::string text = tank_case(R"(
[excitation]
type = "record"
file = "accel.csv"
baseline_correction = false
)");
  for (const std::string scheme : {"isph", "wcsph"}) {
    const Level level = settled_level("accel", text, scheme, "accel.csv", record);
    const double slope = -a / kG, pressure = kRho * kG * (kDepth - kProbeY);
    report("accel_surface_slope_ratio_" + scheme, level.slope / slope);
    report("accel_pressure_ratio_" + scheme, level.pressure / pressure);
    const std::string label = scheme == "isph" ? "ISPH" : "WCSPH";
    check_relative("free-surface slope in the tank's axes, mean over 4.5-6 s, a = 0.1 g, " + label, level.slope, slope,
                   0.02, "liquid at rest under the body force -a: -a/g (inclined at atan(a/g))");
    check_relative("pressure at (L/2, 0.05 m), mean over 4.5-6 s, a = 0.1 g, " + label, level.pressure, pressure, 0.02,
                   "hydrostatics, unchanged by a horizontal acceleration: rho g (h - y)", "Pa");
  }
}

}  // namespace
}  // namespace sloshsph
