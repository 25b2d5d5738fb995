// Case files: every key checked, errors name the file, the line and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/linear/rectangular.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph {
namespace {

const char* kMinimal = R"(
[tank]
shape = "rectangle"
length = 0.5
height = 0.4

[fill]
depth = 0.25

[particles]
dp = 0.01

[time]
end = 1.0
)";

// Expects an InputError whose message names `key` and contains `fragment`.
void expect_error(const std::string& text, const std::vector<std::string>& sets, const std::string& key,
                  const std::string& fragment) {
  try {
    read_case_text(text, "case.toml", sets);
    FAIL() << "no error; expected one naming " << key;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), key) << what;
    EXPECT_NE(what.find("'" + key + "'"), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
    EXPECT_NE(what.find("case.toml"), std::string::npos) << what;
  }
}

// Reference: dummy layers stand (k - 1/2) dp behind the wall and reach a particle dp/2 in front
// of it when k dp < 2h, so ceil(2h/dp) - 1 layers are needed: 1 at h = dp, 2 at 1.4 and 1.5 dp,
// 3 at 1.8 and 2.0 dp, 4 at 2.5 dp (exact integers, no tolerance).
TEST(CaseReader, WallLayersFollowTheKernelRatio) {
  EXPECT_EQ(wall_layers_needed(1.0), 1);
  EXPECT_EQ(wall_layers_needed(1.4), 2);
  EXPECT_EQ(wall_layers_needed(1.5), 2);
  EXPECT_EQ(wall_layers_needed(1.6), 3);
  EXPECT_EQ(wall_layers_needed(1.8), 3);
  EXPECT_EQ(wall_layers_needed(2.0), 3);
  EXPECT_EQ(wall_layers_needed(2.5), 4);
  // The default: the layers needed, never fewer than 2.
  EXPECT_EQ(read_case_text(kMinimal, "case.toml", {"particles.kernel_ratio=1.2"}).particles.wall_layers, 2);
  EXPECT_EQ(read_case_text(kMinimal, "case.toml", {"particles.kernel_ratio=1.8"}).particles.wall_layers, 3);
  EXPECT_EQ(read_case_text(kMinimal, "case.toml", {"particles.kernel_ratio=2.5"}).particles.wall_layers, 4);
  // More than needed is the user's choice; fewer is refused, naming the key.
  EXPECT_EQ(read_case_text(kMinimal, "case.toml", {"particles.kernel_ratio=1.4", "particles.wall_layers=4"})
                .particles.wall_layers,
            4);
  expect_error(kMinimal, {"particles.kernel_ratio=1.8", "particles.wall_layers=2"}, "particles.wall_layers",
               "reaches 3 layers");
}

TEST(CaseReader, MinimalCaseHasTheDocumentedDefaults) {
  const CaseSpec s = read_case_text(kMinimal, "case.toml");
  EXPECT_DOUBLE_EQ(s.fluid.density, 1000.0);
  EXPECT_DOUBLE_EQ(s.fluid.viscosity, 1.0e-6);
  EXPECT_DOUBLE_EQ(s.fluid.gravity, 9.81);
  EXPECT_DOUBLE_EQ(s.particles.kernel_ratio, 1.4);
  EXPECT_EQ(s.particles.wall_layers, 2);
  EXPECT_DOUBLE_EQ(s.scheme.alpha, 0.01);
  EXPECT_EQ(s.scheme.pressure, PressureSolve::implicit_krylov);
  EXPECT_EQ(s.scheme.free_surface, FreeSurfaceModel::air);
  EXPECT_DOUBLE_EQ(s.scheme.free_surface_threshold, 0.9);
  EXPECT_TRUE(s.scheme.turbulence);
  EXPECT_DOUBLE_EQ(s.scheme.smagorinsky, 0.1);
  EXPECT_DOUBLE_EQ(s.scheme.ct, 0.08);
  EXPECT_DOUBLE_EQ(s.time.dt, 5.0e-4);
  EXPECT_FALSE(s.time.adaptive);
  EXPECT_EQ(s.excitation.type, ExcitationType::none);
  EXPECT_EQ(s.name, "case");
}

TEST(CaseReader, DefaultCaseParses) {
  const CaseSpec s = read_case_text(default_case_text(), "<built-in>");
  EXPECT_EQ(s.excitation.type, ExcitationType::harmonic);
  ASSERT_TRUE(s.excitation.beta.has_value());
  EXPECT_DOUBLE_EQ(*s.excitation.beta, 1.0);
  EXPECT_EQ(s.gauges.size(), 1u);
}

TEST(CaseReader, UnknownKeyIsNamedWithASuggestion) {
  std::string text = kMinimal;
  text.replace(text.find("dp = 0.01"), 9, "dpp = 0.01\ndp = 0.01");
  expect_error(text, {}, "particles.dpp", "did you mean 'particles.dp'");
}

TEST(CaseReader, UnknownTableIsNamed) {
  expect_error(std::string(kMinimal) + "\n[screenz]\nx = 1\n", {}, "screenz", "unknown key");
}

