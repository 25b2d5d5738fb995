// The linear modal solution from rest (linear/forced_response) against closed forms: the
// modal forcing and moment of a rectangle, a single mode driven harmonically from rest, the
// static tilt of a steady acceleration, the decay of a damped mode, and the boundary-layer
// damping's shallow- and deep-water limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sloshsph/linear/forced_response.hpp"
#include "sloshsph/linear/modal.hpp"
#include "sloshsph/linear/rectangular.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;

TankGeometry rectangle(double length, double height) {
  TankSpec s;
  s.shape = "rectangle";
  s.length = length;
  s.height = height;
  return make_tank(s, "test");
}

TEST(ForcedResponse, ModalForcingAndMomentOfARectangleMatchTheClosedForm) {
  // Rectangle, x from the left wall: surface_eta = cos(n pi x / L); forcing -4 tanh(k h)/(n pi)
  // and moment int x cos(k x) dx = -2 L^2 / (n pi)^2 for odd n, both 0 for even n.
  const double length = 0.5, depth = 0.25;
  // Resolution 48: the default 16 gives mode 5 (six quadratic elements a wavelength) 1% error.
  ModalOptions fine;
  fine.resolution = 48;
  const auto modes = sloshing_modes(rectangle(length, 0.4), depth, kG, 5, fine);
  for (int n = 1; n <= 5; ++n) {
    const SloshingMode& m = modes[n - 1];
    const double k = n * kPi / length;
    const double forcing = n % 2 ? -4.0 * std::tanh(k * depth) / (n * kPi) : 0.0;
    const double moment = n % 2 ? -2.0 * length * length / (n * n * kPi * kPi) : 0.0;
    EXPECT_NEAR(m.horizontal_forcing, forcing, 2e-3 * std::abs(forcing) + 1e-4) << "mode " << n;
    EXPECT_NEAR(m.surface_moment, moment, 2e-3 * std::abs(moment) + 1e-6) << "mode " << n;
  }
  // forcing x moment = Gamma^2 / lambda = m_n / rho: the effective mass of modal.hpp.
  for (const SloshingMode& m : modes)
    EXPECT_NEAR(m.horizontal_forcing * m.surface_moment / (length * depth), m.effective_mass_fraction, 1e-9);
}

// One undamped mode driven by a(t) = -X w^2 sin(w t) from rest: q'' + w1^2 q = f X w^2 sin(w t),
// q = f X w^2 / (w1^2 - w^2) (sin(w t) - (w / w1) sin(w1 t)).
TEST(ForcedResponse, OneModeFromRestMatchesTheExactSolution) {
  SloshingMode mode;
  mode.omega = 7.5;
  mode.horizontal_forcing = -1.2;
  mode.surface_x = {0.0, 1.0};
  mode.surface_eta = {1.0, 1.0};
  const double x0 = 0.002, w = 0.9 * mode.omega;
  LinearResponseInput in;
  in.modes = {mode};
  in.base_acceleration = [&](double t) { return -x0 * w * w * std::sin(w * t); };
  in.gauge_x = {0.0};
  in.end_time = 10.0;
  in.sample_interval = 0.01;
  const LinearResponse r = linear_response_from_rest(in);
  const double w1 = mode.omega, f = mode.horizontal_forcing;
  double worst = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    const double t = r.time[k];
    const double exact = f * x0 * w * w / (w1 * w1 - w * w) * (std::sin(w * t) - w / w1 * std::sin(w1 * t));
    worst = std::max(worst, std::abs(r.elevation[0][k] - exact));
    largest = std::max(largest, std::abs(exact));
  }
  // RK4 at 1/200 of the period: the phase error over 12 periods is ~1e-7 of the amplitude.
  EXPECT_LT(worst, 1e-6 * largest) << "largest " << largest;
}

