// The ISPH scheme in 3D (issue 31, section 5's first check): a box of water at rest holds its
// hydrostatic pressure, no particle leaves, the fluid stays at rest and the walls carry its weight.
// The scheme is the 2D one's code (BasicIsphScheme<3>), on a box built by geometry/prism_tank; no
// case file reads 3D yet, so the test sets the particles up itself.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/geometry/prism_tank.hpp"
#include "sloshsph/io/vtk_writer.hpp"
#include "sloshsph/schemes/isph.hpp"
#include "run_support.hpp"
#include "three_d_support.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

using testing::check_absolute;
using testing::check_at_most;
using testing::check_relative;
using testing::report;

// A 0.3 m x 0.2 m box, 0.4 m high, with H = 0.2 m of water at dp = 20 mm (15 x 10 x 10 = 1,500
// fluid and 2,852 wall particles), the scheme's defaults (implicit PPE with the multigrid, the
// "air" free surface, SPS turbulence), dt = 2 ms, for 2 s from the hydrostatic start.
// References and tolerances, those of the 2D Validation.HydrostaticTank: the mean pressure of each
// layer of particles whose kernel stays below the free surface (z <= H - 2h: the 2D test's
// highest probe is 5 dp below its surface) within 2% of rho g H of rho g (H - z); no particle
// outside the box; the largest speed below 1% of sqrt(g H); the vertical force of the walls on the
// fluid equal to its weight within 0.5%. The layers nearer the surface are reported, not checked.
TEST(Validation, HydrostaticBoxInThreeDimensions) {
  const double rho = 1000.0, g = 9.81, H = 0.2, dp = 0.02, dt = 0.002, duration = 2.0;
  const CaseSpec spec = testing::box_case(0.3, 0.4, H, dp);
  const PrismTank tank{make_tank(spec.tank, "test"), 0.2};
  Particles3 p = testing::particles_at_rest(spec, tank);
  const std::vector<Vec3> started_at = p.position;  // where each particle started (by id: id = index here)
  ASSERT_EQ(p.n_fluid, 1500u);
  ASSERT_EQ(p.n_wall(), 2852u);

  IsphScheme3 scheme(spec, spec.particles.kernel_ratio * dp);
  IsphScheme3::Input in;
  in.dt = dt;
  in.frame.uniform = {0.0, 0.0, -g};
  const auto start = std::chrono::steady_clock::now();
  scheme.initialise(p, in.frame);
  const int steps = static_cast<int>(std::lround(duration / dt));
  for (int s = 0; s < steps; ++s) scheme.step(p, in);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The mean pressure of each layer of particles (by the lattice row each started in, found by its
  // id: the scheme reorders the fluid by cells; they move far less than dp).
  std::map<long, std::pair<double, int>> layers;
  std::size_t outside = 0;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    auto& layer = layers[std::lround(started_at[static_cast<std::size_t>(p.id[i])].z / dp - 0.5)];
    layer.first += p.pressure[i];
    layer.second += 1;
    outside += tank.signed_distance(p.position[i]) > 0.0 ? 0 : 1;
  }
  const double scale = rho * g * H;
  double worst = 0.0;
  const double h = spec.particles.kernel_ratio * dp;
  for (const auto& [row, sum] : layers) {
    const double z = (row + 0.5) * dp, mean = sum.first / sum.second;
    if (z > H - 2.0 * h) {
      report("hydrostatic_3d_surface_layer_z" + std::to_string(z) + "_error_fraction_of_rho_g_H",
             (mean - rho * g * (H - z)) / scale);
      continue;
    }
    worst = std::max(worst, std::abs(mean - rho * g * (H - z)) / scale);
    check_absolute("mean pressure of the layer at z = " + std::to_string(z) + " m, at 2 s", mean, rho * g * (H - z),
                   0.02 * scale, "hydrostatics rho g (H - z), H = 0.2 m; tolerance 2% of rho g H", "Pa");
  }
  report("hydrostatic_3d_worst_layer_error_fraction_of_rho_g_H", worst);
  check_at_most("particles outside the box", static_cast<double>(outside), 0.0, "none may leave");
  const double max_speed = scheme.diagnostics().max_speed;
  report("hydrostatic_3d_max_speed_m_s", max_speed);
  check_at_most("largest fluid speed at 2 s", max_speed, 0.01 * std::sqrt(g * H), "1% of sqrt(g H), H = 0.2 m", "m/s");
  const double weight = p.mass * static_cast<double>(p.n_fluid) * g;
  report("hydrostatic_3d_vertical_wall_force_over_weight", scheme.diagnostics().wall_force.z / weight);
  check_relative("vertical force of the walls on the fluid, at 2 s", scheme.diagnostics().wall_force.z, weight, 0.005,
                 "the fluid's weight m g", "N");
  report("hydrostatic_3d_wall_seconds", seconds);
}

// The 3D cases below go through the driver (run/simulation.hpp's BasicSimulation<3>) from a case
// file: a 0.4 m x 0.2 m box (x, y), 0.3 m high, with 0.14 m of water at dp = 20 mm (20 x 10 x 7 =
// 1,400 fluid particles), dt = 2 ms, settled for 0.3 s. `extra` is appended to the case: its
// [excitation] or [structure] tables (empty: none).
std::string box_case_file(const std::string& name, const std::string& extra, double end) {
  const std::string text = R"([tank]
dimensions = 3
shape = "rectangle"
length = 0.4
breadth = 0.2
height = 0.3

[fill]
depth = 0.14

[particles]
dp = 0.02

[time]
end = )" + std::to_string(end) + R"(
dt = 0.002
settle = 0.3

[[probes.gauge]]
name = "corner"
x = 0.03
y = 0.03

[[probes.gauge]]
name = "middle"
x = 0.2
y = 0.1

[[probes.pressure]]
name = "P"
x = 0.2
y = 0.1
z = 0.05

[output]
sample_interval = 0.01
snapshot_interval = 0
)" + extra;
  const std::filesystem::path path = std::filesystem::temp_directory_path() / ("sloshsph_" + name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

double mean_from(const std::vector<double>& time, const std::vector<double>& v, double from) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (time[k] >= from) sum += v[k], ++n;
  return sum / n;
}

