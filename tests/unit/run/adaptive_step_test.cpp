// The adaptive time step's floor, time.dt_min (docs/case-format.md, [time]).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph {
namespace {

// Liu & Lin's tank at resonance (X0 = 5 mm), dp = 20 mm, with the smallest CFL factor the reader
// allows (0.001): as the flow gathers speed the bound cfl dp / u_max falls, from 0.48 ms at the first
// step to 0.17 ms at the sixtieth, past a 0.3 ms floor at the seventh.
CaseSpec floor_case(const std::vector<std::string>& extra) {
  std::vector<std::string> sets = {"particles.dp=0.02", "time.end=10",        "time.settle=0.05",
                                   "output.snapshot_interval=0", "time.adaptive=true", "time.cfl=0.001",
                                   "time.dt=0.002"};
  sets.insert(sets.end(), extra.begin(), extra.end());
  return resolve_case(read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/liu_lin_2008.toml", sets));
}

// The step of each of `steps` steps, from the clock.
std::vector<double> step_sizes(BasicSimulation<2>& sim, int steps) {
  std::vector<double> dt;
  for (int n = 0; n < steps; ++n) {
    const double before = sim.time();
    sim.step();
    dt.push_back(sim.time() - before);
  }
  return dt;
}

// Reference: the definition dt = min(time.dt, max(bound, time.dt_min)). Until the flow first takes
// the unfloored step below the floor, the floored run takes the very same steps (the same bits:
// the floor is idle); from then on no step is shorter than the floor (to the clock's rounding, 1e-12
// relative) nor longer than the ceiling, that first step is the floor itself, and the steps at the
// floor are counted, with a largest u_max dt / dp above the CFL factor (the speed bound fell).
TEST(AdaptiveStep, FloorHoldsTheStepWhereTheFlowWouldTakeItBelow) {
  constexpr double kFloor = 3e-4, kCeiling = 2e-3, kRounding = 1e-12;
  BasicSimulation<2> free_step(floor_case({}));
  const std::vector<double> unfloored = step_sizes(free_step, 60);
  EXPECT_EQ(free_step.floor_steps(), 0u);
  const auto first_below = static_cast<std::size_t>(
      std::find_if(unfloored.begin(), unfloored.end(), [&](double dt) { return dt < kFloor * (1.0 - kRounding); }) -
      unfloored.begin());
  ASSERT_GT(first_below, 0u) << "the first step is already below the floor: the test would not see the floor idle";
  ASSERT_LT(first_below, unfloored.size()) << "the flow never takes the step below the floor";

  BasicSimulation<2> sim(floor_case({"time.dt_min=0.0003"}));
  const std::vector<double> floored = step_sizes(sim, 60);
  for (std::size_t n = 0; n < first_below; ++n) EXPECT_EQ(floored[n], unfloored[n]) << "step " << n;
  EXPECT_NEAR(floored[first_below], kFloor, kRounding * kFloor);
  std::size_t at_floor = 0;
  for (const double dt : floored) {
    EXPECT_GE(dt, kFloor * (1.0 - kRounding));
    EXPECT_LE(dt, kCeiling * (1.0 + kRounding));
    at_floor += std::abs(dt - kFloor) <= kRounding * kFloor ? 1 : 0;
  }
  EXPECT_GT(sim.floor_steps(), 0u);
  EXPECT_EQ(sim.floor_steps(), at_floor);
  EXPECT_GT(sim.largest_floor_cfl(), 0.001);
}

}  // namespace
}  // namespace sloshsph
