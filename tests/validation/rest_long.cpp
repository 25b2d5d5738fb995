// Long runs at rest (label `long`; not in CI).
#include <cmath>

#include "run_support.hpp"

namespace sloshsph {
namespace {

using testing::report;
using testing::run_case_in_memory;

// cases/hydrostatic.toml as the thesis runs it: dp = 5 mm, 15 s (thesis 2.6.1, Table 2.1 case 1).
// Reference p = rho g (H - y); tolerance 1% of rho g H for every probe at 15 s; no leaks.
TEST(Long, HydrostaticTankThesisResolution) {
  const double rho = 1000.0, g = 9.81, H = 0.25;
  const auto r = run_case_in_memory("hydrostatic.toml", {});
  double worst = 0.0;
  for (const auto& [name, values] : r.series) {
    if (name.rfind("p:y", 0) != 0) continue;
    const double y = std::stod(name.substr(3));
    const double error = std::abs(values.back() - rho * g * (H - y)) / (rho * g * H);
    worst = std::max(worst, error);
    EXPECT_LT(error, 0.01) << name << ": " << values.back();
  }
  report("hydrostatic_5mm_worst_probe_error_fraction", worst);
  report("hydrostatic_5mm_max_speed_m_s", r.max_speed_end);
  EXPECT_EQ(r.leaked, 0u);
}

}  // namespace
}  // namespace sloshsph
