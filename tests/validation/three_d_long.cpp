// The ISPH scheme in 3D against linear sloshing theory (issue 31, section 5): the (1,0) mode of a
// box. Label `long` (about a minute; it fails the issue's bar so far, see docs/validation/notes.md
// "Three dimensions").
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "sloshsph/geometry/cylinder_tank.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/schemes/isph.hpp"
#include "run_support.hpp"
#include "three_d_support.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_at_least;
using testing::check_at_most;
using testing::check_relative;
using testing::report;

// A box 0.4 m long, 0.1 m across, 0.4 m high with h = 0.2 m of water at dp = 10 mm (20 particles
// over the depth; 8,000 fluid and 9,872 wall particles), the scheme's defaults, dt = 2 ms. The
// fluid starts from rest in position with the velocity of the (1,0) mode of linear theory at its
// zero crossing, amplitude a = 4 mm (a/h = 0.02):
//   u = -a w cosh(k z) / sinh(k h) sin(k x),  w_z = a w sinh(k z) / sinh(k h) cos(k x),  k = pi / L,
// and moves freely for 3 s (four periods); the same in 2D for comparison. Reference: w^2 = g k tanh(k h) (issue 31: k = pi
// sqrt((m/L)^2 + (n/B)^2), m = 1, n = 0). Measured: the frequency of the fluid's horizontal centre of
// mass, pi times the half periods between its first and last crossings of its mean. Tolerance 3%
// (the issue's). No particle may leave.
// The height coordinate of a point: y in 2D, z in 3D.
template <int D>
double height_of(Vec<D> r) {
  if constexpr (D == 2) return r.y;
  else return r.z;
}

// The particles of the box at rest: the 2D section alone, or the section extruded over B.
template <int D>
BasicParticles<D> box_particles(const CaseSpec& spec, const PrismTank& tank) {
  if constexpr (D == 3) {
    return testing::particles_at_rest(spec, tank);
  } else {
    const double dp = spec.particles.dp;
    return particles_at_rest<2>(fill_fluid(tank.section, dp, spec.fill.depth),
                                sample_walls(tank.section, dp, spec.particles.wall_layers), dp, spec.fill.depth,
                                spec.fluid.density, spec.fluid.gravity);
  }
}

struct ModeRun {
  double omega_linear = 0.0, omega = 0.0;
  std::size_t crossings = 0, outside = 0;
};

// The angular frequency of an oscillating signal sampled at `time`: pi times the half periods
// between its first and last crossings of its mean (each crossing interpolated linearly between
// two samples), into run.omega, and the number of crossings into run.crossings.
void measure_frequency(const std::vector<double>& time, const std::vector<double>& signal, ModeRun& run) {
  double mean = 0.0;
  for (double v : signal) mean += v;
  mean /= static_cast<double>(signal.size());
  std::vector<double> crossings;
  for (std::size_t s = 1; s < signal.size(); ++s) {
    const double v0 = signal[s - 1] - mean, v1 = signal[s] - mean;
    if ((v0 < 0.0) != (v1 < 0.0)) crossings.push_back(time[s - 1] + (time[s] - time[s - 1]) * v0 / (v0 - v1));
  }
  run.crossings = crossings.size();
  if (crossings.size() >= 2)
    run.omega = std::numbers::pi * static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
}

// Runs the scheme on `p` under gravity alone for `duration`, samples the fluid's mean of
// `observable` after each step, and gives run its frequency (measure_frequency) and the count of
// fluid particles outside the tank at the end (in 2D its section, in 3D the prism).
template <int D, class Observable>
void run_free(const CaseSpec& spec, const PrismTank& tank, double dt, double duration, Observable observable,
              BasicParticles<D>& p, ModeRun& run) {
  BasicIsphScheme<D> scheme(spec, spec.particles.kernel_ratio * spec.particles.dp);
  typename BasicIsphScheme<D>::Input in;
  in.dt = dt;
  component_ref(in.frame.uniform, D - 1) = -spec.fluid.gravity;
  scheme.initialise(p, in.frame);
  std::vector<double> time, signal;
  const int steps = static_cast<int>(std::lround(duration / dt));
  for (int s = 1; s <= steps; ++s) {
    scheme.step(p, in);
    double sum = 0.0;
    for (std::size_t i = 0; i < p.n_fluid; ++i) sum += observable(p.position[i]);
    time.push_back(s * dt);
    signal.push_back(sum / static_cast<double>(p.n_fluid));
  }
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    run.outside += container_signed_distance<D>(tank.section, tank.breadth, p.position[i]) > 0.0 ? 0 : 1;
  measure_frequency(time, signal, run);
}