// Issue 31, sections 1, 2 and 4: a 3D case at rest through the driver. References and tolerances
// as Validation.HydrostaticBoxInThreeDimensions: the probe at z = 0.05 m within 2% of rho g H of
// rho g (H - z), the vertical wall force (F_wz, N) within 0.5% of the weight, no leak; the gauges
// (at (x, y)) within dp/10 of their level at t = 0. And a snapshot holds the 3D points.
TEST(Validation, ThreeDimensionalCaseAtRestThroughTheDriver) {
  const double rho = 1000.0, g = 9.81, H = 0.14, z = 0.05;
  std::size_t particles = 0;
  Vec3 first{};
  const std::string vtu = (std::filesystem::temp_directory_path() / "sloshsph_box3d_rest.vtu").string();
  const testing::RunResult r = testing::run_file_in_memory<3>(box_case_file("box3d_rest", "", 1.0), {},
                                                             [&](const Simulation3& sim) {
                                                               particles = sim.particles().size();
                                                               first = sim.particles().position[0];
                                                               write_vtu(vtu, sim.particles(), true);
                                                             });
  const std::vector<double>& t = r["time"];
  const double mass = r["fluid_mass"].front();
  EXPECT_NEAR(mass, 1400 * rho * 0.02 * 0.02 * 0.02, 1e-9);
  EXPECT_TRUE(check_absolute("probe pressure at z = 0.05 m (mean, t >= 0.5 s)", mean_from(t, r["p:P"], 0.5),
                             rho * g * (H - z), 0.02 * rho * g * H, "hydrostatics rho g (H - z)", "Pa"));
  EXPECT_TRUE(check_relative("vertical wall force F_wz / weight (mean, t >= 0.5 s)",
                             mean_from(t, r["F_wz"], 0.5) / (mass * g), 1.0, 0.005, "the weight of the water"));
  EXPECT_TRUE(check_at_most("particles outside the box", static_cast<double>(r.leaked), 0.0, "a closed tank"));
  double gauge = 0.0;
  for (const char* c : {"eta:corner", "eta:middle"})
    for (const double e : r[c]) gauge = std::max(gauge, std::abs(e));
  EXPECT_TRUE(check_at_most("largest gauge reading", gauge, 0.1 * 0.02, "still water: 0", "m"));
  // The snapshot: its header counts every particle, and the first particle's (x, y, z) is in its
  // points as three Float32 (z included).
  std::ifstream in(vtu, std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(file.find("NumberOfPoints=\"" + std::to_string(particles) + "\""), std::string::npos);
  const float xyz[3] = {static_cast<float>(first.x), static_cast<float>(first.y), static_cast<float>(first.z)};
  EXPECT_NE(file.find(std::string(reinterpret_cast<const char*>(xyz), sizeof xyz)), std::string::npos);
  EXPECT_GT(first.z, 0.0);
}

// Issue 31, section 3: the base moves along y (direction = [0, 1]), harmonic, A = 10 mm at 0.8 Hz,
// far below the first mode across the breadth (omega_01 = sqrt(g k tanh(k h)), k = pi / 0.2 m:
// 12.25 rad/s against 5.03). Reference: linear potential theory of a rectangular tank in forced
// sway (e.g. Graham & Rodriguez 1952; Ibrahim 2005, ch. 3): the wall force is the rigid mass times
// the acceleration plus the modes' share, F = m a [1 + sum_n (m_n / m) w^2 / (w_n^2 - w^2)], with
// m_n / m = 8 tanh((2n-1) pi h / B) / ((2n-1)^3 pi^3 h / B): 1.0733 with n up to 5. Checked: the
// least-squares slope of F_wy on m a_base_y over t >= 1.5 s (after the 0.5 s ramp) within 10% (the
// free oscillation the start leaves at omega_01 is not subtracted); the force across the motion,
// along x, below 5% of that along it (RMS); the base moves along y only (x_base exactly 0).
// Linear forced sway of a rectangular tank `across` m wide along the motion, water depth h, at w:
// F / (m a) = 1 + sum_n (m_n / m) w^2 / (w_n^2 - w^2), n up to 5.
double linear_sway_force_ratio(double w, double across, double h) {
  const double g = 9.81;
  double ratio = 1.0;
  for (int n = 1; n <= 5; ++n) {
    const double k = (2 * n - 1) * std::numbers::pi / across;
    const double wn2 = g * k * std::tanh(k * h);
    const double share = 8.0 * std::tanh(k * h) / (std::pow(2 * n - 1, 3) * std::pow(std::numbers::pi, 3) * h / across);
    ratio += share * w * w / (wn2 - w * w);
  }
  return ratio;
}

// The least-squares slope of a force column on m times an acceleration column over t >= from.
double force_slope(const testing::RunResult& r, const char* force, const char* acceleration, double from) {
  const double mass = r["fluid_mass"].front();
  double fa = 0.0, aa = 0.0;
  for (std::size_t k = 0; k < r["time"].size(); ++k) {
    if (r["time"][k] < from) continue;
    const double a = mass * r[acceleration][k];
    fa += r[force][k] * a;
    aa += a * a;
  }
  return fa / aa;
}

TEST(Validation, ThreeDimensionalTranslationAcrossTheBreadth) {
  const std::string excitation = R"(
[excitation]
type = "harmonic"
amplitude = 0.01
frequency = 0.8
ramp = 0.5
direction = [0.0, 1.0]
)";
  const testing::RunResult r =
      testing::run_file_in_memory<3>(box_case_file("box3d_sway", excitation, 3.5), {}, [](const Simulation3&) {});
  const double expected = linear_sway_force_ratio(2.0 * std::numbers::pi * 0.8, 0.2, 0.14);
  const std::vector<double>& t = r["time"];
  double fx2 = 0.0, fy2 = 0.0, x_base = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    x_base = std::max(x_base, std::abs(r["x_base"][k]));
    if (t[k] < 1.5) continue;
    fx2 += r["F_w"][k] * r["F_w"][k];
    fy2 += r["F_wy"][k] * r["F_wy"][k];
  }
  report("sway_3d_linear_theory_ratio", expected);
  EXPECT_TRUE(check_relative("F_wy / (m a_base_y), least squares over t >= 1.5 s", force_slope(r, "F_wy", "a_base_y", 1.5),
                             expected, 0.10, "linear forced sway of a rectangular tank (rigid mass and modal shares)"));
  EXPECT_TRUE(check_at_most("RMS F_w (across the motion) / RMS F_wy", std::sqrt(fx2 / fy2), 0.05,
                            "a box moved along its breadth: no force along its length"));
  EXPECT_EQ(x_base, 0.0);
  EXPECT_TRUE(check_at_most("particles outside the box", static_cast<double>(r.leaked), 0.0, "a closed tank"));
}

