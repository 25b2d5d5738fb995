// [structure] and [structure.load] in case files (io/case_reader.cpp): values, defaults, and
// errors naming the file and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "coupling_test_cases.hpp"
#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/case_reader.hpp"

namespace sloshsph {
namespace {

using test::small_tank_case;

void expect_error(const std::string& text, const std::string& key, const std::string& fragment) {
  try {
    read_case_text(text, "case.toml");
    FAIL() << "no error; expected one naming " << key;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), key) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
    EXPECT_NE(what.find("case.toml"), std::string::npos) << what;
  }
}

TEST(StructureCase, IssueKeysAndDefaults) {
  // The key names fixed by issue 5, with the thesis 4.4.2.2 building.
  const CaseSpec s = read_case_text(small_tank_case(R"(
[structure]
mass = 7.0e7
stiffness = 4.96e7
damping = 1.18e6

[structure.load]
type = "harmonic"
amplitude = 1.0e5
frequency = 0.134
)"),
                                    "case.toml");
  ASSERT_TRUE(s.structure);
  const StructureSpec& st = *s.structure;
  EXPECT_DOUBLE_EQ(st.mass, 7.0e7);
  EXPECT_DOUBLE_EQ(st.stiffness, 4.96e7);
  EXPECT_DOUBLE_EQ(st.damping, 1.18e6);
  EXPECT_DOUBLE_EQ(st.tank_width, 1.0);
  EXPECT_EQ(st.tanks, 1);
  EXPECT_DOUBLE_EQ(st.rigid_mass, 0.0);
  EXPECT_FALSE(st.ground_from_excitation);
  EXPECT_EQ(st.load.type, StructureLoadType::harmonic);
  EXPECT_DOUBLE_EQ(st.load.amplitude, 1.0e5);
  EXPECT_DOUBLE_EQ(st.load.frequency, 0.134);
  EXPECT_EQ(s.excitation.type, ExcitationType::none);
}

TEST(StructureCase, FrequencyAndDampingRatio) {
  // K = M (2 pi f)^2, C = 2 zeta M (2 pi f): exact to rounding.
  const CaseSpec s = read_case_text(small_tank_case(R"(
[structure]
mass = 7.0e7
frequency = 0.134
damping_ratio = 0.01
tank_width = 10.0
tanks = 3
)"),
                                    "case.toml");
  const double w = 2.0 * std::numbers::pi * 0.134;
  EXPECT_NEAR(s.structure->stiffness, 7.0e7 * w * w, 1e-6 * 7.0e7 * w * w);
  EXPECT_NEAR(s.structure->damping, 2.0 * 0.01 * 7.0e7 * w, 1e-9 * 7.0e7 * w);
  EXPECT_EQ(s.structure->tanks, 3);
  EXPECT_DOUBLE_EQ(s.structure->tank_width, 10.0);
  EXPECT_EQ(s.structure->load.type, StructureLoadType::none);
}

TEST(StructureCase, NoiseLoadKeys) {
  const CaseSpec s = read_case_text(small_tank_case(R"(
[structure]
mass = 7.0e7
stiffness = 4.96e7
damping = 1.18e6
tanks = 0

[structure.load]
type = "noise"
seed = 7
target_peak_mg = 10.0
)"),
                                    "case.toml");
  const StructureLoadSpec& l = s.structure->load;
  EXPECT_EQ(l.type, StructureLoadType::noise);
  EXPECT_EQ(l.seed, 7u);
  EXPECT_DOUBLE_EQ(l.band_low, 0.05);  // thesis 4.4.2.1 band by default
  EXPECT_DOUBLE_EQ(l.band_high, 0.5);
  EXPECT_DOUBLE_EQ(*l.target_peak_mg, 10.0);
  EXPECT_FALSE(l.rms);
  EXPECT_DOUBLE_EQ(l.peak_duration, 3600.0);
  EXPECT_EQ(s.structure->tanks, 0);
}