// The free (1,0) mode from its linear velocity field (see the test below), in 2D or 3D.
template <int D>
ModeRun first_mode(double L, double B, double h, double dp, double dt, double duration, double a) {
  const CaseSpec spec = testing::box_case(L, 0.4, h, dp);
  const PrismTank tank{make_tank(spec.tank, "test"), B};
  BasicParticles<D> p = box_particles<D>(spec, tank);
  const double g = spec.fluid.gravity, k = std::numbers::pi / L;
  ModeRun run;
  run.omega_linear = std::sqrt(g * k * std::tanh(k * h));
  const double omega = run.omega_linear;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    const double x = p.position[i].x, z = height_of<D>(p.position[i]);
    const double u = -a * omega * std::cosh(k * z) / std::sinh(k * h) * std::sin(k * x);
    const double w = a * omega * std::sinh(k * z) / std::sinh(k * h) * std::cos(k * x);
    if constexpr (D == 2) p.velocity[i] = {u, w};
    else p.velocity[i] = {u, 0.0, w};
  }
  run_free(spec, tank, dt, duration, [](Vec<D> r) { return r.x; }, p, run);
  return run;
}

TEST(ValidationLong, BoxFirstSloshingModeInThreeDimensions) {
  const double L = 0.4, B = 0.1, h = 0.2, dp = 0.01, dt = 0.002, duration = 3.0, a = 0.004;
  const ModeRun three = first_mode<3>(L, B, h, dp, dt, duration, a);
  // The same tank, initial field and scheme in 2D: how much of the error is the scheme's in any
  // dimension (reported, not checked).
  const ModeRun two = first_mode<2>(L, B, h, dp, dt, duration, a);
  report("box_mode_10_linear_omega_rad_s", three.omega_linear);
  report("box_mode_10_3d_crossings", static_cast<double>(three.crossings));
  report("box_mode_10_2d_omega_rad_s", two.omega);
  report("box_mode_10_2d_error_fraction", two.omega / two.omega_linear - 1.0);
  ASSERT_GE(three.crossings, 5u) << "fewer than two periods seen";
  check_relative("frequency of the (1,0) mode, 0.4 x 0.1 m box, h = 0.2 m, dp = 10 mm", three.omega, three.omega_linear,
                 0.03, "linear theory w^2 = g k tanh(k h), k = pi / L; tolerance 3% (issue 31)", "rad/s");
  check_at_most("particles outside the box", static_cast<double>(three.outside), 0.0, "none may leave");
}

// The (m, n) mode of a box in 3D, started from its linear velocity field
//   phi = (a w / k) cosh(k z) / sinh(k h) cos(m pi x / L) cos(n pi y / B),  k = pi sqrt((m/L)^2 + (n/B)^2),
// and free for `duration`; its frequency from the crossings of the mean of an observable that the
// mode moves: x (m = 1, n = 0), y (0, 1), (x - L/2)(y - B/2) (1, 1).
ModeRun box_mode(const CaseSpec& spec, double B, int m, int n, double dt, double duration, double a) {
  const double L = spec.tank.length, h = spec.fill.depth, g = spec.fluid.gravity;
  const PrismTank tank{make_tank(spec.tank, "test"), B};
  Particles3 p = testing::particles_at_rest(spec, tank);
  const double kx = m * std::numbers::pi / L, ky = n * std::numbers::pi / B, k = std::hypot(kx, ky);
  ModeRun run;
  run.omega_linear = std::sqrt(g * k * std::tanh(k * h));
  const double c = a * run.omega_linear / (k * std::sinh(k * h));
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    const Vec3 r = p.position[i];
    const double cx = std::cos(kx * r.x), sx = std::sin(kx * r.x), cy = std::cos(ky * r.y), sy = std::sin(ky * r.y);
    p.velocity[i] = {-c * kx * sx * cy * std::cosh(k * r.z), -c * ky * cx * sy * std::cosh(k * r.z),
                     c * k * cx * cy * std::sinh(k * r.z)};
  }
  run_free(
      spec, tank, dt, duration,
      [m, n, L, B](Vec3 r) { return m == 1 && n == 1 ? (r.x - 0.5 * L) * (r.y - 0.5 * B) : (m == 1 ? r.x : r.y); }, p,
      run);
  return run;
}