// Issue 31, section 1: the WCSPH scheme in 3D (BasicWcsphScheme<3>, the 2D code templated), through
// the driver, on the box of the tests above with the scheme's defaults (delta-SPH, artificial
// viscosity 0.02, Adami walls, symplectic integrator, the CFL step under time.dt). The checks of
// Validation.ThreeDimensionalCaseAtRestThroughTheDriver, at rest for 1 s: the probe at z = 0.05 m
// within 2% of rho g H of rho g (H - z) (mean over t >= 0.5 s), F_wz within 0.5% of the weight, no
// leak, the gauges within dp/10; and of ...TranslationAcrossTheBreadth, swayed along y (10 mm at
// 0.8 Hz) for 3.5 s: F_wy / (m a_base_y) within 10% of linear theory, F_w below 5% of F_wy.
TEST(Validation, WeaklyCompressibleSchemeInThreeDimensions) {
  const double rho = 1000.0, g = 9.81, H = 0.14, z = 0.05;
  const std::string wcsph = "\n[scheme]\ntype = \"wcsph\"\n";
  const testing::RunResult rest =
      testing::run_file_in_memory<3>(box_case_file("box3d_wcsph_rest", wcsph, 1.0), {}, [](const Simulation3&) {});
  const std::vector<double>& t = rest["time"];
  const double mass = rest["fluid_mass"].front();
  EXPECT_TRUE(check_absolute("WCSPH probe pressure at z = 0.05 m (mean, t >= 0.5 s)", mean_from(t, rest["p:P"], 0.5),
                             rho * g * (H - z), 0.02 * rho * g * H, "hydrostatics rho g (H - z)", "Pa"));
  EXPECT_TRUE(check_relative("WCSPH vertical wall force F_wz / weight (mean, t >= 0.5 s)",
                             mean_from(t, rest["F_wz"], 0.5) / (mass * g), 1.0, 0.005, "the weight of the water"));
  double gauge = 0.0;
  for (const char* c : {"eta:corner", "eta:middle"})
    for (const double e : rest[c]) gauge = std::max(gauge, std::abs(e));
  EXPECT_TRUE(check_at_most("WCSPH largest gauge reading at rest", gauge, 0.1 * 0.02, "still water: 0", "m"));
  const testing::RunResult sway = testing::run_file_in_memory<3>(
      box_case_file("box3d_wcsph_sway", wcsph + "\n[excitation]\ntype = \"harmonic\"\namplitude = 0.01\n"
                                                "frequency = 0.8\nramp = 0.5\ndirection = [0.0, 1.0]\n",
                    3.5),
      {}, [](const Simulation3&) {});
  double fx2 = 0.0, fy2 = 0.0;
  for (std::size_t k = 0; k < sway["time"].size(); ++k)
    if (sway["time"][k] >= 1.5) fx2 += sway["F_w"][k] * sway["F_w"][k], fy2 += sway["F_wy"][k] * sway["F_wy"][k];
  EXPECT_TRUE(check_relative("WCSPH F_wy / (m a_base_y), least squares over t >= 1.5 s",
                             force_slope(sway, "F_wy", "a_base_y", 1.5),
                             linear_sway_force_ratio(2.0 * std::numbers::pi * 0.8, 0.2, 0.14), 0.10,
                             "linear forced sway of a rectangular tank (rigid mass and modal shares)"));
  EXPECT_TRUE(check_at_most("WCSPH RMS F_w (across the motion) / RMS F_wy", std::sqrt(fx2 / fy2), 0.05,
                            "a box moved along its breadth: no force along its length"));
  EXPECT_TRUE(check_at_most("particles outside the box", static_cast<double>(rest.leaked + sway.leaked), 0.0,
                            "a closed tank"));
  report("wcsph_3d_rest_steps", static_cast<double>(rest.steps));
  report("wcsph_3d_rest_wall_seconds", rest.wall_seconds);
}

