// Screens in a tuned liquid damper: thesis 2.6.3 / Tait et al. (2005), the tank of
// cases/tld_no_screens.toml with and without the two Ergun screens of cases/tait2005_screens.toml.
#include <cmath>
#include <numbers>

#include "run_support.hpp"
#include "sloshsph/analysis/filter.hpp"
#include "sloshsph/analysis/steady_state.hpp"
#include "sloshsph/linear/rectangular.hpp"

namespace sloshsph {
namespace {

using testing::report;
using testing::run_case_in_memory;

struct TankResponse {
  double eta_max = 0.0;  // average of the last cycles' maxima of the gauge at x/L = 0.95, m
  double eta_min = 0.0;
  double energy = 0.0;   // energy taken from the base per cycle, eq. 4.28 from W_base, J/m
};

// Both runs at X0/L = 0.005, beta = 1.0 (of the exact linear frequency), 40 s (21.8 cycles),
// averaged over the last 13 cycles after the 5 Hz zero-phase filter (thesis 2.6.3.1). To fit
// CI: dp = 10 mm (12 particles across the depth; the thesis uses 5-7 mm) and dt = 1 ms (a
// quarter of the fixed-step bound 0.4 dp / sqrt(g h) = 3.7 ms). Why so many cycles: without
// screens the resonant response beats (measured: the per-cycle energy swings between 0.14 and
// 0.73 J/m and the crest between 35 and 56 mm over cycles 5-21, not settled at 40 s; the
// thesis runs 120 s), while with screens it settles by cycle 10 (0.51-0.60 J/m). A window
// shorter than a beat compares a phase of the beat, not the damping: at 16 s (last 3 cycles)
// the energy ordering came out reversed (0.60 with screens vs 0.66 without).
TankResponse respond(const std::string& case_name) {
  const auto r = run_case_in_memory(case_name, {"particles.dp=0.01", "time.dt=0.001", "time.end=40", "excitation.amplitude=0.00483",
                                                "excitation.beta=1.0", "output.snapshot_interval=0"});
  EXPECT_EQ(r.leaked, 0u) << case_name;
  const double omega = rectangular_sloshing_omega(0.966, 0.119, 9.81);
  const double period = 2.0 * std::numbers::pi / omega, dt = r["time"][1] - r["time"][0];
  const auto eta = steady_state_amplitude(r["time"], lowpass_zero_phase(r["eta:right"], dt), period, 13);
  const auto e = energy_per_cycle_from_work(r["time"], r["W_base"], period, 13);
  std::printf("  %s: %zu steps in %.0f s\n", case_name.c_str(), r.steps, r.wall_seconds);
  return {eta.avg_max, eta.avg_min, e.energy};
}

// Reference: Tait et al. (2005) and thesis Fig. 2.12-2.14: screens damp the sloshing, so at
// resonance the wave is lower with screens and the liquid takes more energy per cycle from the
// base (the screens dissipate it). The bar is the ordering, as the issue states it; no
// tolerance on the size of the difference. The energy with screens must be positive.
TEST(Validation, TaitScreensDampTheResonance) {
  const TankResponse none = respond("tld_no_screens.toml");
  const TankResponse screens = respond("tait2005_screens.toml");
  report("tait_no_screens_eta_max_m", none.eta_max);
  report("tait_no_screens_eta_min_m", none.eta_min);
  report("tait_no_screens_energy_per_cycle_J_per_m", none.energy);
  report("tait_screens_eta_max_m", screens.eta_max);
  report("tait_screens_eta_min_m", screens.eta_min);
  report("tait_screens_energy_per_cycle_J_per_m", screens.energy);
  EXPECT_LT(screens.eta_max, none.eta_max);
  EXPECT_GT(screens.energy, 0.0);
  EXPECT_GT(screens.energy, none.energy);
}

}  // namespace
}  // namespace sloshsph