// Issue 31, section 5: the (1,0), (0,1) and (1,1) modes of a square box (0.3 x 0.3 m, h = 0.15 m,
// dp = 10 mm: 13,500 fluid particles) at h/dp = 1.8 with 3 wall layers, the kernel at which the
// (1,0) mode above comes within 0.2% (at the default 1.4 it is 9% high). Reference: w^2 = g k tanh(k h),
// k = pi sqrt((m/L)^2 + (n/B)^2); tolerance 3% (the issue's); 2 s each (about three periods), dt = 2 ms,
// a = 3 mm. No particle may leave.
TEST(ValidationLong, SquareBoxModesInThreeDimensionsAtKernelRatio18) {
  CaseSpec spec = testing::box_case(0.3, 0.3, 0.15, 0.01);
  spec.particles.kernel_ratio = 1.8;
  spec.particles.wall_layers = 3;
  const int modes[3][2] = {{1, 0}, {0, 1}, {1, 1}};
  for (const auto& mode : modes) {
    const ModeRun run = box_mode(spec, 0.3, mode[0], mode[1], 0.002, 2.0, 0.003);
    const std::string name = "(" + std::to_string(mode[0]) + "," + std::to_string(mode[1]) + ")";
    report("square_box_mode_" + std::to_string(mode[0]) + std::to_string(mode[1]) + "_crossings",
           static_cast<double>(run.crossings));
    ASSERT_GE(run.crossings, 4u) << name << ": fewer than two periods seen";
    check_relative("frequency of the " + name + " mode, 0.3 x 0.3 m box, h = 0.15 m, dp = 10 mm, h/dp = 1.8", run.omega,
                   run.omega_linear, 0.03, "linear theory w^2 = g k tanh(k h); tolerance 3% (issue 31)", "rad/s");
    check_at_most("particles outside the box, " + name + " mode", static_cast<double>(run.outside), 0.0,
                  "none may leave");
  }
}

// Issue 31, section 5: the first mode of an upright cylinder, through the driver from
// cases/cylinder3d_sloshing.toml (R = 0.15 m, 0.15 m of water, shaken along x for two periods of
// the mode at 2 mm, then free) at dp = 15 mm (R/dp = 10) and the default h = 1.4 dp. The
// frequency from the zero crossings of F_w (the walls' force along x; the base is still) over
// t >= 1.6 s, against linear theory w^2 = g k tanh(k h), k = 1.8412 / R, with h the level the
// particles settle to (their volume over pi R^2; since 2026-12-07 the fill holds the water of the
// case's depth, to half a particle, and settles into the ring of gaps the cubic lattice leaves along
// the round wall), the issue's 3%. The gauge's frequency and the theory at the nominal depth are
// reported. Measured 2026-12-07: 10.716 against 10.701 rad/s (+0.14%); before the fill held the
// depth's water (settled level 0.1318 m): +0.34%.
TEST(ValidationLong, CylinderFirstSloshingModeThroughTheDriver) {
  const double R = 0.15, dp = 0.015, g = 9.81;
  std::size_t fluid = 0;
  const testing::RunResult r =
      testing::run_file_in_memory<3>(testing::case_path("cylinder3d_sloshing.toml"),
                                     {"particles.dp=0.015", "output.snapshot_interval=0"},
                                     [&](const Simulation3& sim) { fluid = sim.scene().initial_fluid_count; });
  const double level = cylinder_settled_level(CylinderTank{R, 0.3}, fluid, dp);
  const double linear = cylinder_first_sloshing_omega(R, level, g);
  std::vector<double> time, force, gauge;
  for (std::size_t k = 0; k < r["time"].size(); ++k)
    if (r["time"][k] >= 1.6) {
      time.push_back(r["time"][k]);
      force.push_back(r["F_w"][k]);
      gauge.push_back(r["eta:left"][k]);
    }
  ModeRun from_force, from_gauge;
  measure_frequency(time, force, from_force);
  measure_frequency(time, gauge, from_gauge);
  report("cylinder_settled_level_m", level);
  report("cylinder_linear_omega_nominal_depth_rad_s", cylinder_first_sloshing_omega(R, 0.15, g));
  report("cylinder_gauge_omega_rad_s", from_gauge.omega);
  report("cylinder_crossings", static_cast<double>(from_force.crossings));
  ASSERT_GE(from_force.crossings, 5u) << "fewer than two periods seen";
  check_relative("first mode of the cylinder, R = 0.15 m, dp = 15 mm (from F_w)", from_force.omega, linear, 0.03,
                 "linear theory w^2 = g k tanh(k h), k = 1.8412 / R, h the settled level; tolerance 3% (issue 31)",
                 "rad/s");
  check_at_most("particles outside the cylinder", static_cast<double>(r.leaked), 0.0, "none may leave");
}