// Issue 31: the repulsive walls in 3D, each scheme with its own (WCSPH: Shao's repulsive wall
// particles, scheme.walls = "repulsive", no-slip; ISPH: the force of thesis eq. 3.18 beside the Adami
// walls, scheme.repulsive_walls), on the box of the tests above. Which wall particles act is tested
// in RepulsiveWallsThreeD (unit); here, that the force does not disturb water at rest and that a
// sway across the breadth gives the force of linear theory, with the bars of
// ...WeaklyCompressibleSchemeInThreeDimensions: at rest for 1 s, the probe at z = 0.05 m within 2% of
// rho g H of rho g (H - z) (mean over t >= 0.5 s), F_wz within 0.5% of the weight, the gauge within
// dp/10; swayed along y (10 mm at 0.8 Hz) for 3.5 s, F_wy / (m a_base_y) within 10% of linear theory;
// no particle outside. Measured 2026-12-07: WCSPH probe 906.1 Pa (882.9), F_wz / weight 0.9994,
// sway 1.075 (1.074); ISPH probe 899.3 Pa, 1.0000, sway 1.138, the same as without the force to 10
// digits (ThreeDimensionalTranslationAcrossTheBreadth): in this gentle sway no particle comes within
// its range 0.7 dp of the first layer, so for ISPH this shows only that the force leaves it alone.
TEST(Validation, RepulsiveWallsInThreeDimensions) {
  const double rho = 1000.0, g = 9.81, H = 0.14, z = 0.05;
  struct Variant {
    const char* name;
    const char* scheme;
  };
  const Variant variants[] = {{"WCSPH, Shao's repulsive walls", "\n[scheme]\ntype = \"wcsph\"\nwalls = \"repulsive\"\n"},
                              {"ISPH, thesis eq. 3.18", "\n[scheme]\nrepulsive_walls = true\n"}};
  for (const Variant& v : variants) {
    const std::string name = v.name;
    const testing::RunResult rest =
        testing::run_file_in_memory<3>(box_case_file("box3d_repulsive_rest", v.scheme, 1.0), {}, [](const Simulation3&) {});
    const std::vector<double>& t = rest["time"];
    const double mass = rest["fluid_mass"].front();
    EXPECT_TRUE(check_absolute(name + ": probe pressure at z = 0.05 m (mean, t >= 0.5 s)",
                               mean_from(t, rest["p:P"], 0.5), rho * g * (H - z), 0.02 * rho * g * H,
                               "hydrostatics rho g (H - z)", "Pa"));
    EXPECT_TRUE(check_relative(name + ": vertical wall force F_wz / weight (mean, t >= 0.5 s)",
                               mean_from(t, rest["F_wz"], 0.5) / (mass * g), 1.0, 0.005, "the weight of the water"));
    double gauge = 0.0;
    for (const char* c : {"eta:corner", "eta:middle"})
      for (const double e : rest[c]) gauge = std::max(gauge, std::abs(e));
    EXPECT_TRUE(check_at_most(name + ": largest gauge reading at rest", gauge, 0.1 * 0.02, "still water: 0", "m"));
    const testing::RunResult sway = testing::run_file_in_memory<3>(
        box_case_file("box3d_repulsive_sway",
                      std::string(v.scheme) + "\n[excitation]\ntype = \"harmonic\"\namplitude = 0.01\n"
                                              "frequency = 0.8\nramp = 0.5\ndirection = [0.0, 1.0]\n",
                      3.5),
        {}, [](const Simulation3&) {});
    EXPECT_TRUE(check_relative(name + ": F_wy / (m a_base_y), least squares over t >= 1.5 s",
                               force_slope(sway, "F_wy", "a_base_y", 1.5),
                               linear_sway_force_ratio(2.0 * std::numbers::pi * 0.8, 0.2, 0.14), 0.10,
                               "linear forced sway of a rectangular tank (rigid mass and modal shares)"));
    EXPECT_TRUE(check_at_most(name + ": particles outside the box", static_cast<double>(rest.leaked + sway.leaked),
                              0.0, "a closed tank"));
  }
}

// Issue 31, section 2: a Morison screen (S = 0.4) in the plane x = R through the axis of an upright
// cylinder (cases/cylinder3d_sloshing.toml at dp = 20 mm: R = 0.15 m, 0.15 m of water), forced from
// rest at its first natural frequency (2 mm) for 2.5 s, along x (through the screen) and along y
// (along its plane), against the same tank without it along x. No published sloshing measurement of
// a screened upright cylinder was at hand, so the checks are the screen's two properties that hold
// whatever the flow: Morison's drag acts on the flow through the screen only (eq. 1/2 rho C_l |u_n|
// u_n n), so moved along the plane (a) the screen's force along x stays below 1% of its value when
// moved across it, and (b) the wave and wall force are those of the tank without the screen (the
// cylinder is symmetric under x <-> y) within 5%, the size of the run-to-run differences of this
// coarse tank; and (c) moved through it, the screen takes energy from the sloshing: the largest wall
// force over t >= 1 s at least 2% below the tank without it. Largest values are of |eta| and |F|.
// Measured 2026-12-07 (the cylinder fill holding the water of its depth): (a) 3.7e-4, (b) |eta| +3.0%,
// |F| -1.1%, (c) -5.1%; 0 particles lost; 52 s on one thread for the three runs.
// The same screen as explicit slats (S = 0.5: slats and gaps 40 mm, 20 mm thick, 2 dp per gap), in
// the same two runs: the slats block the flow through their plane and, along it, only the vertical
// flow over their footprint and the water they displace (5.5% of the fill), so (d) moved along the
// plane, the change of the largest wave from the tank without them is less than a quarter of the
// change moved through them (a statement of orientation, not a measured reference: no screened-
// cylinder experiment was at hand), and (e) moved through them they take energy as (c). Measured
// 2026-12-07: wave -4.1% along against -48.3% through; wall force -65% through; 0 lost.
TEST(Validation, ScreenInACylinderResistsOnlyTheFlowThroughIt) {
  const std::string source = testing::case_path("cylinder3d_sloshing.toml");
  const std::vector<std::string> coarse = {"particles.dp=0.02", "time.end=2.5", "excitation.stop=100.0",
                                           "output.snapshot_interval=0"};
  auto with = [&coarse](std::vector<std::string> more) {
    more.insert(more.begin(), coarse.begin(), coarse.end());
    return more;
  };
  const std::string screen = "screens=[{name=\"S\", x=0.15, solidity=0.4, model=\"morison\"}]";
  const testing::RunResult bare = testing::run_file_in_memory<3>(source, with({}), [](const Simulation3&) {});
  const testing::RunResult through = testing::run_file_in_memory<3>(source, with({screen}), [](const Simulation3&) {});
  const testing::RunResult along =
      testing::run_file_in_memory<3>(source, with({screen, "excitation.direction=[0.0, 1.0]"}), [](const Simulation3&) {});
  auto largest = [](const testing::RunResult& r, const char* column) {
    double m = 0.0;
    for (std::size_t k = 0; k < r["time"].size(); ++k)
      if (r["time"][k] >= 1.0) m = std::max(m, std::abs(r[column][k]));
    return m;
  };
  EXPECT_TRUE(check_at_most("screen force along x, moved along its plane / moved through it",
                            largest(along, "F_screen:S") / largest(through, "F_screen:S"), 0.01,
                            "Morison's drag resists the flow through the screen only"));
  EXPECT_TRUE(check_relative("largest wave at the wall, moved along the screen's plane (gauge 'side')",
                             largest(along, "eta:side"), largest(bare, "eta:right"), 0.05,
                             "the tank without the screen moved along x (eta at 'right'; x <-> y symmetry)", "m"));
  EXPECT_TRUE(check_relative("largest wall force, moved along the screen's plane (F_wy)", largest(along, "F_wy"),
                             largest(bare, "F_w"), 0.05, "the tank without the screen moved along x (F_w)", "N"));
  EXPECT_TRUE(check_at_most("largest wall force moved through the screen / without it",
                            largest(through, "F_w") / largest(bare, "F_w"), 0.98,
                            "a screen takes energy from the sloshing"));
  report("cylinder_screen_through_wave_ratio", largest(through, "eta:right") / largest(bare, "eta:right"));
  const std::string slats = "screens=[{name=\"S\", x=0.15, slat_height=0.04, slat_gap=0.04, thickness=0.02, "
                            "model=\"explicit\"}]";
  const testing::RunResult slats_through =
      testing::run_file_in_memory<3>(source, with({slats}), [](const Simulation3&) {});
  const testing::RunResult slats_along =
      testing::run_file_in_memory<3>(source, with({slats, "excitation.direction=[0.0, 1.0]"}), [](const Simulation3&) {});
  const double wave_along = largest(slats_along, "eta:side") / largest(bare, "eta:right") - 1.0;
  const double wave_through = largest(slats_through, "eta:right") / largest(bare, "eta:right") - 1.0;
  report("cylinder_slats_along_wave_change", wave_along);
  report("cylinder_slats_through_wave_change", wave_through);
  EXPECT_TRUE(check_at_most("explicit slats: |wave change moved along their plane| / |moved through them|",
                            std::abs(wave_along) / std::abs(wave_through), 0.25,
                            "the slats block mainly the flow through their plane"));
  EXPECT_TRUE(check_at_most("explicit slats: largest wall force moved through them / without them",
                            largest(slats_through, "F_w") / largest(bare, "F_w"), 0.98,
                            "a screen takes energy from the sloshing"));
  EXPECT_TRUE(check_at_most("particles outside the cylinder",
                            static_cast<double>(bare.leaked + through.leaked + along.leaked + slats_through.leaked +
                                                slats_along.leaked),
                            0.0, "a closed tank"));
}

