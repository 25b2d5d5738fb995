// Tanks at rest: hydrostatic pressure, no leaks, no spurious flow (thesis 2.6.1).
#include <cmath>
#include <string>
#include <vector>

#include "run_support.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_absolute;
using testing::check_at_most;
using testing::check_relative;
using testing::report;
using testing::run_case_in_memory;

// cases/hydrostatic.toml at dp = 10 mm for 5 s (issue: validation in CI).
// Reference: p = rho g (H - y), H = 0.25 m the fill depth.
// Tolerances: every probe within 2% of rho g H of its hydrostatic value at the end of the run,
// no particle lost, maximum fluid speed below 1% of sqrt(g H).
TEST(Validation, HydrostaticTank) {
  const double rho = 1000.0, g = 9.81, H = 0.25;
  double wall_particles = 0;
  const auto r = run_case_in_memory("hydrostatic.toml", {"particles.dp=0.01", "time.end=5", "output.sample_interval=0.05"},
                                    [&](const Simulation& s) { wall_particles = double(s.particles().n_wall()); });
  const double scale = rho * g * H;
  double worst = 0.0;
  std::vector<testing::ProfilePoint> profile;
  for (const auto& [name, values] : r.series) {
    if (name.rfind("p:y", 0) != 0) continue;
    const double y = std::stod(name.substr(3));
    const double expected = rho * g * (H - y);
    const double error = std::abs(values.back() - expected) / scale;
    worst = std::max(worst, error);
    // |p - rho g (H - y)| / (rho g H) < 2%, i.e. within 0.02 rho g H of the hydrostatic value.
    check_absolute("pressure at y = " + name.substr(3) + " m, at 5 s", values.back(), expected, 0.02 * scale,
                   "hydrostatics rho g (H - y), H = 0.25 m; tolerance 2% of rho g H", "Pa");
    profile.push_back({y, values.back(), expected});
  }
  report("hydrostatic_worst_probe_error_fraction_of_rho_g_H", worst);
  testing::record_profile_curve("Tank at rest, pressure probes at 5 s (dp = 10 mm)", profile,
                                "hydrostatic rho g (H - y)");
  check_at_most("particles leaked from the tank", static_cast<double>(r.leaked), 0.0, "none may leave");
  const double limit = 0.01 * std::sqrt(g * H);
  report("hydrostatic_max_speed_m_s", r.max_speed_end);
  report("hydrostatic_max_speed_fraction_of_sqrt_gH", r.max_speed_end / std::sqrt(g * H));
  check_at_most("maximum fluid speed at 5 s", r.max_speed_end, limit, "1% of sqrt(g H), H = 0.25 m", "m/s");
  // The walls carry the weight: the vertical wall force equals m g (within 0.5%).
  const double weight = r["fluid_mass"].back() * g;
  report("hydrostatic_vertical_wall_force_over_weight", r["F_wy"].back() / weight);
  check_relative("vertical force of the fluid on the walls, at 5 s", r["F_wy"].back(), weight, 0.005,
                 "the fluid's weight m g", "N/m");
  report("hydrostatic_wall_seconds", r.wall_seconds);
}

}  // namespace
}  // namespace sloshsph