TEST(CaseReader, WrongTypeIsNamed) {
  std::string text = kMinimal;
  text.replace(text.find("dp = 0.01"), 9, "dp = \"fine\"");
  expect_error(text, {}, "particles.dp", "expected a number");
}

TEST(CaseReader, NegativeSpacingIsRejected) {
  expect_error(kMinimal, {"particles.dp=-0.005"}, "particles.dp", "positive");
}

TEST(CaseReader, FluidDeeperThanTheTank) {
  expect_error(kMinimal, {"fill.depth=0.5"}, "fill.depth", "deeper than the tank");
}

TEST(CaseReader, MissingRequiredKey) {
  std::string text = kMinimal;
  text.replace(text.find("end = 1.0"), 9, "");
  expect_error(text, {}, "time.end", "required");
}

TEST(CaseReader, HarmonicNeedsAFrequency) {
  expect_error(std::string(kMinimal) + "\n[excitation]\ntype = \"harmonic\"\namplitude = 0.001\n", {},
               "excitation.frequency", "needs 'frequency'");
  expect_error(std::string(kMinimal) + "\n[excitation]\namplitude = 0.001\nbeta = 1.0\nfrequency = 1.0\n", {},
               "excitation.beta", "give only one of");
}

TEST(CaseReader, ErrorsGiveTheLine) {
  std::string text = kMinimal;
  text.replace(text.find("dp = 0.01"), 9, "dp = -1.0");
  try {
    read_case_text(text, "case.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "case.toml:11") << e.what();
  }
}

TEST(CaseReader, SyntaxErrorGivesTheLine) {
  try {
    read_case_text("[tank]\nlength = = 1\n", "bad.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml:2"), std::string::npos) << e.what();
  }
}

TEST(CaseReader, SetOverridesAnyKey) {
  const CaseSpec s = read_case_text(kMinimal, "case.toml",
                                    {"time.end=2", "particles.dp=0.005", "tank.shape=rectangle", "scheme.turbulence=false"});
  EXPECT_DOUBLE_EQ(s.time.end, 2.0);
  EXPECT_DOUBLE_EQ(s.particles.dp, 0.005);
  EXPECT_FALSE(s.scheme.turbulence);
  EXPECT_EQ(s.where("time.end"), "case.toml (--set time.end)");
}

TEST(CaseReader, SetCreatesTablesAndIndexesArrays) {
  const std::string text = std::string(kMinimal) + "\n[[probes.gauge]]\nname = \"a\"\nx = 0.1\n";
  const CaseSpec s = read_case_text(text, "case.toml", {"probes.gauge.0.x=0.2", "excitation.amplitude=0.001",
                                                        "excitation.frequency=0.9"});
  ASSERT_EQ(s.gauges.size(), 1u);
  EXPECT_DOUBLE_EQ(s.gauges[0].x, 0.2);
  EXPECT_EQ(s.excitation.type, ExcitationType::harmonic);
  EXPECT_DOUBLE_EQ(*s.excitation.frequency, 0.9);
}

