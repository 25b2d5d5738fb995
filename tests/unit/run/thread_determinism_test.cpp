// Issue 8: results for 1 and 2 threads identical. The whole ISPH step (turbulence, Ergun
// screens, the implicit pressure solve, wall contact) on the Tait tank with two screens, run
// from the same start on 1 and on 2 OpenMP threads. Reference: gather loops (each particle
// writes only itself) and sums over fixed blocks in a fixed order (the PPE's Krylov solver
// included): bitwise identical particles and samples. Tolerance: none.
#include <gtest/gtest.h>
#include <omp.h>

#include <string>
#include <utility>
#include <vector>

#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"
#include "same_bits.hpp"

namespace sloshsph {
namespace {

using test::same_bits;

template <int D = 2>
struct RunEnd {
  BasicParticles<D> particles;
  std::vector<double> sample;
  int solver_iterations = 0;
};

// `steps` steps of a case of cases/ with `overrides` on `threads` OpenMP threads.
template <int D = 2>
RunEnd<D> run_on_threads(int threads, const std::string& case_file, const std::vector<std::string>& overrides,
                         int steps) {
  const CaseSpec spec = resolve_case(read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/" + case_file, overrides));
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  BasicSimulation<D> sim(spec);
  int iterations = 0;
  for (int n = 0; n < steps; ++n) {
    sim.step();
    iterations += sim.scheme().diagnostics().solver_iterations;
  }
  omp_set_num_threads(before);
  return {sim.particles(), sim.sample(), iterations};
}

// 200 steps at dp = 14 mm (552 fluid particles: several blocks of the solver's sums).
RunEnd<> tait_with_screens(int threads) {
  return run_on_threads(threads, "tait2005_screens.toml",
                        {"particles.dp=0.014", "time.dt=0.0014", "output.snapshot_interval=0"}, 200);
}

TEST(ThreadDeterminism, IsphWithScreensTwoThreadsMatchOneThreadBitwise) {
  const RunEnd<> one = tait_with_screens(1), two = tait_with_screens(2);
  EXPECT_GT(one.solver_iterations, 200);  // the Krylov solver did work in every step
  EXPECT_EQ(one.solver_iterations, two.solver_iterations);
  EXPECT_TRUE(same_bits(one.particles.position, two.particles.position));
  EXPECT_TRUE(same_bits(one.particles.velocity, two.particles.velocity));
  EXPECT_TRUE(same_bits(one.particles.pressure, two.particles.pressure));
  EXPECT_EQ(one.sample, two.sample);
}

// Particle shifting (issue 30) in both schemes: every shift is worked out before any particle moves
// and the count of cut shifts is an integer reduction, so the dam break (the flow that shifts most,
// dp = 40 mm: 1,250 fluid particles) is the same bits on 1 and 2 threads.
TEST(ThreadDeterminism, ShiftingInBothSchemesTwoThreadsMatchOneThreadBitwise) {
  for (const auto& [file, model] : {std::pair<std::string, std::string>{"dambreak_koshizuka.toml", "lind"},
                                    {"dambreak_koshizuka_wcsph.toml", "delta_plus"}}) {
    const std::vector<std::string> set = {"particles.dp=0.04", "output.snapshot_interval=0", "scheme.shifting=" + model};
    const RunEnd<> one = run_on_threads(1, file, set, 150), two = run_on_threads(2, file, set, 150);
    EXPECT_TRUE(same_bits(one.particles.position, two.particles.position)) << file;
    EXPECT_TRUE(same_bits(one.particles.velocity, two.particles.velocity)) << file;
    EXPECT_TRUE(same_bits(one.particles.pressure, two.particles.pressure)) << file;
    EXPECT_EQ(one.sample, two.sample) << file;
  }
}

// Both schemes in 3D (issue 31): the box of cases/box3d_diagonal.toml at dp = 20 mm (1,500 fluid
// particles), shaken along its diagonal, 60 steps; WCSPH with kernel gradient correction, SPS
// turbulence and delta-plus shifting, so that every 3D stage runs.
TEST(ThreadDeterminism, BothSchemesInThreeDimensionsTwoThreadsMatchOneThreadBitwise) {
  for (const std::vector<std::string>& scheme :
       {std::vector<std::string>{}, std::vector<std::string>{"scheme={type=\"wcsph\", kernel_gradient_correction=true, "
                                                             "turbulence=\"sps\", shifting=\"delta_plus\"}"}}) {
    std::vector<std::string> set = {"particles.dp=0.02", "time.settle=0.05", "output.snapshot_interval=0"};
    set.insert(set.end(), scheme.begin(), scheme.end());
    const RunEnd<3> one = run_on_threads<3>(1, "box3d_diagonal.toml", set, 60),
                    two = run_on_threads<3>(2, "box3d_diagonal.toml", set, 60);
    const std::string which = scheme.empty() ? "isph" : "wcsph";
    EXPECT_TRUE(same_bits(one.particles.position, two.particles.position)) << which;
    EXPECT_TRUE(same_bits(one.particles.velocity, two.particles.velocity)) << which;
    EXPECT_TRUE(same_bits(one.particles.pressure, two.particles.pressure)) << which;
    EXPECT_EQ(one.sample, two.sample) << which;
  }
}

}  // namespace
}  // namespace sloshsph