// Issue 31, section 5: swirling. An upright cylinder shaken along x only, slightly above its first
// mode, develops a wave that runs round the wall: under longitudinal forcing near the primary
// resonance the planar wave loses its stability to swirling (Miles 1984, J. Fluid Mech. 149,
// 15-31; Faltinsen, Lukovsky & Timokha 2016, J. Fluid Mech. 804, 608-645), which a purely planar
// response would not have. cases/cylinder3d_swirling.toml: R = 0.15 m, 0.15 m of water (omega1 =
// 10.70 rad/s), 5 mm (X0/R = 0.033) at 1.03 omega1 (beta), 25 s; and the same case at 0.85 omega1,
// below resonance, where the planar wave is stable. Measured 2026-12-07 (the fill holding the
// depth's water): 0.963 F_wy / F_w and +0.98 turns a period at 1.03 omega1, 0.0062 at 0.85 omega1
// (before, with the water settled 12% low and the forcing at 1.73 Hz: 0.99, -1.02 and 0.010); 10 min
// on one thread beside two one-hour runs. The limits of the swirling band
// in omega / omega1 were not read here (the papers' full texts were not at hand): the test uses one
// frequency close above omega1, inside the band by either theory, and one well below it.
// Checked over the last 3 s (22-25 s): at 1.03 omega1 the RMS of the transverse force F_wy at least
// half that of the in-line force F_w (the issue's "the same order") and the horizontal force vector
// turning round at least 0.8 times per forcing period, always the same way (a rotating wave: an
// oblique planar one would swing back and forth); at 0.85 omega1 F_wy below 5% of F_w (planar).
// The force is smoothed over 0.11 s (a fifth of a period) before its angle is followed.
struct SwirlMeasure {
  double transverse_ratio = 0.0;  // RMS F_wy / RMS F_w
  double turns = 0.0;             // net turns of (F_w, F_wy), signed
};

SwirlMeasure measure_swirl(const testing::RunResult& r, double from, double to) {
  const std::vector<double>& t = r["time"];
  auto smooth = [&](const std::vector<double>& v, std::size_t k) {
    const std::size_t lo = k >= 5 ? k - 5 : 0, hi = std::min(v.size() - 1, k + 5);
    double sum = 0.0;
    for (std::size_t j = lo; j <= hi; ++j) sum += v[j];
    return sum / static_cast<double>(hi - lo + 1);
  };
  SwirlMeasure m;
  double fx2 = 0.0, fy2 = 0.0, last_angle = 0.0;
  bool started = false;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < from || t[k] >= to) continue;
    fx2 += r["F_w"][k] * r["F_w"][k];
    fy2 += r["F_wy"][k] * r["F_wy"][k];
    const double angle = std::atan2(smooth(r["F_wy"], k), smooth(r["F_w"], k));
    if (started) m.turns += std::remainder(angle - last_angle, 2.0 * std::numbers::pi) / (2.0 * std::numbers::pi);
    last_angle = angle;
    started = true;
  }
  m.transverse_ratio = std::sqrt(fy2 / fx2);
  return m;
}