// Issue 31: fill blocks and the surge-front probe in 3D. The dam break of cases/dambreak_koshizuka.toml
// (a 1 m x 2 m column released in a 4 m tank, ISPH with the repulsive walls) as a slab 4 particles
// broad with free-slip end walls (cases/dambreak_koshizuka3d_slab.toml), against the 2D case, both at
// dp = 40 mm and dt = 2 ms for 0.65 s (the front reaches the far wall at about 0.7 s). Reference: the
// 2D run's front; the slab's flow is the 2D one. Bar: the RMS difference of the two fronts over the
// run within 2% of the column width a = 1 m (the 2D front's own error against Koshizuka & Oka is
// checked at 5% of a), and no particle lost. Measured 2026-12-07: 0.0097 a (the slab's front 0.3-1.5%
// ahead); 28 s on one thread.
TEST(Validation, DamBreakSlabReproducesTheTwoDimensionalFront) {
  const std::vector<std::string> coarse = {"particles.dp=0.04", "time.dt=0.002", "time.end=0.65",
                                           "output.snapshot_interval=0"};
  std::vector<std::string> slab = coarse;
  slab.push_back("tank.breadth=0.16");
  const testing::RunResult two_d = testing::run_case_in_memory("dambreak_koshizuka.toml", coarse);
  const testing::RunResult three_d = testing::run_file_in_memory<3>(testing::case_path("dambreak_koshizuka3d_slab.toml"),
                                                                    slab, [](const Simulation3&) {});
  ASSERT_EQ(two_d["time"].size(), three_d["time"].size());
  double sum = 0.0;
  for (std::size_t k = 0; k < two_d["time"].size(); ++k) {
    const double d = three_d["front:tip"][k] - two_d["front:tip"][k];
    sum += d * d;
  }
  const double rms = std::sqrt(sum / static_cast<double>(two_d["time"].size()));
  EXPECT_TRUE(check_at_most("RMS difference of the surge front, 3D slab against 2D, / a", rms / 1.0, 0.02,
                            "the 2D run of the same case (a = 1 m)"));
  EXPECT_TRUE(check_at_most("particles outside the tank, slab", static_cast<double>(three_d.leaked), 0.0, "a closed tank"));
  report("dambreak_slab_front_at_0.5s_m", three_d["front:tip"][50]);
}