TEST(CaseReader, SetErrorsAreNamed) {
  EXPECT_THROW(read_case_text(kMinimal, "case.toml", {"nonsense"}), InputError);
  expect_error(kMinimal, {"particles.dq=1"}, "particles.dq", "unknown key");
  try {
    read_case_text(kMinimal, "case.toml", {"probes.gauge.3.x=1"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--set"), std::string::npos) << e.what();
  }
}

TEST(CaseReader, DuplicateProbeNames) {
  const std::string text = std::string(kMinimal) + "\n[[probes.gauge]]\nname = \"a\"\nx = 0.1\n[[probes.gauge]]\nname = \"a\"\nx = 0.2\n";
  expect_error(text, {}, "probes.gauge.1.name", "duplicate");
}

TEST(CaseReader, TimeStepAboveTheStabilityBound) {
  expect_error(kMinimal, {"time.dt=0.05"}, "time.dt", "stability bound");
}

// With time.adaptive the step bounds itself by the flow's speed each step, so its ceiling is
// held only to the body-force bound 0.25 sqrt(h / g): here h = 1.4 x 10 mm, 9.4 ms, against the
// fixed step's 0.4 dp / sqrt(g depth) = 2.55 ms.
TEST(CaseReader, AdaptiveCeilingIsHeldToTheBodyForceBound) {
  EXPECT_NO_THROW(read_case_text(kMinimal, "case.toml", {"time.adaptive=true", "time.dt=0.009"}));
  expect_error(kMinimal, {"time.dt=0.009"}, "time.dt", "stability bound");
  expect_error(kMinimal, {"time.adaptive=true", "time.dt=0.01"}, "time.dt", "0.25 sqrt(h / g)");
}

// time.dt_min, the adaptive step's floor: only with the adaptive ISPH step, not above its ceiling,
// and not above the fixed step's bound (here 0.4 dp / sqrt(g depth) = 2.55 ms), since where it binds
// the step is a fixed one. Default 0 (no floor).
TEST(CaseReader, AdaptiveStepFloorIsChecked) {
  const CaseSpec plain = read_case_text(kMinimal, "case.toml");
  EXPECT_DOUBLE_EQ(plain.time.dt_min, 0.0);
  const CaseSpec floored = read_case_text(kMinimal, "case.toml", {"time.adaptive=true", "time.dt=0.009", "time.dt_min=0.0025"});
  EXPECT_DOUBLE_EQ(floored.time.dt_min, 0.0025);
  // In the resolved case only when set (the committed run records' case.toml are compared with it
  // as text), and read back from it.
  EXPECT_EQ(resolved_case_toml(plain).find("dt_min"), std::string::npos);
  EXPECT_DOUBLE_EQ(read_case_text(resolved_case_toml(floored), "resolved.toml").time.dt_min, 0.0025);
  expect_error(kMinimal, {"time.dt=0.002", "time.dt_min=0.001"}, "time.dt_min", "time.adaptive = true");
  expect_error(kMinimal, {"scheme={type=\"wcsph\"}", "time.adaptive=true", "time.dt=0.002", "time.dt_min=0.001"},
               "time.dt_min", "ISPH");
  expect_error(kMinimal, {"time.adaptive=true", "time.dt=0.002", "time.dt_min=0.0021"}, "time.dt_min",
               "above the step's ceiling");
  expect_error(kMinimal, {"time.adaptive=true", "time.dt=0.009", "time.dt_min=0.003"}, "time.dt_min",
               "bound of a fixed step");
  expect_error(kMinimal, {"time.adaptive=true", "time.dt_min=-0.001"}, "time.dt_min", ">= 0");
}

TEST(CaseReader, ResolvedCaseReadsBackToTheSameSpec) {
  const CaseSpec a = read_case_text(default_case_text(), "default.toml");
  const CaseSpec b = read_case_text(resolved_case_toml(a), "resolved.toml");
  EXPECT_EQ(resolved_case_toml(a).substr(resolved_case_toml(a).find("\n\n")),
            resolved_case_toml(b).substr(resolved_case_toml(b).find("\n\n")));
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// The relaxation time replaces alpha: a resolved case writes one of the two, so that it reads back.
TEST(CaseReader, DensityRelaxationTimeAndPredictorReadBack) {
  const CaseSpec a = read_case_text(kMinimal, "case.toml",
                                    {"scheme.density_relaxation_time=0.05", "scheme.predictor=midpoint"});
  EXPECT_DOUBLE_EQ(a.scheme.density_relaxation_time, 0.05);
  EXPECT_EQ(a.scheme.predictor, PositionPredictor::midpoint);
  const CaseSpec b = read_case_text(resolved_case_toml(a), "resolved.toml");
  EXPECT_DOUBLE_EQ(b.scheme.density_relaxation_time, 0.05);
  EXPECT_EQ(b.scheme.predictor, PositionPredictor::midpoint);
  const CaseSpec c = read_case_text(kMinimal, "case.toml");
  EXPECT_EQ(c.scheme.density_relaxation_time, 0.0);
  EXPECT_EQ(c.scheme.predictor, PositionPredictor::euler);
  expect_error(kMinimal, {"scheme.alpha=0.02", "scheme.density_relaxation_time=0.05"},
               "scheme.density_relaxation_time", "leave alpha out");
}

TEST(CaseReader, FreeSurfaceModelFollowsThePressureSolve) {
  EXPECT_EQ(read_case_text(kMinimal, "case.toml", {"scheme.pressure=explicit"}).scheme.free_surface,
            FreeSurfaceModel::thesis);
  EXPECT_EQ(read_case_text(kMinimal, "case.toml", {"scheme.pressure=implicit", "scheme.free_surface=thesis"})
                .scheme.free_surface,
            FreeSurfaceModel::thesis);
  expect_error(kMinimal, {"scheme.pressure=explicit", "scheme.free_surface=air"}, "scheme.free_surface",
               "needs pressure = \"implicit\"");
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// Two blocks either side of x = 0.25 in the 0.5 m tank of kMinimal, 0.2 m and 0.1 m deep.
const char* kBlocks = R"(
[tank]
shape = "rectangle"
length = 0.5
height = 0.4

[fill]
[[fill.blocks]]
from = [0.0, 0.0]
to = [0.25, 0.2]
[[fill.blocks]]
from = [0.25, 0.0]
to = [0.5, 0.1]

[particles]
dp = 0.01

[time]
end = 1.0
dt = 1.0e-3
)";

TEST(CaseReader, FillBlocksSettleToTheDepthOfTheirWater) {
  const CaseSpec s = read_case_text(kBlocks, "case.toml");
  ASSERT_EQ(s.fill.blocks.size(), 2u);
  // Water 0.25 x 0.2 + 0.25 x 0.1 = 0.075 m^2 over 0.5 m: 0.15 m (the lattice holds it exactly).
  EXPECT_NEAR(s.fill.depth, 0.15, 1e-9);
  EXPECT_DOUBLE_EQ(fill_head(s.fill), 0.2);
  // The speed scale of a collapsing column: sqrt(2 g head).
  EXPECT_NEAR(fill_speed_scale(s.fill, s.fluid.gravity), std::sqrt(2.0 * 9.81 * 0.2), 1e-12);
  // A given depth is kept.
  EXPECT_DOUBLE_EQ(read_case_text(kBlocks, "case.toml", {"fill.depth=0.12"}).fill.depth, 0.12);
  // And the resolved case reads back to the same blocks.
  const CaseSpec b = read_case_text(resolved_case_toml(s), "resolved.toml");
  ASSERT_EQ(b.fill.blocks.size(), 2u);
  EXPECT_DOUBLE_EQ(b.fill.blocks[1].to.y, 0.1);
}

TEST(CaseReader, FillBlocksAreChecked) {
  expect_error(kBlocks, {"fill.blocks.0.to=[0.25, -0.1]"}, "fill.blocks.0.to", "above and to the right");
  expect_error(kBlocks, {"fill.blocks.1.to=[0.6, 0.1]"}, "fill.blocks.1.from", "outside the tank");
  expect_error(kBlocks, {"fill.blocks.0.to=[0.25, 0.4]"}, "fill.blocks.0.to", "top of the walls");
  expect_error(kBlocks, {"fill.blocks.0.to=[0.005, 0.2]"}, "fill.blocks.0.to", "thinner than one particle");
  expect_error(kBlocks, {"fill.blocks.0.volume=1"}, "fill.blocks.0.volume", "unknown key");
  // Without blocks the depth is required.
  expect_error(kMinimal, {"fill.depth=-1"}, "fill.depth", "positive");
}

TEST(CaseReader, FrontProbeKeys) {
  const CaseSpec s = read_case_text(kBlocks, "case.toml", {"probes.front=[{name = \"tip\"}]"});
  ASSERT_EQ(s.fronts.size(), 1u);
  EXPECT_EQ(s.fronts[0].name, "tip");
  EXPECT_DOUBLE_EQ(s.fronts[0].band, 0.0);
  EXPECT_TRUE(s.fronts[0].rightward);
  expect_error(kBlocks, {"probes.front=[{name = \"tip\", direction = \"up\"}]"}, "probes.front.0.direction", "up");
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// cases/box3d_diagonal.toml, moved along y ([0, 2], normalised to [0, 1]).
std::string box3d_text() {
  return read_case_file_text(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/box3d_diagonal.toml");
}
const std::vector<std::string> kAlongY = {"excitation.direction=[0.0, 2.0]"};

// Issue 31, section 2: the fixed 3D keys. y of a gauge and of a probe is the breadth coordinate,
// z of a probe its height; the direction is normalised. (Exact values: no arithmetic but the
// normalisation of (0, 2).)
TEST(CaseReader, ThreeDimensionalKeys) {
  const CaseSpec s = read_case_text(box3d_text(), "case.toml", kAlongY);
  EXPECT_EQ(s.tank.dimensions, 3);
  EXPECT_EQ(s.tank.breadth, 0.2);
  EXPECT_EQ(s.excitation.direction.x, 0.0);
  EXPECT_EQ(s.excitation.direction.y, 1.0);
  EXPECT_EQ(s.gauges.at(2).x, 0.2);
  EXPECT_EQ(s.gauges.at(2).across, 0.17);
  EXPECT_EQ(s.pressure_probes.at(1).position.x, 0.395);
  EXPECT_EQ(s.pressure_probes.at(1).across, 0.1);
  EXPECT_EQ(s.pressure_probes.at(1).position.y, 0.1);
  // The 2D default is unchanged, and a 2D case.toml has no 3D key.
  const CaseSpec flat = read_case_text(kMinimal, "case.toml", {});
  EXPECT_EQ(flat.tank.dimensions, 2);
  EXPECT_EQ(resolved_case_toml(flat).find("dimensions"), std::string::npos);
  // The resolved 3D case reads back to the same keys.
  const CaseSpec again = read_case_text(resolved_case_toml(s), "resolved.toml", {});
  EXPECT_EQ(again.tank.dimensions, 3);
  EXPECT_EQ(again.tank.breadth, s.tank.breadth);
  EXPECT_EQ(again.excitation.direction.y, 1.0);
  EXPECT_EQ(again.gauges.at(2).across, 0.17);
  EXPECT_EQ(again.pressure_probes.at(1).across, 0.1);
  EXPECT_EQ(again.pressure_probes.at(1).position.y, 0.1);
}

// Issue 31, section 3: a rotation of a 3D tank, roll, pitch or yaw: `pivot` [x, y, z] and `axis`
// (normalised; default (0, -1, 0), the 2D pitch's sense). Exact values; the resolved case reads back.
TEST(CaseReader, ThreeDimensionalRotationKeys) {
  const CaseSpec s = read_case_text(box3d_text(), "case.toml",
                                    {"excitation={type=\"pitch\", angle=3.0, frequency=1.0, pivot=[0.2, 0.1, 0.15], "
                                     "axis=[0.0, 0.0, 2.0]}"});
  EXPECT_EQ(s.excitation.type, ExcitationType::pitch);
  EXPECT_EQ(s.excitation.pivot.x, 0.2);
  EXPECT_EQ(s.excitation.pivot.y, 0.15);  // the pivot's height, z
  EXPECT_EQ(s.excitation.pivot_across, 0.1);
  EXPECT_EQ(s.excitation.axis.z, 1.0);  // a yaw, normalised
  const CaseSpec again = read_case_text(resolved_case_toml(s), "resolved.toml", {});
  EXPECT_EQ(again.excitation.pivot_across, 0.1);
  EXPECT_EQ(again.excitation.pivot.y, 0.15);
  EXPECT_EQ(again.excitation.axis.z, 1.0);
  const CaseSpec pitch = read_case_text(
      box3d_text(), "case.toml", {"excitation={type=\"pitch\", angle=3.0, frequency=1.0, pivot=[0.2, 0.1, 0.15]}"});
  EXPECT_EQ(pitch.excitation.axis.y, -1.0);  // the default: the 2D pitch's sense
}

// Issue 31, section 2: a screen across the breadth, `y` (3D boxes): its plane y = const, full height,
// over the whole length; the resolved case reads back; `y` with `x`, outside the breadth or in a
// prism is refused by name.
TEST(CaseReader, ScreenAcrossTheBreadthKeys) {
  const std::string box = box3d_text();
  const std::string across = "\n[[screens]]\nname = \"Y\"\ny = 0.1\nsolidity = 0.4\nmodel = \"morison\"\n";
  const CaseSpec s = read_case_text(box + across, "case.toml", {});
  ASSERT_EQ(s.screens.size(), 1u);
  ASSERT_TRUE(s.screens[0].plane_y);
  EXPECT_EQ(*s.screens[0].plane_y, 0.1);
  EXPECT_TRUE(s.screens[0].full_height);
  const CaseSpec again = read_case_text(resolved_case_toml(s), "resolved.toml", {});
  ASSERT_TRUE(again.screens.at(0).plane_y);
  EXPECT_EQ(*again.screens[0].plane_y, 0.1);
  expect_error(box + "\n[[screens]]\nname = \"Y\"\ny = 0.1\nx = 0.2\nsolidity = 0.4\n", {}, "screens.0.x", "'y'");
  expect_error(box + "\n[[screens]]\nname = \"Y\"\ny = 0.25\nsolidity = 0.4\n", {}, "screens.0.y", "breadth");
  expect_error(box + across, {"tank.shape=\"circular\""}, "screens.0.y", "box");
  expect_error(kMinimal + across, {}, "screens.0.y", "3D tanks");
}

// An upright cylinder: radius and height; it spans 2R in x and y (exact: no arithmetic but 2R), and
// its resolved case reads back.
TEST(CaseReader, CylinderKeys) {
  const CaseSpec s =
      read_case_file(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/cylinder3d_sloshing.toml", {});
  EXPECT_EQ(s.tank.dimensions, 3);
  EXPECT_EQ(s.tank.shape, "cylinder");
  EXPECT_EQ(s.tank.radius, 0.15);
  EXPECT_EQ(s.tank.height, 0.3);
  EXPECT_EQ(s.tank.length, 0.3);
  EXPECT_EQ(s.tank.breadth, 0.3);
  const CaseSpec again = read_case_text(resolved_case_toml(s), "resolved.toml", {});
  EXPECT_EQ(again.tank.shape, "cylinder");
  EXPECT_EQ(again.tank.radius, 0.15);
  EXPECT_EQ(again.tank.height, 0.3);
}

// Issue 31, section 3: the 2-DOF structure of a 3D case. [structure] is the sway along x,
// [structure.y] the sway along y with its own mass, stiffness (or frequency), damping (or ratio),
// initial state and load; the tanks, their rigid mass and the ground are [structure]'s. Exact
// values where no arithmetic is done; the resolved case reads back the same.
const std::string kTwoDof = R"(
[structure]
mass = 1000.0
stiffness = 4000.0
damping = 20.0
tanks = 2
rigid_mass = 5.0
ground = "excitation"

[structure.y]
mass = 500.0
frequency = 0.5
damping_ratio = 0.02
initial_displacement = 0.01

[structure.y.load]
type = "harmonic"
amplitude = 3.0
frequency = 0.4
)";

TEST(CaseReader, TwoDofStructureKeys) {
  const CaseSpec s = read_case_text(box3d_text() + kTwoDof, "case.toml", {});
  ASSERT_TRUE(s.structure && s.structure_y);
  EXPECT_EQ(s.structure->mass, 1000.0);
  EXPECT_EQ(s.structure->stiffness, 4000.0);
  EXPECT_EQ(s.structure->tanks, 2);
  EXPECT_EQ(s.structure_y->mass, 500.0);
  const double w = 2.0 * 3.141592653589793238 * 0.5;
  EXPECT_DOUBLE_EQ(s.structure_y->stiffness, 500.0 * w * w);
  EXPECT_DOUBLE_EQ(s.structure_y->damping, 2.0 * 0.02 * 500.0 * w);
  EXPECT_EQ(s.structure_y->initial_displacement, 0.01);
  EXPECT_EQ(s.structure_y->load.type, StructureLoadType::harmonic);
  EXPECT_EQ(s.structure_y->load.amplitude, 3.0);
  EXPECT_EQ(s.structure_y->tanks, 2);         // shared with [structure]
  EXPECT_EQ(s.structure_y->rigid_mass, 5.0);  // shared with [structure]
  EXPECT_TRUE(s.structure_y->ground_from_excitation);  // the harmonic of box3d_diagonal.toml
  EXPECT_EQ(s.structure->load.type, StructureLoadType::none);
  const std::string resolved = resolved_case_toml(s);
  EXPECT_EQ(resolved.find("tank_width"), std::string::npos);  // a 3D tank's forces are whole
  const CaseSpec again = read_case_text(resolved, "resolved.toml", {});
  ASSERT_TRUE(again.structure_y);
  EXPECT_EQ(again.structure_y->stiffness, s.structure_y->stiffness);
  EXPECT_EQ(again.structure_y->damping, s.structure_y->damping);
  EXPECT_EQ(again.structure_y->load.frequency, 0.4);
  EXPECT_EQ(again.structure_y->tanks, 2);
}

TEST(CaseReader, TwoDofStructureKeysAreChecked) {
  const std::string box = box3d_text();
  expect_error(kMinimal + kTwoDof, {}, "structure.y", "3D tanks");
  expect_error(box + kTwoDof, {"structure.tank_width=2.0"}, "structure.tank_width",
               "whole tank");
  expect_error(box + kTwoDof, {"structure.y.tanks=3"}, "structure.y.tanks",
               "belongs in [structure]");
  expect_error(box + kTwoDof, {"structure.y.ground=\"excitation\""},
               "structure.y.ground", "belongs in [structure]");
  expect_error(box + kTwoDof, {"structure.y.mass=-1.0"}, "structure.y.mass", "");
  expect_error(box + kTwoDof, {"structure.y.damping=1.0"}, "structure.y.damping_ratio",
               "only one");
  expect_error(box + kTwoDof, {"structure.y.load.type=\"noise\""},
               "structure.y.load.target_peak_mg", "");
  expect_error(box + kTwoDof, {"structure.y.colour=1.0"}, "structure.y.colour", "");
}

// Issue 31, section 3: [excitation.y], an independent motion of the base along y. Its keys are a
// translation's; its beta refers to the box's first mode across the breadth (exact: the closed form
// of the same function); the resolved case reads back the same.
TEST(CaseReader, ExcitationAlongYKeys) {
  const std::string text =
      box3d_text() + "\n[excitation.y]\ntype = \"harmonic\"\namplitude = 0.004\nbeta = 0.9\nramp = 1.0\n";
  const CaseSpec s = resolve_case(read_case_text(text, "case.toml", {"excitation.direction=[1.0, 0.0]"}));
  ASSERT_TRUE(s.excitation_y);
  EXPECT_EQ(s.excitation_y->type, ExcitationType::harmonic);
  EXPECT_EQ(s.excitation_y->amplitude, 0.004);
  EXPECT_EQ(s.excitation_y->direction.y, 1.0);
  EXPECT_EQ(s.excitation_y->omega, 0.9 * rectangular_sloshing_omega(0.2, 0.15, 9.81));
  EXPECT_EQ(s.excitation.type, ExcitationType::harmonic);  // the motion along x is kept
  const CaseSpec again = resolve_case(read_case_text(resolved_case_toml(s), "resolved.toml", {}));
  ASSERT_TRUE(again.excitation_y);
  EXPECT_EQ(again.excitation_y->omega, s.excitation_y->omega);
  EXPECT_EQ(again.excitation_y->ramp, 1.0);
  // Along y alone: [excitation] of type none with its y table survives the round trip too.
  CaseSpec without_x = s;
  without_x.excitation = ExcitationSpec{};
  const CaseSpec y_only = read_case_text(resolved_case_toml(without_x), "resolved.toml", {});
  EXPECT_EQ(y_only.excitation.type, ExcitationType::none);
  ASSERT_TRUE(y_only.excitation_y);
  EXPECT_EQ(y_only.excitation_y->amplitude, 0.004);
}

TEST(CaseReader, ExcitationAlongYKeysAreChecked) {
  const std::string y = "\n[excitation.y]\ntype = \"harmonic\"\namplitude = 0.004\nfrequency = 1.0\n";
  const std::string box = box3d_text() + y;
  expect_error(kMinimal + std::string("\n[excitation]\ntype = \"none\"\n") + y, {}, "excitation.y", "3D tanks");
  expect_error(box, {}, "excitation.direction", "motion along x");  // box3d_diagonal.toml's [2, 1]
  expect_error(box, {"excitation.direction=[1.0, 0.0]", "excitation.y.direction=[0.0, 1.0]"}, "excitation.y.direction",
               "along y");
  expect_error(box, {"excitation.direction=[1.0, 0.0]", "excitation.y.type=\"pitch\""}, "excitation.y.type",
               "translation");
  expect_error(box, {"excitation.direction=[1.0, 0.0]", "excitation.y.type=\"none\""}, "excitation.y.type",
               "translation");
  expect_error(box, {"excitation.direction=[1.0, 0.0]", "excitation.y.amplitude=-1.0"}, "excitation.y.amplitude", "");
  expect_error(box, {"excitation.direction=[1.0, 0.0]", "excitation.y.y={type=\"harmonic\"}"}, "excitation.y.y", "");
  // beta along y: a box's or a cylinder's first mode across the breadth ("thesis" is a 2D section's
  // closed form); a prism's section varies along x, so it needs 'frequency'.
  const std::string beta_y = box3d_text() + "\n[excitation.y]\ntype = \"harmonic\"\namplitude = 0.004\nbeta = 1.0\n";
  try {
    resolve_case(read_case_text(beta_y, "case.toml", {"excitation.direction=[1.0, 0.0]", "tank.shape=\"circular\""}));
    FAIL() << "beta along y accepted for a circular section";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "excitation.y.beta") << e.what();
    EXPECT_NE(std::string(e.what()).find("frequency"), std::string::npos) << e.what();
  }
  try {
    resolve_case(read_case_text(beta_y + "beta_reference = \"thesis\"\n", "case.toml", {"excitation.direction=[1.0, 0.0]"}));
    FAIL() << "beta_reference = thesis along y accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "excitation.y.beta_reference") << e.what();
  }
}

// 3D keys in a 2D case, and what 3D cannot do yet, are refused by name.
TEST(CaseReader, ThreeDimensionalKeysAreChecked) {
  expect_error(kMinimal, {"tank.breadth=0.2"}, "tank.breadth", "dimensions = 3");
  expect_error(kMinimal, {"excitation={type=\"harmonic\", amplitude=0.001, frequency=1.0, direction=[0.0, 1.0]}"},
               "excitation.direction", "3D tanks");
  const std::string box = box3d_text();
  expect_error(box, {"tank.breadth=0.03"}, "particles.dp", "breadth");
  expect_error(box, {"excitation.direction=[0.0, 0.0]"}, "excitation.direction", "not zero");
  expect_error(kMinimal, {"tank={shape=\"cylinder\", radius=0.2, height=0.4}"}, "tank.shape", "dimensions = 3");
  expect_error(box, {"tank={dimensions=3, shape=\"cylinder\", radius=0.2, height=0.4, breadth=0.4}"}, "tank.breadth",
               "radius and height");
  // Both schemes' repulsive walls read in 3D (what they do: RepulsiveWallsThreeD, Validation.RepulsiveWalls...).
  EXPECT_EQ(read_case_text(box, "case.toml", {"scheme={type=\"wcsph\", walls=\"repulsive\"}"}).scheme.wcsph.walls,
            WallTreatment::repulsive);
  EXPECT_TRUE(read_case_text(box, "case.toml", {"scheme.repulsive_walls=true"}).scheme.repulsive_walls);
  // A rotation in 3D: the pivot is [x, y, z], the axis not zero, and no translation's direction.
  expect_error(box, {"excitation={type=\"pitch\", angle=2.0, frequency=1.0, pivot=[0.2, 0.1]}"}, "excitation.pivot",
               "[x, y, z]");
  expect_error(box, {"excitation={type=\"pitch\", angle=2.0, frequency=1.0, pivot=[0.2, 0.1, 0.1], axis=[0.0, 0.0, 0.0]}"},
               "excitation.axis", "not zero");
  expect_error(box, {"excitation={type=\"pitch\", angle=2.0, frequency=1.0, pivot=[0.2, 0.1, 0.1], direction=[0.0, 1.0]}"},
               "excitation.direction", "axis");
  std::string with_face = box;
  with_face.replace(with_face.find("z = 0.005\n"), 10, "z = 0.005\nto = [0.2, 0.05]\n");
  expect_error(with_face, {}, "probes.pressure.0.to", "not available in 3D");
  // Explicit slats across the breadth read (their layout: ThreeD.ExplicitSlatsAcrossTheBreadth...).
  EXPECT_TRUE(read_case_text(box + "\n[[screens]]\nname = \"s\"\ny = 0.1\nslat_height = 0.01\nslat_gap = 0.01\n"
                                   "model = \"explicit\"\n",
                             "case.toml", {})
                  .screens.at(0)
                  .plane_y.has_value());
  // output.moment_point: [x, y, z] in 3D, [x, y] in 2D; written to case.toml only when given.
  EXPECT_EQ(read_case_text(box, "case.toml", {"output.moment_point=[0.1, 0.2, 0.3]"}).output.moment_point->z, 0.3);
  expect_error(box, {"output.moment_point=[0.1, 0.2]"}, "output.moment_point", "[x, y, z]");
  expect_error(kMinimal, {"output.moment_point=[0.1, 0.2, 0.3]"}, "output.moment_point", "[x, y]");
  EXPECT_EQ(resolved_case_toml(read_case_text(kMinimal, "case.toml", {})).find("moment_point"), std::string::npos);
  EXPECT_NE(resolved_case_toml(read_case_text(kMinimal, "case.toml", {"output.moment_point=[0.0, 0.0]"}))
                .find("moment_point = [ 0.0, 0.0 ]"),
            std::string::npos);
  // Screens through a segment of the plan (any angle): 3D, box or cylinder, porous or explicit, ends inside.
  const CaseSpec diagonal =
      read_case_text(box + "\n[[screens]]\nname = \"d\"\nplan_from = [0.0, 0.0]\nplan_to = [0.4, 0.2]\nsolidity = 0.4\n",
                     "case.toml", {});
  ASSERT_TRUE(diagonal.screens.at(0).plan.has_value());
  EXPECT_EQ(diagonal.screens.at(0).plan->second.x, 0.4);
  EXPECT_NE(resolved_case_toml(diagonal).find("plan_to"), std::string::npos);
  const std::string plan_screen = "\n[[screens]]\nname = \"d\"\nsolidity = 0.4\n";
  expect_error(box + plan_screen + "plan_from = [0.0, 0.0]\n", {}, "screens.0.plan_to", "both");
  expect_error(box + plan_screen + "plan_from = [0.0, 0.0]\nplan_to = [0.5, 0.2]\n", {}, "screens.0.plan_to",
               "inside the tank");
  expect_error(box + plan_screen + "plan_from = [0.0, 0.0]\nplan_to = [0.4, 0.2]\nx = 0.1\n", {}, "screens.0.x",
               "plan_from");
  EXPECT_EQ(read_case_text(box + plan_screen + "plan_from = [0.0, 0.0]\nplan_to = [0.4, 0.2]\nmodel = \"explicit\"\n"
                                                "slat_height = 0.01\nslat_gap = 0.01\n",
                           "case.toml", {})
                .screens.at(0)
                .model,
            ScreenModel::explicit_slats);
  expect_error(kMinimal + plan_screen + "plan_from = [0.0, 0.0]\nplan_to = [0.4, 0.2]\n", {}, "screens.0.plan_from",
               "3D");
  // Fill blocks in 3D: the section's rectangle over a box's or prism's breadth (settled depth from
  // the section's area, as in 2D), or in a cylinder over the chords of the circle, checked against
  // the rectangle 2R x height (the scene's particles: ThreeD.FillBlocksInACylinderHoldTheLatticeInsideTheCircle).
  // The front probe reads in 3D.
  const CaseSpec blocks = read_case_text(box + "\n[[fill.blocks]]\nfrom = [0.0, 0.0]\nto = [0.1, 0.2]\n"
                                               "[[probes.front]]\nname = \"tip\"\n", "case.toml", {});
  EXPECT_EQ(blocks.fill.blocks.size(), 1u);
  EXPECT_EQ(blocks.fronts.size(), 1u);
  const std::string round = read_case_file_text(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/cylinder3d_sloshing.toml");
  const std::string round_block = round + "\n[[fill.blocks]]\nfrom = [0.0, 0.0]\nto = [0.15, 0.1]\n";
  EXPECT_EQ(read_case_text(round_block, "case.toml", {}).fill.blocks.size(), 1u);
  expect_error(round_block, {"fill.blocks.0.to=[0.31, 0.1]"}, "fill.blocks.0.from", "outside the tank");
  expect_error(round_block, {"fill.blocks.0.to=[0.15, 0.3]"}, "fill.blocks.0.to", "top of the walls");
  // Screens in a cylinder (R = 0.15 m, dp = 10 mm): vertical planes x or y = const, porous or explicit,
  // at least dp inside the wall (their particles: ScreenDrag.ScreenInACylinderSpansTheChordOfItsPlane).
  const std::string cylinder = read_case_file_text(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/cylinder3d_sloshing.toml");
  const auto with_screen = [&cylinder](const std::string& keys) {
    return cylinder + "\n[[screens]]\nname = \"s\"\nsolidity = 0.4\n" + keys;
  };
  EXPECT_EQ(read_case_text(with_screen("x = 0.15\nmodel = \"morison\"\n"), "case.toml", {}).screens.size(), 1u);
  EXPECT_TRUE(read_case_text(with_screen("y = 0.1\n"), "case.toml", {}).screens.at(0).plane_y.has_value());
  EXPECT_EQ(read_case_text(with_screen("x = 0.15\nmodel = \"explicit\"\nslat_height = 0.01\nslat_gap = 0.01\n"),
                           "case.toml", {})
                .screens.at(0)
                .model,
            ScreenModel::explicit_slats);
  expect_error(with_screen("from = [0.1, 0.0]\nto = [0.2, 0.3]\n"), {}, "screens.0.from", "vertical plane");
  expect_error(with_screen("x = 0.005\n"), {}, "screens.0.x", "at least dp inside");
  expect_error(with_screen("y = 0.295\n"), {}, "screens.0.y", "at least dp inside");
  // In 3D a gauge needs its y, and a probe its z.
  expect_error(box + "\n[[probes.gauge]]\nname = \"h\"\nx = 0.1\n", {}, "probes.gauge.3.y", "");
  expect_error(box + "\n[[probes.pressure]]\nname = \"q\"\nx = 0.1\ny = 0.1\n", {}, "probes.pressure.2.z", "");
}

}  // namespace
}  // namespace sloshsph