TEST(ForcedResponse, SteadyAccelerationTiltsTheSurfaceStatically) {
  // A constant a0 from t = 0 with 20% modal damping settles to the static tilt
  // eta = -a0 (x - L/2) / g, and the walls then carry the liquid's mass: F_w = rho A a0, F_sw = 0.
  const double length = 0.5, depth = 0.25, a0 = 0.3;
  LinearResponseInput in;
  in.modes = sloshing_modes(rectangle(length, 0.4), depth, kG, 40);
  in.damping.assign(in.modes.size(), 0.2);
  in.base_acceleration = [&](double) { return a0; };
  in.gauge_x = {0.1, 0.4};
  in.density = 1000.0;
  in.still_water_area = length * depth;
  in.end_time = 10.0;
  in.sample_interval = 0.01;
  const LinearResponse r = linear_response_from_rest(in);
  for (std::size_t g = 0; g < 2; ++g) {
    const double exact = -a0 * (in.gauge_x[g] - length / 2) / kG;
    // The cosine series of a linear function converges as 1/n^2: 40 modes (20 odd) leave ~1e-3.
    EXPECT_NEAR(r.elevation[g].back(), exact, 2e-3 * std::abs(exact)) << "gauge " << g;
  }
  EXPECT_NEAR(r.wall_force.back(), 1000.0 * length * depth * a0, 1e-6 * 1000.0 * length * depth * a0);
  EXPECT_NEAR(r.sloshing_force.back(), 0.0, 1e-6);
}

TEST(ForcedResponse, ADampedModeDecaysAtItsRatio) {
  // A short push, then free decay: successive crests fall by exp(-2 pi zeta / sqrt(1 - zeta^2)).
  SloshingMode mode;
  mode.omega = 2.0 * kPi;
  mode.horizontal_forcing = 1.0;
  mode.surface_x = {0.0};
  mode.surface_eta = {1.0};
  const double zeta = 0.01;
  LinearResponseInput in;
  in.modes = {mode};
  in.damping = {zeta};
  in.base_acceleration = [](double t) { return t < 0.5 ? -std::sin(2.0 * kPi * t) : 0.0; };
  in.gauge_x = {0.0};
  in.end_time = 12.0;
  in.sample_interval = 0.001;
  const LinearResponse r = linear_response_from_rest(in);
  auto crest = [&](double from) {
    double c = -1e300;
    for (std::size_t k = 0; k < r.time.size(); ++k)
      if (r.time[k] >= from && r.time[k] < from + 1.0) c = std::max(c, r.elevation[0][k]);
    return c;
  };
  const double ratio = crest(11.0) / crest(1.0);  // ten periods
  const double exact = std::exp(-10.0 * 2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta));
  EXPECT_NEAR(ratio, exact, 1e-3 * exact);
}

TEST(ForcedResponse, BoundaryLayerDampingHasTheKnownLimits) {
  const double nu = 1e-6;
  // Shallow water (k h = 0.0314): the TLD literature's sqrt(nu / (2 omega)) / (2 h) for a 2D clean
  // tank (Sun et al. 1992 with b -> infinity, S = 0); the O((kh)^2) terms and the bulk part differ.
  const double length = 10.0, shallow = 0.1;
  const double w = rectangular_sloshing_omega(length, shallow, kG);
  testing::check_relative("zeta_1 of the Stokes layers, L = 10 m, h = 0.1 m",
                          rectangular_boundary_layer_damping(length, shallow, kG, nu),
                          std::sqrt(nu / (2.0 * w)) / (2.0 * shallow), 0.01,
                          "shallow-water limit sqrt(nu / (2 omega)) / (2 h) (Keulegan 1959, Sun et al. 1992)");
  // Deep water (k h = 31): only the side walls count, sqrt(nu / (2 omega)) / L, plus the bulk 2 nu k^2 / omega.
  const double deep_length = 0.1, deep = 1.0;
  const double wd = rectangular_sloshing_omega(deep_length, deep, kG), k = kPi / deep_length;
  EXPECT_NEAR(rectangular_boundary_layer_damping(deep_length, deep, kG, nu),
              std::sqrt(nu / (2.0 * wd)) / deep_length + 2.0 * nu * k * k / wd, 1e-9);
  // The laboratory tank of cases/linear_sloshing.toml (0.5 m, 0.25 m, water): about 0.05% of critical.
  EXPECT_NEAR(rectangular_boundary_layer_damping(0.5, 0.25, kG, nu), 5.26e-4, 0.01e-4);
}

}  // namespace
}  // namespace sloshsph