// Issue 31, section 2: a screen at any angle in the plan (plan_from, plan_to). A square box (0.6 x
// 0.6 m, 0.1 m of water, dp = 20 mm) with a Morison screen (S = 0.5) on its diagonal from (0, 0) to
// (0.6, 0.6), forced at its (1,0) mode (5 mm) for 1.5 s along x and, separately, along y. The box
// and the screen are symmetric about the diagonal, so the run along y is the mirror image of the
// run along x (x <-> y). References and bars: F_wy of the run along y against F_w of the run along
// x and the gauge (0.3, 0.03) against (0.03, 0.3), RMS over 0.75-1.5 s, within 2% (the lattice is
// mirrored but the particles' order is not, so the two runs part at round-off and grow apart);
// the screen's force along its normal (1, -1)/sqrt(2): its x and y parts opposite, RMS within 1e-9
// of each other (Morison resists the flow through the screen only; its magnitude is checked in
// ScreenDrag.ScreenInAPlaneThroughThePlanAtAnyAngle); 0 particles lost. Measured 2026-12-07: F +0.33%,
// gauge +0.27%; 53 s on one thread beside two other runs.
TEST(Validation, DiagonalScreenMirrorsTheSquareBoxsResponse) {
  const std::string text = R"([tank]
dimensions = 3
shape = "rectangle"
length = 0.6
breadth = 0.6
height = 0.3
[fill]
depth = 0.1
[particles]
dp = 0.02
[time]
end = 1.5
dt = 2.0e-3
settle = 0.2
[excitation]
type = "harmonic"
amplitude = 0.005
beta = 1.0
[[screens]]
name = "D"
plan_from = [0.0, 0.0]
plan_to = [0.6, 0.6]
solidity = 0.5
model = "morison"
[[probes.gauge]]
name = "a"
x = 0.03
y = 0.3
[[probes.gauge]]
name = "b"
x = 0.3
y = 0.03
[output]
sample_interval = 0.01
snapshot_interval = 0
)";
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "sloshsph_diagonal_screen.toml";
  std::ofstream(path) << text;
  const testing::RunResult along_x = testing::run_file_in_memory<3>(path.string(), {}, [](const Simulation3&) {});
  const testing::RunResult along_y =
      testing::run_file_in_memory<3>(path.string(), {"excitation.direction=[0.0, 1.0]"}, [](const Simulation3&) {});
  auto rms = [](const testing::RunResult& r, const char* column) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < r["time"].size(); ++k)
      if (r["time"][k] >= 0.75) sum += r[column][k] * r[column][k], ++n;
    return std::sqrt(sum / static_cast<double>(n));
  };
  EXPECT_TRUE(check_relative("RMS F_wy moved along y / RMS F_w moved along x, diagonal screen", rms(along_y, "F_wy"),
                             rms(along_x, "F_w"), 0.02, "the mirror image about the diagonal", "N"));
  EXPECT_TRUE(check_relative("RMS gauge (0.3, 0.03) moved along y / gauge (0.03, 0.3) moved along x",
                             rms(along_y, "eta:b"), rms(along_x, "eta:a"), 0.02, "the mirror image about the diagonal",
                             "m"));
  for (const testing::RunResult* r : {&along_x, &along_y})
    EXPECT_TRUE(check_relative("RMS of the screen's force along y / along x (opposite parts of a force along its normal)",
                               rms(*r, "F_screen_y:D"), rms(*r, "F_screen:D"), 1e-9, "Morison's normal drag", "N"));
  report("diagonal_screen_force_rms_N", rms(along_x, "F_screen:D"));
  EXPECT_TRUE(check_at_most("particles outside the box", static_cast<double>(along_x.leaked + along_y.leaked), 0.0,
                            "a closed tank"));
}

// Issue 31, section 3: two independent base motions, [excitation] along x and [excitation.y] along
// y, on the box of the tests above for 1.5 s. The motion along a direction is validated above
// (linear theory across the breadth); here the two components are shown to be that motion:
//  * [excitation.y] alone (10 mm at 0.8 Hz) is the base moved along direction = [0, 1]: the same
//    bits in every column;
//  * [excitation] and [excitation.y] with the same harmonic (10 mm at 0.8 Hz) are the base moved
//    along [1, 1] with 10 sqrt(2) mm: the same run but for round-off (the diagonal's components are
//    A sqrt(2) / sqrt(2) instead of A), so every force within 1e-6 of its largest value.
// A component that did not reach the fluid, or reached it along the wrong axis, fails by 100%.
double largest_difference(const std::vector<double>& a, const std::vector<double>& b, double& largest_b) {
  double d = 0.0;
  largest_b = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
    d = std::max(d, std::abs(a[k] - b[k])), largest_b = std::max(largest_b, std::abs(b[k]));
  return d;
}

TEST(Validation, ThreeDimensionalIndependentMotionsAlongXAndY) {
  const std::string harmonic = "type = \"harmonic\"\nfrequency = 0.8\nramp = 0.5\n";
  auto run = [](const std::string& name, const std::string& extra) {
    return testing::run_file_in_memory<3>(box_case_file(name, extra, 1.5), {}, [](const Simulation3&) {});
  };
  const testing::RunResult y_only = run("box3d_y", "\n[excitation]\ntype = \"none\"\n\n[excitation.y]\n" + harmonic +
                                                       "amplitude = 0.01\n");
  const testing::RunResult along_y =
      run("box3d_dir_y", "\n[excitation]\n" + harmonic + "amplitude = 0.01\ndirection = [0.0, 1.0]\n");
  for (const char* column : {"y_base", "a_base_y", "F_w", "F_wy", "F_wz", "eta:corner", "p:P"})
    EXPECT_EQ(y_only[column], along_y[column]) << column;
  const testing::RunResult both = run("box3d_xy", "\n[excitation]\n" + harmonic + "amplitude = 0.01\n\n[excitation.y]\n" +
                                                      harmonic + "amplitude = 0.01\n");
  const testing::RunResult diagonal =
      run("box3d_diagonal", "\n[excitation]\n" + harmonic + "amplitude = 0.01414213562373095\ndirection = [1.0, 1.0]\n");
  for (const char* column : {"F_w", "F_wy", "F_wz"}) {
    double largest = 0.0;
    const double d = largest_difference(both[column], diagonal[column], largest);
    report(std::string("xy_against_diagonal_") + column, d / largest);
    EXPECT_TRUE(check_at_most(std::string("largest |") + column + " of x + y - " + column +
                                  " along [1, 1]| / its largest value",
                              d / largest, 1e-6, "the same motion: round-off only"));
  }
  EXPECT_TRUE(check_at_most("particles outside the box", static_cast<double>(both.leaked), 0.0, "a closed tank"));
}

