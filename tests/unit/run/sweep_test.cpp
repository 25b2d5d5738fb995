// The plan of a sweep (run/sweep.hpp): frequency ratios times the values of ranged --set keys.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"
#include "sloshsph/run/sweep.hpp"

namespace sloshsph {
namespace {

CaseSpec default_case() { return resolve_case(read_case_text(default_case_text(), "<default>", {})); }

TEST(SweepSets, RangesAndListsBecomeAxesOtherValuesStayFixed) {
  const SweepSets s = split_sweep_sets({"fill.depth=0.1:0.2:3", "time.end=2", "probes.gauge.0.x=[0.1, 0.2]",
                                        "screens.0.model=\"ergun\",\"morison\"", "name=\"a,b\"",
                                        "excitation.amplitude=0.003, 0.006"});
  ASSERT_EQ(s.axes.size(), 3u);
  EXPECT_EQ(s.axes[0].key, "fill.depth");
  EXPECT_EQ(s.axes[0].values, (std::vector<std::string>{"0.1", "0.15", "0.2"}));
  EXPECT_EQ(s.axes[1].key, "screens.0.model");
  EXPECT_EQ(s.axes[1].values, (std::vector<std::string>{"\"ergun\"", "\"morison\""}));
  EXPECT_EQ(s.axes[2].values, (std::vector<std::string>{"0.003", "0.006"}));
  // An array, a quoted string with a comma and a plain value hold for every point.
  EXPECT_EQ(s.fixed, (std::vector<std::string>{"time.end=2", "probes.gauge.0.x=[0.1, 0.2]", "name=\"a,b\""}));
}

TEST(SweepSets, BadRangesAreInputErrors) {
  EXPECT_THROW(split_sweep_sets({"fill.depth=0.1:0.2:0"}), InputError);    // no points
  EXPECT_THROW(split_sweep_sets({"fill.depth=0.1:0.2:2.5"}), InputError);  // N not whole
  EXPECT_THROW(split_sweep_sets({"fill.depth=0.1,,0.2"}), InputError);     // an empty value
  EXPECT_THROW(split_sweep_sets({"fill.depth=0.1,0.2", "fill.depth=0.3:0.4:2"}), InputError);  // swept twice
  try {
    split_sweep_sets({"fill.depth=0.1:0.2:x"});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "fill.depth");
  }
}

TEST(SweepPlan, EveryBetaTimesEveryValueFirstAxisSlowest) {
  const CaseSpec spec = default_case();
  const SweepSets s = split_sweep_sets({"fill.depth=0.12,0.14", "excitation.amplitude=0.003:0.006:2"});
  const std::vector<SweepPoint> points = plan_sweep(spec, {0.9, 1.1}, s.axes, "/tmp/sweep");
  ASSERT_EQ(points.size(), 8u);
  EXPECT_EQ(points[0].label, "beta_0.9000__fill.depth_0.12__excitation.amplitude_0.003");
  EXPECT_EQ(points[1].label, "beta_0.9000__fill.depth_0.12__excitation.amplitude_0.006");
  EXPECT_EQ(points[2].label, "beta_0.9000__fill.depth_0.14__excitation.amplitude_0.003");
  EXPECT_EQ(points[7].label, "beta_1.1000__fill.depth_0.14__excitation.amplitude_0.006");
  EXPECT_EQ(points[7].directory, "/tmp/sweep/" + points[7].label);
  ASSERT_EQ(points[7].overrides.size(), 3u);  // the frequency first, then the axes in order
  EXPECT_EQ(points[7].overrides[1], "fill.depth=0.14");
  EXPECT_EQ(points[7].overrides[2], "excitation.amplitude=0.006");
  EXPECT_EQ(points[7].axis_values, (std::vector<std::string>{"0.14", "0.006"}));
  EXPECT_DOUBLE_EQ(points[7].beta, 1.1);
}

TEST(SweepPlan, WithoutBetaThePointsKeepTheCasesFrequency) {
  const CaseSpec spec = default_case();
  const SweepSets s = split_sweep_sets({"excitation.amplitude=0.003,0.006"});
  const std::vector<SweepPoint> points = plan_sweep(spec, {}, s.axes, "out");
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].label, "excitation.amplitude_0.003");
  EXPECT_EQ(points[0].overrides, (std::vector<std::string>{"excitation.amplitude=0.003"}));
  EXPECT_TRUE(std::isnan(points[0].beta));  // filled in from each point's case by the command
  EXPECT_NEAR(excitation_beta(spec), 1.0, 1e-12);  // the default case is shaken at resonance
  EXPECT_THROW(plan_sweep(spec, {}, {}, "out"), InputError);  // nothing to sweep
}

}  // namespace
}  // namespace sloshsph
