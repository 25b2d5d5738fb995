// `sloshsph linear` as data (run/linear_case): which screens of a case the linear model takes and
// with which loss law, and its frequency response.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/physics/porous.hpp"
#include "sloshsph/run/linear_case.hpp"
#include "sloshsph/run/simulation.hpp"

namespace sloshsph {
namespace {

std::string tait_case() { return std::string(SLOSHSPH_SOURCE_DIR) + "/cases/tait2005_screens.toml"; }

CaseSpec tait(const std::vector<std::string>& sets) { return resolve_case(read_case_file(tait_case(), sets)); }

// The two Ergun screens of cases/tait2005_screens.toml (S = 0.333 at 0.4 L and 0.6 L, full height,
// t and D_c as the case and the SPH element have them): over the whole still depth, with the
// inertial coefficient and Darcy term of their Ergun equation (physics/porous.hpp).
TEST(LinearCase, TakesTheCasesVerticalScreensWithTheirErgunLaw) {
  const CaseSpec spec = tait({"time.end=1.0"});
  const LinearCase r = linear_case_response(spec, {});
  ASSERT_EQ(r.screens.size(), 2u);
  const ScreenSpec& sc = spec.screens.at(0);
  const double porosity = 1.0 - sc.solidity;
  const double grain = sc.spacing > 0.0 ? sc.spacing : spec.particles.dp;
  const double permeability = kozeny_carman_permeability(porosity, grain);
  EXPECT_DOUBLE_EQ(r.screens[0].loss_coefficient, ergun_inertial_loss_coefficient(permeability, porosity, sc.thickness));
  EXPECT_DOUBLE_EQ(r.screens[0].linear_resistance, sc.thickness * 1000.0 * spec.fluid.viscosity / permeability);
  EXPECT_NEAR(r.screens[0].x, 0.4 * spec.tank.length, 1e-9);
  EXPECT_NEAR(r.screens[1].x, 0.6 * spec.tank.length, 1e-9);
  EXPECT_EQ(r.screens[0].z_from, 0.0);
  EXPECT_EQ(r.screens[0].z_to, spec.fill.depth);
  EXPECT_TRUE(r.ignored.empty());
  // Morison with a given C_l, and slat screens of solidity S: Baines & Peterson's C_l.
  const LinearCase morison = linear_case_response(
      tait({"time.end=1.0", "screens.0.model=\"morison\"", "screens.0.loss_coefficient=2.5"}), {});
  EXPECT_EQ(morison.screens.at(0).loss_coefficient, 2.5);
  EXPECT_EQ(morison.screens.at(0).linear_resistance, 0.0);
  // --screens none: a clean tank, the screens named as left out.
  LinearCaseOptions clean;
  clean.screens = false;
  const LinearCase none = linear_case_response(spec, clean);
  EXPECT_TRUE(none.screens.empty());
  ASSERT_EQ(none.ignored.size(), 1u);
  EXPECT_NE(none.ignored[0].find("screens"), std::string::npos);
}

// The frequency response at beta = 0.8 and 1.0: omega = beta omega_1 of the case's reference; the
// screens at least halve the resonant wave of the clean tank (whose boundary layers alone damp it
// at 0.15% of critical) and take energy from the flow.
TEST(LinearCase, FrequencyResponseOfTheScreenedTank) {
  const std::vector<std::string> sets = {"time.end=60.0"};
  LinearCaseOptions clean;
  clean.screens = false;
  const auto with = linear_frequency_response(tait_case(), sets, {0.8, 1.0}, {}).points;
  const auto without = linear_frequency_response(tait_case(), sets, {0.8, 1.0}, clean).points;
  ASSERT_EQ(with.size(), 2u);
  const double omega_ref = tait(sets).excitation.omega / 1.01;  // the case's own beta is 1.01
  EXPECT_NEAR(with[1].omega, omega_ref, 1e-9 * omega_ref);
  EXPECT_NEAR(with[0].omega, 0.8 * omega_ref, 1e-9 * omega_ref);
  auto height = [](const LinearFrequencyPoint& p) {
    const ResponseValue* v = p.response.find("eta:right");
    return v ? v->avg_max - v->avg_min : NAN;
  };
  EXPECT_LT(height(with[1]), 0.5 * height(without[1]));
  EXPECT_GT(with[1].response.energy_per_cycle.value_or(0.0), 0.0);
}

}  // namespace
}  // namespace sloshsph