// Issue 31, sections 3 and 5: the building as a 2-DOF structure, without its tank acting back
// (tanks = 0: the fluid rides on the structure). Each sway mode is an SDOF of its own, so the
// reference is the closed form of a free damped oscillator, per direction:
//   x(t) = exp(-zeta w t) [x0 cos(w_d t) + (v0 + zeta w x0) / w_d sin(w_d t)], w_d = w sqrt(1 - zeta^2).
// Along x: 10 kg, 1.0 Hz, 2% of critical, released from x0 = 10 mm; along y: 20 kg, 0.7 Hz, 5%,
// from rest at y = 0 with v0 = 30 mm/s. Tolerance, the issue's 1%: the largest difference over the
// 3 s (2-3 periods) within 1% of each mode's amplitude (x0; v0 / w). Newmark's average acceleration
// at dt = 2 ms has a period error of (w dt)^2 / 12 = 1.3e-5 at 1 Hz, so 1% holds a wrong mass,
// stiffness or damping of either mode (a 1% frequency error alone gives 2-3% by 3 s) and any
// mixing of the two directions. And the fluid feels both motions: F_w and F_wy are not zero.
TEST(Validation, TwoDofStructureWithoutTankAgainstItsClosedForm) {
  const std::string structure = R"(
[structure]
tanks = 0
mass = 10.0
frequency = 1.0
damping_ratio = 0.02
initial_displacement = 0.01

[structure.y]
mass = 20.0
frequency = 0.7
damping_ratio = 0.05
initial_velocity = 0.03
)";
  const testing::RunResult r =
      testing::run_file_in_memory<3>(box_case_file("box3d_2dof_alone", structure, 3.0), {}, [](const Simulation3&) {});
  auto free_vibration = [](double f, double zeta, double x0, double v0, double t) {
    const double w = 2.0 * std::numbers::pi * f, wd = w * std::sqrt(1.0 - zeta * zeta);
    return std::exp(-zeta * w * t) * (x0 * std::cos(wd * t) + (v0 + zeta * w * x0) / wd * std::sin(wd * t));
  };
  const std::vector<double>& t = r["time"];
  double error_x = 0.0, error_y = 0.0, force_x = 0.0, force_y = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    error_x = std::max(error_x, std::abs(r["x_s"][k] - free_vibration(1.0, 0.02, 0.01, 0.0, t[k])));
    error_y = std::max(error_y, std::abs(r["x_s_y"][k] - free_vibration(0.7, 0.05, 0.0, 0.03, t[k])));
    force_x = std::max(force_x, std::abs(r["F_w"][k]));
    force_y = std::max(force_y, std::abs(r["F_wy"][k]));
  }
  const double amplitude_y = 0.03 / (2.0 * std::numbers::pi * 0.7);
  EXPECT_TRUE(check_at_most("largest |x_s - closed form| / x0 over 3 s", error_x / 0.01, 0.01,
                            "free damped SDOF along x (10 kg, 1.0 Hz, 2%)"));
  EXPECT_TRUE(check_at_most("largest |x_s_y - closed form| / (v0 / w) over 3 s", error_y / amplitude_y, 0.01,
                            "free damped SDOF along y (20 kg, 0.7 Hz, 5%)"));
  // The tank's largest acceleration times the fluid mass is 0.39 N along x, 0.26 N along y.
  EXPECT_GT(force_x, 0.1);
  EXPECT_GT(force_y, 0.1);
  report("two_dof_alone_error_x", error_x / 0.01);
  report("two_dof_alone_error_y", error_y / amplitude_y);
  EXPECT_TRUE(check_at_most("particles outside the box", static_cast<double>(r.leaked), 0.0, "a closed tank"));
}

