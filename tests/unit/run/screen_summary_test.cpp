// summary.json's `screens` block (run/screen_summary): one object per element with the closure's
// parameters and the loss coefficient each closure stands for.
#include <gtest/gtest.h>

#include <vector>

#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/physics/porous.hpp"
#include "sloshsph/run/screen_summary.hpp"

namespace sloshsph {
namespace {

ScreenSpec screen(const char* name, ScreenModel model, double x) {
  ScreenSpec s;
  s.name = name;
  s.model = model;
  s.from = {x, 0.0};
  s.to = {x, 0.5};
  s.solidity = 5.0 / 12.0;  // Tait et al. (2005): 5 mm slats, 7 mm gaps
  s.thickness = 0.001;
  s.slat_height = 0.005;
  s.slat_gap = 0.007;
  return s;
}

// The Tait tank's screen (S = 5/12, t = 1 mm) at dp = 7 mm in the three models. Expected values
// from the closed forms of physics/porous (their own tests check them by hand), so this checks
// which number lands under which key: n = 7/12, D_c = dp = 7 mm, C_E = 3.5 t (1 - n)/(n^3 D_c) =
// 1.0496 by hand (1.4583e-3 / (0.198495 x 0.007)), Baines & Peterson C_l(5/12) = 2.0556 (test_porous_formulas); 1e-4 relative.
TEST(ScreenSummary, KeysPerModel) {
  TankSpec t;
  t.shape = "rectangle";
  t.length = 1.0;
  t.height = 0.5;
  const TankGeometry tank = make_tank(t, "test");
  const std::vector<ScreenSpec> specs = {screen("E", ScreenModel::ergun, 0.3), screen("M", ScreenModel::morison, 0.5),
                                         screen("X", ScreenModel::explicit_slats, 0.7)};
  const double dp = 0.007;
  const nlohmann::json j = screens_summary(make_screen_particles(specs, dp, 1.4 * dp, tank, "case.toml").elements);
  ASSERT_EQ(j.size(), 3u);

  const nlohmann::json& e = j[0];
  EXPECT_EQ(e["name"], "E");
  EXPECT_EQ(e["model"], "ergun");
  EXPECT_NEAR(e["porosity"].get<double>(), 7.0 / 12.0, 1e-12);
  EXPECT_NEAR(e["length_m"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(e["grain_diameter_m"].get<double>(), dp, 1e-15);
  EXPECT_NEAR(e["equivalent_loss_coefficient"].get<double>(), 1.0496, 1e-4 * 1.0496);
  EXPECT_NEAR(e["slat_screen_loss_coefficient"].get<double>(), 2.0556, 1e-4 * 2.0556);
  EXPECT_EQ(e["screen_particles"], 72);  // ceil(0.5 / 0.007)
  EXPECT_EQ(e["velocity"], "thesis");
  EXPECT_FALSE(e.contains("loss_coefficient"));

  const nlohmann::json& m = j[1];
  EXPECT_EQ(m["model"], "morison");
  EXPECT_NEAR(m["loss_coefficient"].get<double>(), 2.0556, 1e-4 * 2.0556);  // C_l from S when not given
  EXPECT_FALSE(m.contains("equivalent_loss_coefficient"));

  const nlohmann::json& x = j[2];
  EXPECT_EQ(x["model"], "explicit");
  EXPECT_FALSE(x.contains("screen_particles"));  // walls, not screen particles
  EXPECT_TRUE(x.contains("slat_screen_loss_coefficient"));
}

}  // namespace
}  // namespace sloshsph
