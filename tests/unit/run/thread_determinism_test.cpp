// Issue 8: results for 1 and 2 threads identical. The whole ISPH step (turbulence, Ergun
// screens, the implicit pressure solve, wall contact) on the Tait tank with two screens, run
// from the same start on 1 and on 2 OpenMP threads. Reference: gather loops (each particle
// writes only itself) and sums over fixed blocks in a fixed order (the PPE's Krylov solver
// included): bitwise identical particles and samples. Tolerance: none.
#include <gtest/gtest.h>
#include <omp.h>


#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"
#include "same_bits.hpp"

namespace sloshsph {
namespace {

using test::same_bits;

struct RunEnd {
  Particles particles;
  std::vector<double> sample;
  int solver_iterations = 0;
};

// 200 steps at dp = 14 mm (552 fluid particles: several blocks of the solver's sums).
RunEnd run_on_threads(int threads) {
  const CaseSpec spec = resolve_case(read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/tait2005_screens.toml",
                                                    {"particles.dp=0.014", "time.dt=0.0014", "output.snapshot_interval=0"}));
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Simulation sim(spec);
  int iterations = 0;
  for (int n = 0; n < 200; ++n) {
    sim.step();
    iterations += sim.scheme().diagnostics().solver_iterations;
  }
  omp_set_num_threads(before);
  return {sim.particles(), sim.sample(), iterations};
}

TEST(ThreadDeterminism, IsphWithScreensTwoThreadsMatchOneThreadBitwise) {
  const RunEnd one = run_on_threads(1), two = run_on_threads(2);
  EXPECT_GT(one.solver_iterations, 200);  // the Krylov solver did work in every step
  EXPECT_EQ(one.solver_iterations, two.solver_iterations);
  EXPECT_TRUE(same_bits(one.particles.position, two.particles.position));
  EXPECT_TRUE(same_bits(one.particles.velocity, two.particles.velocity));
  EXPECT_TRUE(same_bits(one.particles.pressure, two.particles.pressure));
  EXPECT_EQ(one.sample, two.sample);
}

}  // namespace
}  // namespace sloshsph
