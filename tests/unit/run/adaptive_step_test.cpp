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

// Liu & Lin's tank at resonance (X0 = 5 mm, omega about 6.9 rad/s: the base moves at up to 0.035
// m/s from the start), dp = 20 mm, with the smallest CFL factor the reader allows (0.001), so that
// the flow's bound cfl dp / u_max (about 0.6 ms at 0.035 m/s) falls below a 1 ms floor at once.
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

// Reference: the definition dt = min(time.dt, max(bound, time.dt_min)). Without a floor the flow
// takes the step below 1 ms (so the floor below is not idle); with it no step is shorter than the
// floor (to the clock's rounding, 1e-12 relative), the steps whose bound fell below it take it, and
// their count and largest u_max dt / dp (above the CFL factor, as a step at the floor must be) are
// reported.
TEST(AdaptiveStep, FloorHoldsTheStepWhereTheFlowWouldTakeItBelow) {
  BasicSimulation<2> free_step(floor_case({}));
  const std::vector<double> unfloored = step_sizes(free_step, 60);
  EXPECT_LT(*std::min_element(unfloored.begin(), unfloored.end()), 0.9e-3);
  EXPECT_EQ(free_step.floor_steps(), 0u);

  constexpr double kFloor = 1e-3;
  BasicSimulation<2> sim(floor_case({"time.dt_min=0.001"}));
  const std::vector<double> floored = step_sizes(sim, 60);
  std::size_t at_floor = 0;
  for (const double dt : floored) {
    EXPECT_GE(dt, kFloor * (1.0 - 1e-12));
    EXPECT_LE(dt, 0.002 * (1.0 + 1e-12));
    at_floor += std::abs(dt - kFloor) <= 1e-12 * kFloor ? 1 : 0;
  }
  EXPECT_GT(sim.floor_steps(), 0u);
  EXPECT_EQ(sim.floor_steps(), at_floor);
  EXPECT_GT(sim.largest_floor_cfl(), 0.001);
}

}  // namespace
}  // namespace sloshsph
