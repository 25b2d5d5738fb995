// Google Benchmark suite of the time-step stages (issue: speed). Each benchmark reports
// particle-steps per second as the counter `particle_steps/s` (items processed per second).
// Sizes: the Tait tank (L = 0.966 m, depth 0.119 m) at dp = 10, 7 and 5 mm, and a deep tank
// scaled from 2,000 to 200,000 particles for the cost-per-particle curve. The whole step
// (IsphStep*), each stage of it (Stage*: SPS stress, prediction, density and PPE source, the
// pressure solve with either preconditioner, correction), the WCSPH step, the neighbour-list
// build and the porous drag; the ISPH step of a 3D box of about 94,000 particles (IsphStepBox3D).
//   build/bench/bench_stages --benchmark_filter=IsphStep   (OMP_NUM_THREADS=1 or 2)
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "sloshsph/geometry/prism_tank.hpp"
#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/physics/frame.hpp"
#include "sloshsph/physics/porous.hpp"
#include "sloshsph/run/simulation.hpp"
#include "sloshsph/schemes/isph.hpp"
#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {
namespace {

std::string case_file(const std::string& name) { return std::string(SLOSHSPH_SOURCE_DIR) + "/cases/" + name; }

// The Tait tank with its two Ergun screens at X0/L = 0.016 (cases/tait2005_screens.toml).
CaseSpec tait_case(double dp, const std::string& preconditioner = "multigrid") {
  return resolve_case(read_case_file(case_file("tait2005_screens.toml"),
                                     {"particles.dp=" + std::to_string(dp), "output.snapshot_interval=0",
                                      "scheme.preconditioner=\"" + preconditioner + "\""}));
}

// A tank of aspect 2:1 filled to half its height with about `fluid` particles (walls add more),
// its pressure solve preconditioned by `preconditioner` ("multigrid" or "jacobi").
CaseSpec sized_tank(double fluid, const std::string& preconditioner) {
  const double length = 2.0, depth = 1.0;
  const double dp = std::sqrt(length * depth / fluid);
  return resolve_case(read_case_file(case_file("hydrostatic.toml"),
                                     {"tank.length=2.0", "tank.height=1.5", "fill.depth=1.0",
                                      "particles.dp=" + std::to_string(dp), "time.dt=" + std::to_string(0.05 * dp),
                                      "output.snapshot_interval=0", "probes.pressure=[]",
                                      "scheme.solver_max_iterations=20000",  // see docs/performance.md
                                      "scheme.preconditioner=\"" + preconditioner + "\""}));
}

// One Simulation::step (the whole ISPH step with screens, turbulence, walls, observers'
// accumulators), after 20 steps to leave the start-up; the counter krylov_iterations is the mean
// of the pressure solve's iterations over the timed steps.
void run_steps(benchmark::State& state, const CaseSpec& spec) {
  Simulation sim(spec);
  for (int k = 0; k < 20; ++k) sim.step();
  const double particles = static_cast<double>(sim.particles().size());
  double iterations = 0.0;
  for (auto _ : state) {
    sim.step();
    iterations += sim.scheme().diagnostics().solver_iterations;
  }
  state.counters["particles"] = particles;
  state.counters["krylov_iterations"] = iterations / static_cast<double>(state.iterations());
  state.counters["particle_steps/s"] =
      benchmark::Counter(particles * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void IsphStepTaitScreens(benchmark::State& state) { run_steps(state, tait_case(state.range(0) / 1000.0)); }
BENCHMARK(IsphStepTaitScreens)->Arg(10)->Arg(7)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime();

void IsphStepTaitScreensJacobi(benchmark::State& state) {
  run_steps(state, tait_case(state.range(0) / 1000.0, "jacobi"));
}
BENCHMARK(IsphStepTaitScreensJacobi)->Arg(10)->Arg(7)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime();

// The cost-per-particle curve (issue 8): multigrid from 2,000 to 200,000 particles; the Jacobi
// preconditioner to 50,000 (at 200,000 one of its steps takes about a minute).
void IsphStepSized(benchmark::State& state) {
  run_steps(state, sized_tank(static_cast<double>(state.range(0)), "multigrid"));
}
BENCHMARK(IsphStepSized)
    ->Arg(2000)->Arg(5000)->Arg(20000)->Arg(50000)->Arg(100000)->Arg(200000)
    ->Unit(benchmark::kMillisecond)->UseRealTime();

void IsphStepSizedJacobi(benchmark::State& state) {
  run_steps(state, sized_tank(static_cast<double>(state.range(0)), "jacobi"));
}
BENCHMARK(IsphStepSizedJacobi)->Arg(2000)->Arg(5000)->Arg(20000)->Arg(50000)->Unit(benchmark::kMillisecond)->UseRealTime();

// The ISPH step in 3D (issue 31, section 6): a box 0.6 m long, 0.4 m across and 0.4 m high with
// 0.3 m of water at dp = 10 mm (72,000 fluid and 22,272 wall particles, about 94,000 in all),
// the scheme's defaults, from rest.
void IsphStepBox3D(benchmark::State& state) {
  CaseSpec spec;
  spec.tank.length = 0.6;
  spec.tank.height = 0.4;
  spec.fill.depth = 0.3;
  spec.particles.dp = 0.01;
  const PrismTank tank{make_tank(spec.tank, "bench"), 0.4};
  Particles3 p = particles_at_rest(tank, spec.particles.dp, spec.fill.depth, spec.particles.wall_layers,
                                   spec.fluid.density, spec.fluid.gravity);
  IsphScheme3 scheme(spec, spec.particles.kernel_ratio * spec.particles.dp);
  IsphScheme3::Input in;
  in.dt = 0.002;
  in.frame.uniform = {0.0, 0.0, -spec.fluid.gravity};
  scheme.initialise(p, in.frame);
  for (auto _ : state) scheme.step(p, in);
  state.counters["particle_steps/s"] = benchmark::Counter(
      static_cast<double>(p.size()) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["particles"] = static_cast<double>(p.size());
  state.counters["krylov_iterations"] = scheme.diagnostics().solver_iterations;
}
BENCHMARK(IsphStepBox3D)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(20);

void WcsphStepTait(benchmark::State& state) {
  const CaseSpec spec = resolve_case(read_case_file(case_file("tait2005_screens.toml"),
                                     {"particles.dp=0.007", "scheme.type=\"wcsph\"", "output.snapshot_interval=0"}));
  run_steps(state, spec);
}
BENCHMARK(WcsphStepTait)->Unit(benchmark::kMillisecond)->UseRealTime();

// The stages of the ISPH step one at a time (IsphScheme::run_stage) on the Tait tank with screens
// after 20 steps of its excitation: a scheme of its own is started on a copy of the particles and
// takes two steps, and each timed stage then runs on a fresh copy of them (the copy and the build
// of the pairs the stage reads are not timed; StagePairs times that build alone, at r*) with the
// solver data of the last step. The pressure solve starts from the pressures before that
// step, as the step did, so its Krylov iterations are the step's; its multigrid hierarchy is kept
// from call to call as a step keeps it (the same rows, at most 20 uses, docs/physics.md), so the
// timed solves build it about once in 21, where a sloshing run builds it about once in ten steps.
struct StageBench {
  CaseSpec spec;
  Particles particles, pressures_before;
  IsphScheme scheme;
  StepInput input;
};

StageBench stage_bench(double dp, const std::string& preconditioner) {
  const CaseSpec spec = tait_case(dp, preconditioner);
  Simulation sim(spec);
  for (int k = 0; k < 20; ++k) sim.step();
  StageBench b{spec, sim.particles(), {}, IsphScheme(spec, sim.scene().h), {}};
  b.input.dt = spec.time.dt;
  b.input.frame = frame_force(spec.fluid.gravity, sim.tank_motion());
  b.scheme.initialise(b.particles, b.input.frame);
  do {  // until a step that kept the particle order, so that the saved pressures still fit
    b.pressures_before = b.particles;
    b.scheme.step(b.particles, b.input);
  } while (b.scheme.diagnostics().neighbours_rebuilt);
  return b;
}

void time_stage(benchmark::State& state, IsphStage stage, const std::string& preconditioner = "multigrid") {
  StageBench b = stage_bench(state.range(0) / 1000.0, preconditioner);
  const Particles& start = stage == IsphStage::pressure_solve ? b.pressures_before : b.particles;
  for (auto _ : state) {
    state.PauseTiming();
    Particles p = start;
    b.scheme.prepare_stage(stage, p);
    state.ResumeTiming();
    b.scheme.run_stage(stage, p, b.input);
  }
  state.counters["particle_steps/s"] = benchmark::Counter(
      static_cast<double>(start.size()) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  if (stage == IsphStage::pressure_solve)
    state.counters["krylov_iterations"] = b.scheme.diagnostics().solver_iterations;
}

// The pair layer's build (sph/pairs.hpp) at r*, as the step does it before the density stage.
void StagePairs(benchmark::State& state) {
  StageBench b = stage_bench(state.range(0) / 1000.0, "multigrid");
  for (auto _ : state) b.scheme.prepare_stage(IsphStage::density_and_ppe_source, b.particles);
  state.counters["particle_steps/s"] = benchmark::Counter(
      static_cast<double>(b.particles.size()) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
void StageSpsStress(benchmark::State& s) { time_stage(s, IsphStage::sps_stress); }
void StagePredict(benchmark::State& s) { time_stage(s, IsphStage::predict); }
void StageDensityAndPpeSource(benchmark::State& s) { time_stage(s, IsphStage::density_and_ppe_source); }
void StagePressureSolve(benchmark::State& s) { time_stage(s, IsphStage::pressure_solve); }
void StagePressureSolveJacobi(benchmark::State& s) { time_stage(s, IsphStage::pressure_solve, "jacobi"); }
void StageCorrectAndAdvance(benchmark::State& s) { time_stage(s, IsphStage::correct_and_advance); }
BENCHMARK(StagePairs)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StageSpsStress)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StagePredict)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StageDensityAndPpeSource)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StagePressureSolve)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StagePressureSolveJacobi)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(StageCorrectAndAdvance)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();

// Neighbour-list build alone on the particles of the Tait tank.
void NeighbourBuild(benchmark::State& state) {
  const CaseSpec spec = tait_case(state.range(0) / 1000.0);
  const Scene scene = build_scene(spec);
  NeighbourList list(2.0 * scene.h, 0.2 * 2.0 * scene.h);
  for (auto _ : state) list.build(scene.particles.position, scene.particles.n_fluid);
  state.counters["particle_builds/s"] = benchmark::Counter(
      static_cast<double>(scene.particles.size()) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(NeighbourBuild)->Arg(7)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime();

// The porous drag stage alone (two passes over the screen interface zone).
void PorousDrag(benchmark::State& state) {
  const CaseSpec spec = tait_case(state.range(0) / 1000.0);
  Simulation sim(spec);
  for (int k = 0; k < 20; ++k) sim.step();
  ScreenDragWork work;
  std::vector<Vec2> acceleration;
  std::vector<ScreenElementLoad> loads;
  const Particles& p = sim.particles();
  for (auto _ : state)
    screen_drag(sim.screens(), p, p.velocity, spec.fluid.density, spec.fluid.density * spec.fluid.viscosity, work,
                acceleration, loads);
  state.counters["screen_particles"] = static_cast<double>(sim.screens().position.size());
}
BENCHMARK(PorousDrag)->Arg(7)->Arg(5)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
}  // namespace sloshsph

BENCHMARK_MAIN();