TEST(ValidationLong, CylinderSwirlsJustAboveItsFirstMode) {
  const double R = 0.15, dp = 0.015, g = 9.81;
  std::size_t fluid = 0;
  const testing::RunResult swirl =
      testing::run_file_in_memory<3>(testing::case_path("cylinder3d_swirling.toml"), {"output.snapshot_interval=0"},
                                     [&](const Simulation3& sim) { fluid = sim.scene().initial_fluid_count; });
  const testing::RunResult planar = testing::run_file_in_memory<3>(
      testing::case_path("cylinder3d_swirling.toml"), {"output.snapshot_interval=0", "excitation.beta=0.85"},
      [](const Simulation3&) {});
  const double omega_case = cylinder_first_sloshing_omega(R, 0.15, g);  // beta's reference
  const double above = 1.03 * omega_case / (2.0 * std::numbers::pi);      // Hz
  const double omega1 = cylinder_first_sloshing_omega(R, cylinder_settled_level(CylinderTank{R, 0.3}, fluid, dp), g);
  report("swirl_frequency_ratio_above", 1.03 * omega_case / omega1);
  report("swirl_frequency_ratio_below", 0.85 * omega_case / omega1);
  const SwirlMeasure s = measure_swirl(swirl, 22.0, 25.0), p = measure_swirl(planar, 22.0, 25.0);
  for (double from = 0.0; from < 25.0; from += 3.0)  // the growth, for the notes
    report("swirl_transverse_ratio_from_" + std::to_string(static_cast<int>(from)) + "s",
           measure_swirl(swirl, from, from + 3.0).transverse_ratio);
  report("swirl_turns_per_period", s.turns / (3.0 * above));
  report("planar_transverse_ratio", p.transverse_ratio);
  check_at_least("RMS F_wy / RMS F_w over 22-25 s at 1.03 omega1", s.transverse_ratio, 0.5,
                 "swirling: the transverse force of the order of the in-line force");
  check_at_least("|turns of the horizontal force| per forcing period, 22-25 s at 1.03 omega1",
                 std::abs(s.turns) / (3.0 * above), 0.8, "a wave running round the wall, one turn a period");
  check_at_most("RMS F_wy / RMS F_w over 22-25 s at 0.85 omega1", p.transverse_ratio, 0.05,
                "below resonance the planar wave is stable");
  check_at_most("particles outside the cylinder", static_cast<double>(swirl.leaked + planar.leaked), 0.0,
                "none may leave");
}

// Issue 31, section 5: a thin 3D slab with free-slip end walls reproduces the 2D run. The Liu &
// Lin (2008) case (cases/liu_lin_2008.toml: L = 0.57 m, h = 0.15 m, resonant sway X0 = 0.0088 L)
// at dp = 10 mm, dt = 1 ms, for 7 s, in 2D and as a slab 4 dp = 40 mm broad (the gauges and the
// probe on its middle plane, y = 20 mm). The walls carry the fluid's free-slip image velocity
// (thesis 2.4.3.1), so the end walls do not brake the flow, and a slab is the 2D flow repeated
// across. Checked: the RMS of each gauge over 3-7 s (the growth to resonance) within the issue's 5%
// of the 2D run's; reported: the peaks.
double rms_between(const testing::RunResult& r, const std::string& column, double from, double to) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < r["time"].size(); ++k)
    if (r["time"][k] >= from && r["time"][k] <= to) sum += r[column][k] * r[column][k], ++n;
  return std::sqrt(sum / n);
}

TEST(ValidationLong, ThinSlabReproducesTheTwoDimensionalLiuLinRun) {
  const std::vector<std::string> common = {"particles.dp=0.01", "time.dt=0.001", "output.snapshot_interval=0"};
  std::vector<std::string> slab = common;
  for (const char* set : {"tank.dimensions=3", "tank.breadth=0.04", "probes.gauge.0.y=0.02", "probes.gauge.1.y=0.02",
                          "probes.pressure.0.y=0.02", "probes.pressure.0.z=0.0"})
    slab.push_back(set);
  const testing::RunResult two = testing::run_case_in_memory("liu_lin_2008.toml", common);
  const testing::RunResult three =
      testing::run_file_in_memory<3>(testing::case_path("liu_lin_2008.toml"), slab, [](const Simulation3&) {});
  for (const char* gauge : {"eta:left", "eta:right"}) {
    const double rms2 = rms_between(two, gauge, 3.0, 7.0), rms3 = rms_between(three, gauge, 3.0, 7.0);
    check_relative(std::string("RMS of ") + gauge + " over 3-7 s, 3D slab against 2D", rms3, rms2, 0.05,
                   "the 2D run of the same case (issue 31: a slab reproduces it within 5%)", "m");
    double peak2 = 0.0, peak3 = 0.0;
    for (const double v : two[gauge]) peak2 = std::max(peak2, std::abs(v));
    for (const double v : three[gauge]) peak3 = std::max(peak3, std::abs(v));
    report(std::string("slab_peak_3d_") + gauge, peak3);
    report(std::string("slab_peak_2d_") + gauge, peak2);
  }
  report("slab_wall_seconds", three.wall_seconds);
  check_at_most("particles outside the slab", static_cast<double>(three.leaked), 0.0, "none may leave");
}