TEST(StructureCase, ResolvedCaseReadsBackTheSame) {
  const CaseSpec s = read_case_text(small_tank_case(R"(
[structure]
mass = 20.0
frequency = 0.7
damping_ratio = 0.02
rigid_mass = 3.5
initial_displacement = 0.01

[structure.load]
type = "pulse"
shape = "cosine"
amplitude = 5.0
period = 0.5
start = 0.1
)"),
                                    "case.toml");
  const CaseSpec r = read_case_text(resolved_case_toml(s), "resolved.toml");
  ASSERT_TRUE(r.structure);
  EXPECT_DOUBLE_EQ(r.structure->stiffness, s.structure->stiffness);
  EXPECT_DOUBLE_EQ(r.structure->damping, s.structure->damping);
  EXPECT_DOUBLE_EQ(r.structure->rigid_mass, 3.5);
  EXPECT_DOUBLE_EQ(r.structure->initial_displacement, 0.01);
  EXPECT_EQ(r.structure->load.type, StructureLoadType::pulse);
  EXPECT_EQ(r.structure->load.shape, "cosine");
  EXPECT_DOUBLE_EQ(r.structure->load.period, 0.5);
  EXPECT_DOUBLE_EQ(r.structure->load.start, 0.1);
}

TEST(StructureCase, Errors) {
  const std::string mk = "[structure]\nmass = 1.0e3\n";
  expect_error(small_tank_case("[structure]\nstiffness = 1.0\ndamping = 0.0\n"), "structure.mass", "required");
  expect_error(small_tank_case(mk + "damping = 1.0\n"), "structure.stiffness", "'frequency'");
  expect_error(small_tank_case(mk + "stiffness = 1.0\nfrequency = 1.0\ndamping = 1.0\n"), "structure.frequency",
               "only one");
  expect_error(small_tank_case(mk + "stiffness = 1.0\n"), "structure.damping", "damping_ratio");
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 1.0\ndamping_ratio = 0.01\n"),
               "structure.damping_ratio", "only one");
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 1.0\ntanks = -1\n"), "structure.tanks", "");
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 1.0\nmasss = 2.0\n"), "structure.masss", "unknown");
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 1.0\n[structure.load]\ntype = \"noise\"\n"),
               "structure.load.target_peak_mg", "rms");
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 1.0\n[structure.load]\ntype = \"noise\"\n"
                                    "target_peak_mg = 10.0\nrms = 1.0\n"),
               "structure.load.rms", "only one");
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 0.0\n[structure.load]\ntype = \"noise\"\n"
                                    "target_peak_mg = 10.0\n"),
               "structure.load.target_peak_mg", "undamped");
  // A key of another load type is unknown.
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 1.0\n[structure.load]\ntype = \"harmonic\"\n"
                                    "amplitude = 1.0\nfrequency = 1.0\nseed = 3\n"),
               "structure.load.seed", "unknown");
  expect_error(small_tank_case(mk + "stiffness = 1.0\ndamping = 1.0\n[structure.load]\ntype = \"record\"\n"
                                    "file = \"no_such_force.csv\"\n"),
               "structure.load.file", "no such file");
}

TEST(StructureCase, ExcitationOnlyAsGroundMotion) {
  const std::string structure = "[structure]\nmass = 1.0e3\nstiffness = 1.0e4\ndamping = 10.0\n";
  const std::string harmonic = "[excitation]\ntype = \"harmonic\"\namplitude = 0.001\nfrequency = 1.0\n";
  // An imposed tank motion and a structure carrying the tank cannot both hold.
  expect_error(small_tank_case(structure + harmonic), "excitation.type", "structure.ground");
  // As the ground motion under the structure it is accepted.
  const CaseSpec s = read_case_text(small_tank_case(structure + "ground = \"excitation\"\n" + harmonic), "case.toml");
  EXPECT_TRUE(s.structure->ground_from_excitation);
  EXPECT_EQ(s.excitation.type, ExcitationType::harmonic);
  // Ground motion needs an excitation, and a pitch is not a ground translation.
  expect_error(small_tank_case(structure + "ground = \"excitation\"\n"), "structure.ground", "no [excitation]");
  expect_error(small_tank_case(structure + "ground = \"excitation\"\n" +
                               "[excitation]\ntype = \"pitch\"\nangle = 1.0\npivot = [0.05, 0.0]\nfrequency = 1.0\n"),
               "excitation.type", "pitch");
}

}  // namespace
}  // namespace sloshsph
