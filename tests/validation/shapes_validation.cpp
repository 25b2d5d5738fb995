// Tanks of any section (thesis chapter 3): a circular tank at rest, and the free-sloshing
// frequency of the sloped, parabolic and circular tanks of Table 3.4 against exact linear
// theory (the modal solver).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "run_support.hpp"
#include "sloshsph/analysis/filter.hpp"
#include "sloshsph/analysis/spectrum.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/linear/modal.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_absolute;
using testing::check_at_most;
using testing::check_relative;
using testing::report;
using testing::run_case_in_memory;

// The still level (depth above the lowest point) at which the section holds `area`: the
// depth the SPH fluid really has. The lattice fill keeps particle centres >= dp/2 from the
// wall, so on walls off the lattice the particle area n dp^2 is short of the section area
// (about 0.5 dp times the wetted wall length) and the fluid settles below the requested depth.
double mass_equivalent_depth(const TankGeometry& tank, double area, double requested) {
  double lo = 0.0, hi = requested;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (section_area(tank, mid) < area ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// cases/circular_rest.toml (thesis 3.4.4.1: R = 0.5 m, depth 0.241 m) for 20 s at dp = 10 mm
// and dt = 1 ms (the thesis: dp = 5 mm, dt = 0.5 ms; the CI budget allows the coarser pair,
// the same dt/dp; tests/validation/shapes_long.cpp runs the thesis's resolution for 200 s).
// Reference: hydrostatic pressure rho g (H_eff - y), H_eff the still level that holds the
// fluid's area (see mass_equivalent_depth; at dp = 10 mm it is 8 mm below the requested
// 0.241 m, so the requested depth is not the level this fluid can stand at).
// Tolerances: no particle leaves the tank; every probe within 2% of rho g H_eff of its
// hydrostatic value at 20 s; maximum speed at 20 s below 1% of sqrt(g H_eff).
TEST(Validation, CircularTankAtRest) {
  const double rho = 1000.0, g = 9.81, H = 0.241;
  double level = 0.0;
  const auto r = run_case_in_memory(
      "circular_rest.toml",
      {"particles.dp=0.01", "time.dt=0.001", "time.end=20", "output.sample_interval=0.05", "output.snapshot_interval=0"},
      [&](const Simulation& s) {
        const double area = static_cast<double>(s.particles().n_fluid) * s.particles().volume;
        level = mass_equivalent_depth(*s.scene().tank, area, H);
      });
  check_at_most("particles leaked from the tank in 20 s", static_cast<double>(r.leaked), 0.0, "none may leave");
  report("circular_rest_leaked", double(r.leaked));
  report("circular_rest_mass_equivalent_depth_m", level);
  const double scale = rho * g * level;
  double worst = 0.0, worst_nominal = 0.0;
  std::vector<testing::ProfilePoint> profile;
  for (const auto& [name, values] : r.series) {
    if (name.rfind("p:", 0) != 0) continue;
    const double y = std::stod(name.substr(name.rfind('y') + 1));
    const double error = (values.back() - rho * g * (level - y)) / scale;
    worst = std::max(worst, std::abs(error));
    worst_nominal = std::max(worst_nominal, std::abs(values.back() - rho * g * (H - y)) / (rho * g * H));
    report("circular_rest_error_" + name.substr(2), error);
    // |error| < 2%, i.e. within 0.02 rho g H_eff of the hydrostatic value.
    check_absolute("pressure at probe " + name.substr(2) + ", at 20 s", values.back(), rho * g * (level - y), 0.02 * scale,
                   "hydrostatics rho g (H_eff - y), H_eff the mass-equivalent still level; tolerance 2% of rho g H_eff",
                   "Pa");
    profile.push_back({y, values.back(), rho * g * (level - y)});
  }
  testing::record_profile_curve("Circular tank at rest, pressure probes at 20 s (dp = 10 mm)", profile,
                                "hydrostatic rho g (H_eff - y)");
  report("circular_rest_worst_probe_error_fraction_of_rho_g_Heff", worst);
  // For the record: against the requested depth the error is the level deficit (not tested).
  report("circular_rest_worst_probe_error_vs_requested_depth", worst_nominal);
  report("circular_rest_max_speed_m_s", r.max_speed_end);
  check_at_most("maximum fluid speed at 20 s", r.max_speed_end, 0.01 * std::sqrt(g * level), "1% of sqrt(g H_eff)", "m/s");
  report("circular_rest_wall_seconds", r.wall_seconds);
}

struct FreeSloshing {
  const char* label;
  const char* file;
  double dp;          // m
  double end;         // s
};

// Free sloshing of a Table 3.4 tank: no screens, two periods of harmonic excitation at the
// modal omega1 with X0 = 2 mm (the Table 3.4 amplitude), then the base stops (excitation.stop)
// and the fluid sloshes freely. The frequency is that of the antisymmetric first mode in
// eta(left) - eta(right) (gauges 0.1 L_tank (sloped: 0.05 m) either side of the centre; the
// difference cancels the symmetric modes and the slow level drift), low-passed zero-phase at
// 1.5 f1 as the thesis low-passes its SPH series (3.4.4.2; a zero-phase filter does not move
// the zero crossings), and measured by the mean up-crossing period after the excitation.
// References: omega1 of the modal solver (exact linear theory) at the requested depth (the
// tested one) and at the mass-equivalent depth (reported). Tolerance: 3% (the issue's).
void check_free_sloshing(const FreeSloshing& c) {
  const std::vector<std::string> base = {"particles.dp=" + std::to_string(c.dp), "time.end=" + std::to_string(c.end),
                                         "screens=[]", "excitation.beta_reference=\"modal\"", "excitation.amplitude=0.002",
                                         "output.sample_interval=0.01", "output.snapshot_interval=0"};
  const CaseSpec spec = resolve_case(read_case_file(testing::case_path(c.file), base));
  const double omega1 = first_sloshing_omega(spec);
  const double stop = 2.0 * 2.0 * std::numbers::pi / omega1;
  std::vector<std::string> overrides = base;
  overrides.push_back("excitation.stop=" + std::to_string(stop));
  double omega_effective = 0.0, depth_effective = 0.0;
  const auto r = run_case_in_memory(c.file, overrides, [&](const Simulation& s) {
    const double area = static_cast<double>(s.particles().n_fluid) * s.particles().volume;
    depth_effective = mass_equivalent_depth(*s.scene().tank, area, spec.fill.depth);
    omega_effective = first_sloshing_omega(*s.scene().tank, depth_effective, spec.fluid.gravity);
  });
  check_at_most(std::string("particles leaked from the tank, ") + c.label, static_cast<double>(r.leaked), 0.0,
                "none may leave");

  const auto& time = r["time"];
  std::vector<double> difference(time.size());
  for (std::size_t k = 0; k < time.size(); ++k) difference[k] = r["eta:left"][k] - r["eta:right"][k];
  const double dt = time[1] - time[0];
  const std::vector<double> smooth = lowpass_zero_phase(difference, dt, 1.5 * omega1 / (2.0 * std::numbers::pi));
  std::vector<double> t, x;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] >= stop + 0.2) {
      t.push_back(time[k]);
      x.push_back(smooth[k]);
    }
  const double period = zero_crossing_period(t, x);
  ASSERT_GT(period, 0.0) << c.label << ": fewer than two up-crossings after the excitation";
  const double omega = 2.0 * std::numbers::pi / period;
  const std::string key = std::string("free_sloshing_") + c.label;
  report(key + "_omega", omega);
  report(key + "_modal_omega", omega1);
  report(key + "_error", omega / omega1 - 1.0);
  report(key + "_mass_equivalent_depth_m", depth_effective);
  report(key + "_modal_omega_at_that_depth", omega_effective);
  report(key + "_error_at_that_depth", omega / omega_effective - 1.0);
  report(key + "_wall_seconds", r.wall_seconds);
  check_relative(std::string("free-sloshing angular frequency, mean up-crossing period of eta(left) - eta(right), ") +
                     c.label,
                 omega, omega1, 0.03,
                 "omega1 of the modal solver (exact linear theory) at the requested depth, thesis Table 3.4 tank", "rad/s");
  testing::record_curve({"free_sloshing",
                         std::string("Free sloshing, ") + c.label + " tank: eta(left) - eta(right), low-passed at 1.5 f1",
                         "time (s)", "eta difference (m)", time, smooth, "", {}, {}});
}