// Issue 31, section 2: porous screens in 3D, each the section's element extruded over the breadth.
// The Tait (2005) TLD with its two Ergun screens (cases/tait2005_screens.toml: 0.966 m, 0.119 m of
// water, X0 = 0.016 L at 1.01 omega1) at dp = 14 mm, dt = 1.4 ms, for 4 s, in 2D and as a slab 4 dp
// = 56 mm broad (gauge on the middle plane; the pressure probes dropped: the test reads the gauge and
// the forces). The screens' velocity is the Shepard-normalised one (screens.N.velocity =
// "shepard"): the thesis's eq. 2.26 sum is truncated where the kernel leaves the fluid, and a screen
// particle's kernel (support 2 x 2.5 h = 7 dp) reaches through both end walls of a 4 dp slab, which
// would make the slab a test of that truncation rather than of the extrusion (docs/validation/notes.md
// gives the thesis velocity's numbers). Checked over 1-4 s, as the thin-slab tests: the RMS of each
// screen's force per metre of breadth (F_screen / breadth) within 10% of the 2D run's, and the RMS
// of the gauge within 5%; 0 particles lost.
TEST(ValidationLong, ScreenedSlabReproducesTheTwoDimensionalTaitRun) {
  std::string text = read_case_file_text(testing::case_path("tait2005_screens.toml"));
  text = text.substr(0, text.find("[[probes.pressure]]")) + text.substr(text.find("[output]"));
  const std::string flat = (std::filesystem::temp_directory_path() / "sloshsph_tait_slab_2d.toml").string();
  const std::string slab = (std::filesystem::temp_directory_path() / "sloshsph_tait_slab_3d.toml").string();
  std::ofstream(flat) << text;
  std::string three = text;
  three.replace(three.find("shape = \"rectangle\""), 19, "dimensions = 3\nshape = \"rectangle\"\nbreadth = 0.056");
  three.replace(three.find("x = 0.9177"), 10, "y = 0.028\nx = 0.9177");
  std::ofstream(slab) << three;
  const std::vector<std::string> set = {"particles.dp=0.014", "time.dt=0.0014", "time.end=4.0",
                                        "output.snapshot_interval=0", "screens.0.velocity=\"shepard\"",
                                        "screens.1.velocity=\"shepard\""};
  const testing::RunResult two = testing::run_file_in_memory<2>(flat, set, [](const Simulation&) {});
  const testing::RunResult slab3 = testing::run_file_in_memory<3>(slab, set, [](const Simulation3&) {});
  for (const char* screen : {"F_screen:S1", "F_screen:S2"}) {
    const double rms2 = rms_between(two, screen, 1.0, 4.0), rms3 = rms_between(slab3, screen, 1.0, 4.0) / 0.056;
    check_relative(std::string("RMS of ") + screen + " per metre of breadth over 1-4 s, 3D slab against 2D", rms3, rms2,
                   0.10, "the 2D run of the same case (the extruded screen's drag per metre)", "N/m");
  }
  check_relative("RMS of eta:right over 1-4 s, screened 3D slab against 2D", rms_between(slab3, "eta:right", 1.0, 4.0),
                 rms_between(two, "eta:right", 1.0, 4.0), 0.05, "the 2D run of the same case (issue 31: 5% for a slab)",
                 "m");
  check_at_most("particles outside the slab", static_cast<double>(slab3.leaked), 0.0, "none may leave");
}

