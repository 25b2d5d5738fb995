// Long runs at rest (label `long`; not in CI).
#include <cmath>
#include <string>
#include <vector>

#include "run_support.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_absolute;
using testing::check_at_most;
using testing::report;
using testing::run_case_in_memory;

// cases/hydrostatic.toml as the thesis runs it: dp = 5 mm, 15 s (thesis 2.6.1, Table 2.1 case 1).
// Reference p = rho g (H - y); tolerance 1% of rho g H for every probe at 15 s; no leaks.
TEST(Long, HydrostaticTankThesisResolution) {
  const double rho = 1000.0, g = 9.81, H = 0.25;
  const auto r = run_case_in_memory("hydrostatic.toml", {});
  double worst = 0.0;
  std::vector<testing::ProfilePoint> profile;
  for (const auto& [name, values] : r.series) {
    if (name.rfind("p:y", 0) != 0) continue;
    const double y = std::stod(name.substr(3));
    const double error = std::abs(values.back() - rho * g * (H - y)) / (rho * g * H);
    worst = std::max(worst, error);
    // error < 1%, i.e. within 0.01 rho g H of the hydrostatic value.
    check_absolute("pressure at y = " + name.substr(3) + " m, at 15 s, dp = 5 mm", values.back(), rho * g * (H - y),
                   0.01 * (rho * g * H), "hydrostatics rho g (H - y), H = 0.25 m (thesis 2.6.1); tolerance 1% of rho g H",
                   "Pa");
    profile.push_back({y, values.back(), rho * g * (H - y)});
  }
  report("hydrostatic_5mm_worst_probe_error_fraction", worst);
  report("hydrostatic_5mm_max_speed_m_s", r.max_speed_end);
  testing::record_profile_curve("Tank at rest, pressure probes at 15 s (dp = 5 mm)", profile,
                                "hydrostatic rho g (H - y)");
  check_at_most("particles leaked from the tank", static_cast<double>(r.leaked), 0.0, "none may leave");
}

}  // namespace
}  // namespace sloshsph