// Issue 31, section 3: the 2-DOF structure coupled two-way with the tank (tanks = 1). With no
// damping anywhere (C = 0 in both directions, an inviscid fluid, no turbulence model, no load), the
// structure loses exactly the work the walls do on the liquid: |E_s + E_s_y - E_s(0) - E_s_y(0) +
// W_base| within 1e-4 of the initial energy E0 = (M_x + m_w) v_x0^2 / 2 + (M_y + m_w) v_y0^2 / 2,
// the bar of the 2D StructureCoupling.UndampedEnergyIsConserved (W_base is the integral of F_w . dX
// over both directions: the coupling creates no energy, run/structure_coupling.hpp). The total's
// drift (the fluid scheme's own dissipation) is reported. The structure: 10 kg, K = 200 N/m along
// x, 150 N/m along y (coupled with the 11.2 kg of water: 0.49 and 0.42 Hz, below the box's first
// modes at 1.27 and 1.95 Hz), released from rest at x = y = 0 with 0.1 and 0.08 m/s, for 4 s.
TEST(Validation, TwoDofStructureExchangesExactlyTheWallWorkWithTheTank) {
  const std::string structure = R"(
[fluid]
viscosity = 0.0

[scheme]
turbulence = false

[structure]
mass = 10.0
stiffness = 200.0
damping = 0.0
initial_velocity = 0.1

[structure.y]
mass = 10.0
stiffness = 150.0
damping = 0.0
initial_velocity = 0.08
)";
  const testing::RunResult r =
      testing::run_file_in_memory<3>(box_case_file("box3d_2dof_coupled", structure, 4.0), {}, [](const Simulation3&) {});
  const std::vector<double>& t = r["time"];
  const double m_w = r["fluid_mass"].front();
  const double e0 = 0.5 * (10.0 + m_w) * (0.1 * 0.1 + 0.08 * 0.08);
  const double es0 = r["E_s"].front() + r["E_s_y"].front(), total0 = es0 + r["E_TLD"].front();
  double exchange = 0.0, drift = 0.0, moved_y = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double es = r["E_s"][k] + r["E_s_y"][k];
    exchange = std::max(exchange, std::abs(es - es0 + r["W_base"][k]));
    drift = std::max(drift, std::abs(es + r["E_TLD"][k] - total0));
    moved_y = std::max(moved_y, std::abs(r["x_s_y"][k]));
  }
  EXPECT_TRUE(check_at_most("largest |E_s + E_s_y - (E_s + E_s_y)(0) + W_base| / E0 over 4 s", exchange / e0, 1e-4,
                            "the structure loses exactly the work the walls do on the liquid, in both directions"));
  EXPECT_GT(moved_y, 0.01);  // the sway along y took place (about v_y0 / w = 30 mm)
  report("two_dof_coupled_exchange_error", exchange / e0);
  report("two_dof_coupled_energy_drift_max", drift / e0);
  EXPECT_TRUE(check_at_most("particles outside the box", static_cast<double>(r.leaked), 0.0, "a closed tank"));
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// The moment columns (issue 31, section 4: forces and moments; M_w in 2D, M_wx, M_wy, M_wz in 3D):
// the moment about output.moment_point of the walls' (and screens') force on the fluid.
//
// 1. Against the fluid's own dynamics (2D): the pair forces between fluid particles are central
//    (pressure) or nearly so (viscosity), so the walls' moment about the origin is what changes the
//    fluid's angular momentum L = sum m r x u beside the frame force: over each sample interval,
//      (L(t_k) - L(t_k-1)) / dt_s = M_w - g m xbar + a m ybar   (frame force (-a, -g)),
//    the right side averaged over the interval (M_w is the interval mean; xbar, ybar and a by the
//    trapezoid rule). cases/clean_tank_forced.toml (X0 = 10 mm here, beta 0.9, dp = L/40) for 3 s.
//    Bar: the RMS of the difference within 5% of the RMS of the dynamic part M_w - W xbar.
// 2. At rest in 3D (the box of the tests above, 0.5 s) about (0, 0, 0): (W B/2, -W L/2, 0), the
//    weight's moment. Bar 0.5% of W B/2 and W L/2, as F_wz / weight.
// Measured 2026-12-07: (1) 0.62% of the dynamic part's RMS; (2) 0.99994, 0.99994, 1.3e-9 (and, by
// hand, the 2D hydrostatic case, cases/hydrostatic.toml at 15 s about (0, 0): M_w / (W L/2) 1.00005).
TEST(Validation, WallMomentBalancesTheFluidsAngularMomentum) {
  const CaseSpec spec = resolve_case(read_case_file(
      testing::case_path("clean_tank_forced.toml"),
      {"particles.dp=0.0125", "time.end=3.0", "excitation.amplitude=0.01", "output.sample_interval=0.01",
       "output.moment_point=[0.0, 0.0]"}));
  Simulation sim(spec);
  const double g = spec.fluid.gravity;
  struct Moments {
    double L = 0.0, xbar = 0.0, ybar = 0.0, mass = 0.0;
  };
  auto moments = [&sim]() {
    Moments m;
    const Particles& p = sim.particles();
    for (std::size_t i = 0; i < p.n_fluid; ++i) {
      m.L += p.mass * cross(p.position[i], p.velocity[i]);
      m.xbar += p.mass * p.position[i].x;
      m.ybar += p.mass * p.position[i].y;
      m.mass += p.mass;
    }
    m.xbar /= m.mass;
    m.ybar /= m.mass;
    return m;
  };
  auto column = [&sim](const std::vector<double>& row, const std::string& name) {
    for (std::size_t k = 0; k < row.size(); ++k)
      if (sim.columns()[k].name == name) return row[k];
    ADD_FAILURE() << "no column " << name;
    return std::numeric_limits<double>::quiet_NaN();
  };
  Moments before = moments();
  double a_before = column(sim.sample(), "a_base"), t_before = 0.0, next = spec.output.sample_interval;
  double diff2 = 0.0, dyn2 = 0.0;
  std::size_t n = 0;
  while (!sim.finished()) {
    sim.step();
    if (sim.time() < next - 1e-9 && !sim.finished()) continue;
    while (next <= sim.time() + 1e-9) next += spec.output.sample_interval;
    const std::vector<double> row = sim.sample();
    const Moments now = moments();
    const double a = column(row, "a_base"), M = column(row, "M_w"), dts = sim.time() - t_before;
    const double xbar = 0.5 * (now.xbar + before.xbar), ybar = 0.5 * (now.ybar + before.ybar);
    const double rate = (now.L - before.L) / dts;
    const double predicted = M - g * now.mass * xbar + 0.5 * (a + a_before) * now.mass * ybar;
    if (sim.time() > 0.2) {  // past the start, where the interval means begin
      diff2 += (rate - predicted) * (rate - predicted);
      dyn2 += (M - g * now.mass * xbar) * (M - g * now.mass * xbar);
      ++n;
    }
    before = now;
    a_before = a;
    t_before = sim.time();
  }
  ASSERT_GT(n, 100u);
  EXPECT_TRUE(check_at_most("RMS of dL/dt - (M_w - g m xbar + a m ybar) / RMS of (M_w - W xbar)", std::sqrt(diff2 / dyn2),
                            0.05, "the fluid's angular momentum balance (frame force (-a, -g))"));

  // At rest in 3D, about the origin.
  const testing::RunResult rest = testing::run_file_in_memory<3>(
      box_case_file("box3d_moment_rest", "", 0.5), {"output.moment_point=[0.0, 0.0, 0.0]"}, [](const Simulation3&) {});
  const double W = rest["fluid_mass"].front() * g;
  const std::vector<double>& t = rest["time"];
  EXPECT_TRUE(check_relative("M_wx / (W B/2) at rest, 3D box (mean, t >= 0.25 s)", mean_from(t, rest["M_wx"], 0.25) / (W * 0.1),
                             1.0, 0.005, "the weight's moment about the origin"));
  EXPECT_TRUE(check_relative("-M_wy / (W L/2) at rest, 3D box (mean, t >= 0.25 s)",
                             -mean_from(t, rest["M_wy"], 0.25) / (W * 0.2), 1.0, 0.005,
                             "the weight's moment about the origin"));
  EXPECT_TRUE(check_at_most("|M_wz| / (W L/2) at rest, 3D box (mean, t >= 0.25 s)",
                            std::abs(mean_from(t, rest["M_wz"], 0.25)) / (W * 0.2), 0.005, "no moment about the vertical"));
}

}  // namespace
}  // namespace sloshsph