// Issue 31, section 2: a perforated floor in 3D, the section's horizontal element extruded over the
// breadth. A 0.6 m tank with 0.15 m of water over a Morison floor (solidity 0.5) 0.06 m above the
// bottom, forced at X0 = 5 mm at its first natural frequency for 4 s, dp = 15 mm, dt = 1 ms, in 2D
// and as a slab 4 dp = 60 mm broad (gauge on the middle plane); the floor's velocity Shepard-normalised,
// as in the screened slab above (its kernel reaches through the end walls of a 4 dp slab). Checked
// over 1-4 s with the bars of the screened slab: the RMS of the gauge within 5% of the 2D run's and
// of the floor's vertical force per metre of breadth (F_screen_z / breadth against the 2D
// F_screen_y) within 10%; 0 particles lost. Measured 2026-12-07: gauge -2.7%, floor force -6.8%
// (F_w per metre -4.7%, reported); 45 s on one thread.
TEST(ValidationLong, PerforatedFloorSlabReproducesTheTwoDimensionalRun) {
  const std::string text = R"([tank]
shape = "rectangle"
length = 0.6
height = 0.4
[fill]
depth = 0.15
[particles]
dp = 0.015
[time]
end = 4.0
dt = 1.0e-3
settle = 0.2
[excitation]
type = "harmonic"
amplitude = 0.005
beta = 1.0
[[screens]]
name = "floor"
model = "morison"
from = [0.0, 0.06]
to = [0.6, 0.06]
solidity = 0.5
velocity = "shepard"
[[probes.gauge]]
name = "left"
x = 0.03
[output]
sample_interval = 0.01
snapshot_interval = 0
)";
  const std::string flat = (std::filesystem::temp_directory_path() / "sloshsph_floor_slab_2d.toml").string();
  std::ofstream(flat) << text;
  const double breadth = 0.06;
  const testing::RunResult two = testing::run_file_in_memory<2>(flat, {}, [](const Simulation&) {});
  const testing::RunResult three = testing::run_file_in_memory<3>(
      flat, {"tank.dimensions=3", "tank.breadth=0.06", "probes.gauge.0.y=0.03"}, [](const Simulation3&) {});
  check_relative("RMS of eta:left over 1-4 s, perforated-floor 3D slab against 2D", rms_between(three, "eta:left", 1.0, 4.0),
                 rms_between(two, "eta:left", 1.0, 4.0), 0.05, "the 2D run of the same case (issue 31: 5% for a slab)",
                 "m");
  check_relative("RMS of the floor's vertical force per metre of breadth over 1-4 s, 3D slab against 2D",
                 rms_between(three, "F_screen_z:floor", 1.0, 4.0) / breadth, rms_between(two, "F_screen_y:floor", 1.0, 4.0),
                 0.10, "the 2D run of the same case (the extruded element's drag per metre)", "N/m");
  report("floor_slab_F_w_per_metre_ratio", rms_between(three, "F_w", 1.0, 4.0) / breadth / rms_between(two, "F_w", 1.0, 4.0));
  check_at_most("particles outside the slab", static_cast<double>(three.leaked), 0.0, "none may leave");
}

// Issue 31, section 2: explicit slats in 3D, the section's slat walls on every lattice plane across
// the breadth. The Biswal et al. (2006) tank with its two solid baffles (cases/biswal_baffles_explicit.toml:
// 1 m, 0.5 m of water, baffles 0.3 m long at 0.1 m from the bottom at both walls) at dp = 20 mm,
// dt = 2 ms, forced below resonance (X0 = 10 mm at 0.8 omega1 of the unbaffled tank), for 4 s, in 2D
// and as a slab 4 dp = 80 mm broad (gauge on the middle plane). Checked over 1-4 s: the RMS of the
// gauge within 5% of the 2D run's (the issue's bar for a slab) and of the base shear per metre of
// breadth (F_w / breadth) within 5%; 0 particles lost. Why not the case's own forcing (0.995 omega1):
// at resonance the response depends on the scheme's own frequency, which at h = 1.4 dp is further
// above theory in 3D than in 2D (the box's (1,0) mode: +9.25% against +5.90%), so the slab departs
// from 2D there with or without baffles (measured: -9.6% gauge, -10.6% F_w at dp = 10 mm with the
// baffles; -49% gauge without them at dp = 20 mm), a test of that excess and not of the slats
// (docs/validation/notes.md).
TEST(ValidationLong, BaffledSlabReproducesTheTwoDimensionalBiswalRun) {
  const std::vector<std::string> common = {"particles.dp=0.02", "time.dt=0.002", "time.end=4.0", "excitation.beta=0.8",
                                           "excitation.amplitude=0.01", "output.snapshot_interval=0"};
  std::vector<std::string> slab = common;
  for (const char* set : {"tank.dimensions=3", "tank.breadth=0.08", "probes.gauge.0.y=0.04"}) slab.push_back(set);
  const testing::RunResult two = testing::run_case_in_memory("biswal_baffles_explicit.toml", common);
  const testing::RunResult three =
      testing::run_file_in_memory<3>(testing::case_path("biswal_baffles_explicit.toml"), slab, [](const Simulation3&) {});
  check_relative("RMS of eta:right over 1-4 s, baffled 3D slab against 2D", rms_between(three, "eta:right", 1.0, 4.0),
                 rms_between(two, "eta:right", 1.0, 4.0), 0.05, "the 2D run of the same case (issue 31: 5% for a slab)",
                 "m");
  check_relative("RMS of F_w per metre of breadth over 1-4 s, baffled 3D slab against 2D",
                 rms_between(three, "F_w", 1.0, 4.0) / 0.08, rms_between(two, "F_w", 1.0, 4.0), 0.05,
                 "the 2D run of the same case", "N/m");
  check_at_most("particles outside the slab", static_cast<double>(three.leaked), 0.0, "none may leave");
}