// Sloped: 45-degree V, h = 0.1 m (Table 3.4), modal omega1 = sqrt(g/h) = 9.905 rad/s; 5 s.
// dp = 5 mm: at dp = 10 mm the fluid is 10% short of the section area (depth 0.0949 m),
// which alone raises omega1 by 2.7% (measured, before the case had time.settle: +2.8% against
// the requested depth, +0.1% against the mass-equivalent one); at 5 mm, +1.8% and +0.5%.
TEST(Validation, FreeSloshingSlopedTank) { check_free_sloshing({"sloped", "shapes_sloped.toml", 0.005, 5.0}); }

// Parabolic: L = 1.4 m, h = 0.14 m (Table 3.4), modal omega1 = 4.208 rad/s; dp = 10 mm, 10 s.
TEST(Validation, FreeSloshingParabolicTank) { check_free_sloshing({"parabolic", "shapes_parabolic.toml", 0.01, 10.0}); }

// Circular: R = 0.5 m, h = 0.1 m (Table 3.4), modal omega1 = 4.5255 rad/s; dp = 10 mm, 9 s.
TEST(Validation, FreeSloshingCircularTank) { check_free_sloshing({"circular", "shapes_circular.toml", 0.01, 9.0}); }

}  // namespace
}  // namespace sloshsph
