#include "sloshsph/linear/closed_form.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/linear/rectangular.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kJ01Squared = 5.783185962946784;  // first zero of J0, squared (thesis: 5.783)

void check_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError("", "", std::string("closed-form sloshing frequency: ") + what + " must be positive");
}

[[noreturn]] void fail_depth(const std::string& why) {
  throw InputError("", "fill.depth", "no closed-form sloshing frequency: " + why);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

double flat_long_wave_omega(double length, double depth, double gravity) {
  check_positive(length, "the length");
  check_positive(depth, "the depth");
  return kPi / length * std::sqrt(gravity * depth);  // thesis eq. 3.29
}

double v_bottom_long_wave_omega(double surface_length, double depth, double gravity) {
  check_positive(surface_length, "the free-surface length");
  check_positive(depth, "the depth");
  return std::sqrt(kJ01Squared * gravity * depth / (surface_length * surface_length));  // thesis eq. 3.32
}

double trapezoid_long_wave_omega(double bottom_width, double angle_deg, double depth, double gravity) {
  check_positive(depth, "the depth");
  if (!(angle_deg > 0.0 && angle_deg < 90.0)) throw InputError("", "tank.angle", "must be between 0 and 90 degrees");
  if (!(bottom_width >= 0.0)) throw InputError("", "tank.bottom_width", "must not be negative");
  const double slope = std::tan(angle_deg * kPi / 180.0);
  if (bottom_width == 0.0) return v_bottom_long_wave_omega(2.0 * depth / slope, depth, gravity);
  // F(omega) = J0(z) cos(k b/2) - J1(z) sin(k b/2) (elevation and flux matched at the toes).
  auto f = [&](double omega) {
    const double z = 2.0 * omega * std::sqrt(depth / gravity) / slope;
    const double kb = omega / std::sqrt(gravity * depth) * 0.5 * bottom_width;
    return std::cyl_bessel_j(0.0, z) * std::cos(kb) - std::cyl_bessel_j(1.0, z) * std::sin(kb);
  };
  // F(0) = 1. Scan for the first sign change in steps of a fraction of the smaller of the
  // V root (b = 0) and the flat root (vertical slopes, width b), then bisect.
  const double v_root = v_bottom_long_wave_omega(2.0 * depth / slope, depth, gravity);
  const double flat_root = flat_long_wave_omega(bottom_width, depth, gravity);
  const double step = std::min(v_root, flat_root) / 500.0;
  double lo = 0.0;
  for (int i = 1; i <= 50000; ++i) {
    double hi = step * i;
    if (f(hi) <= 0.0) {
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (f(mid) > 0.0) lo = mid;
        else hi = mid;
      }
      return 0.5 * (lo + hi);
    }
    lo = hi;
  }
  throw std::runtime_error("trapezoid_long_wave_omega: no root found");
}

double parabolic_long_wave_omega(double half_surface_length, double depth, double gravity) {
  check_positive(half_surface_length, "the half free-surface length");
  check_positive(depth, "the depth");
  return std::sqrt(2.0 * gravity * depth / (half_surface_length * half_surface_length));  // thesis eq. 3.34
}

double circular_fit_omega(double radius, double depth, double gravity) {
  check_positive(radius, "the radius");
  check_positive(depth, "the depth");
  constexpr double kappa = 0.2872;  // fitted to thesis Table 3.10 (see the header)
  const double x = depth / (2.0 * radius);
  return std::sqrt(gravity / radius * (1.0 + kappa * (std::pow(x, 3.129) + 1.542 * x)));
}

double thesis_closed_form_omega(const TankSpec& spec, double depth, double gravity) {
  if (spec.shape == "rectangle") return rectangular_sloshing_omega(spec.length, depth, gravity);  // eq. 4.29
  if (spec.shape == "sloped" || spec.shape == "triangle" || spec.shape == "trapezoid") {
    const double slope = std::tan(spec.angle * kPi / 180.0);
    const double wall_foot = 0.5 * (spec.length - spec.bottom_width) * slope;  // where the slope meets x = 0
    if (depth > wall_foot * (1.0 + 1e-9))
      fail_depth("the fluid (" + number(depth) + " m) reaches the vertical walls above the slopes (at " +
                 number(wall_foot) + " m)");
    return trapezoid_long_wave_omega(spec.bottom_width, spec.angle, depth, gravity);
  }
  if (spec.shape == "parabolic") {
    const double wall_foot = spec.coefficient * 0.25 * spec.length * spec.length;
    if (depth > wall_foot * (1.0 + 1e-9))
      fail_depth("the fluid (" + number(depth) + " m) reaches the vertical walls above the parabola (at " +
                 number(wall_foot) + " m)");
    check_positive(spec.coefficient, "the parabola coefficient");
    return parabolic_long_wave_omega(std::sqrt(depth / spec.coefficient), depth, gravity);
  }
  if (spec.shape == "circular") {
    const double radius = 0.5 * spec.length;
    if (depth > radius * (1.0 + 1e-9))
      fail_depth("the fluid (" + number(depth) + " m) is above the centre of the circle (R = " + number(radius) +
                 " m)");
    return circular_fit_omega(radius, depth, gravity);
  }
  throw InputError("", "tank.shape", "no closed-form sloshing frequency for shape '" + spec.shape +
                                         "': use the modal solver (linear/modal.hpp)");
}

}  // namespace sloshsph