// Issue 31, section 3: pitch in 3D. A thin slab of the Akyildiz & Erdem (2006) pitching tank
// (cases/akyildiz_erdem_pitch.toml: 0.92 m, 75% fill, 4 deg at 2 rad/s about the tank's centre) at
// dp = 20 mm, dt = 2 ms, for 6 s, in 2D and as a 3D slab 4 dp = 80 mm broad turned about the axis
// (0, -1, 0) through (0.46, 0.04, 0.31) (the 2D pitch's sense, docs/case-format.md), gauge and
// probe on the middle plane. As the thin-slab test below, the slab is the 2D flow repeated across
// (free-slip end walls): the RMS of the gauge over 1-6 s within 5% of the 2D run's (the issue's bar
// for a slab); the RMS of the wall pressure P1 reported.
TEST(ValidationLong, PitchedSlabReproducesTheTwoDimensionalPitch) {
  const std::vector<std::string> common = {"particles.dp=0.02", "time.dt=0.002", "time.end=6.0",
                                           "output.snapshot_interval=0"};
  std::vector<std::string> slab = common;
  for (const char* set : {"tank.dimensions=3", "tank.breadth=0.08", "probes.gauge.0.y=0.04", "probes.pressure.0.y=0.04",
                          "probes.pressure.0.z=0.06", "probes.pressure.1.y=0.04", "probes.pressure.1.z=0.17",
                          "excitation.pivot=[0.46, 0.04, 0.31]"})
    slab.push_back(set);
  const testing::RunResult two = testing::run_case_in_memory("akyildiz_erdem_pitch.toml", common);
  const testing::RunResult three =
      testing::run_file_in_memory<3>(testing::case_path("akyildiz_erdem_pitch.toml"), slab, [](const Simulation3&) {});
  const double rms2 = rms_between(two, "eta:left", 1.0, 6.0), rms3 = rms_between(three, "eta:left", 1.0, 6.0);
  check_relative("RMS of eta:left over 1-6 s, pitched 3D slab against 2D", rms3, rms2, 0.05,
                 "the 2D run of the same case (issue 31: a slab reproduces it within 5%)", "m");
  // The sense of the rotation: the RMS is blind to a mirrored flow (the left gauge of a tank turned
  // the other way is the right one), the difference of the two series is not. Bar: the RMS of the
  // difference below 20% of the 2D RMS (a mirrored flow gives about 200%).
  double d2 = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < two["time"].size() && k < three["time"].size(); ++k)
    if (two["time"][k] >= 1.0) d2 += std::pow(three["eta:left"][k] - two["eta:left"][k], 2), ++n;
  check_at_most("RMS (eta:left 3D - eta:left 2D) / RMS eta:left 2D, 1-6 s", std::sqrt(d2 / n) / rms2, 0.2,
                "the same flow, turned the same way");
  report("pitch_slab_p1_rms_2d_Pa", rms_between(two, "p:P1", 1.0, 6.0));
  report("pitch_slab_p1_rms_3d_Pa", rms_between(three, "p:P1", 1.0, 6.0));
  check_at_most("particles outside the slab", static_cast<double>(three.leaked), 0.0, "none may leave");
}

}  // namespace
}  // namespace sloshsph
