// Tuning a tank to a target first sloshing frequency (linear/tuning).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/linear/rectangular.hpp"
#include "sloshsph/linear/tuning.hpp"
#include "validation_check.hpp"

namespace sloshsph {
namespace {

constexpr double kG = 9.81;

TankGeometry tank(const std::string& shape, double length, double height, double angle = 45.0) {
  TankSpec s;
  s.shape = shape;
  s.length = length;
  s.height = height;
  s.coefficient = 1.0;
  s.angle = angle;
  return make_tank(s, "test");
}

TEST(Tuning, RectangleMatchesTheInverseTanhFormula) {
  // Reference: rectangular_depth_for_omega (inverse of eq. 4.29). Tolerance 0.5% (task);
  // the solver's omega_1 error (< 1e-5) moves the depth by far less.
  const TankGeometry t = tank("rectangle", 1.0, 0.5);
  for (double omega : {2.5, 3.5, 4.43}) {
    const double exact = rectangular_depth_for_omega(1.0, omega, kG);
    const double depth = depth_for_omega(t, omega, kG);
    std::printf("  rectangle L = 1 m, omega = %.2f rad/s: depth %.6f m, exact %.6f m\n", omega, depth, exact);
    EXPECT_NEAR(depth, exact, 0.005 * exact);
  }
}

TEST(Tuning, RightAngledVHasDepthGOverOmegaSquared) {
  // 45-degree V: omega_1^2 = g / h exactly (Lamb sec. 258), so h = g / omega^2; 0.5%.
  const TankGeometry v = tank("sloped", 1.0, 0.5);
  for (double omega : {4.43, 7.0, 11.909}) {
    const double depth = depth_for_omega(v, omega, kG);
    EXPECT_NEAR(depth, kG / (omega * omega), 0.005 * kG / (omega * omega)) << omega;
  }
}

TEST(Tuning, TunedTankReportsAreaAndWidth) {
  // m_w = rho B A by definition; the tuned omega is the target (to the solver's tolerance).
  const TankGeometry c = tank("circular", 1.1, 0.55);
  const TunedTank t = tune_for_omega(c, 4.43, kG, 100.0, 1000.0);
  EXPECT_NEAR(t.omega, 4.43, 1e-6 * 4.43);
  EXPECT_NEAR(t.area, section_area(c, t.depth), 1e-12);
  ASSERT_TRUE(t.width.has_value());
  EXPECT_NEAR(*t.width * 1000.0 * t.area, 100.0, 1e-9);
  const TunedTank no_mass = tune_for_omega(c, 4.43, kG, std::nullopt, 1000.0);
  EXPECT_FALSE(no_mass.width.has_value());
}

TEST(Tuning, UnreachableTargetIsAnInputError) {
  // A rectangle L = 1 m cannot exceed sqrt(pi g / L) = 5.55 rad/s (deep-water limit).
  const TankGeometry t = tank("rectangle", 1.0, 0.5);
  try {
    (void)depth_for_omega(t, 6.0, kG);
    ADD_FAILURE() << "6 rad/s accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "target_omega");
  }
}

TEST(Tuning, Table36DepthsForTheTargetFrequency) {
  // Thesis Table 3.6: every tank tuned to 4.43 rad/s with m_w = 100 kg (depths printed to
  // 0.01 m, widths B to 0.01 m). Our tuned depth (exact linear theory, the modal solver) and
  // width B = m_w / (rho A) beside the table's, on the validation page. Asserted only where
  // theory fixes the answer (flat: the inverse of eq. 4.29; 45-degree V: g / omega^2, Lamb
  // sec. 258), within 0.5% (issue). The table's own values are recorded, not asserted, with
  // half a printed unit (0.005 m) as the bar: the thesis tuned with its long-wave forms, which
  // overestimate omega_1 for sloped and parabolic sections (4-17%), so its depths are not
  // expected to be ours there. The table's sloped tank (L_fluid = 0.72 m at h = 0.18 m) has
  // slopes of 1:2 (26.6 degrees), not 45 degrees; both are shown.
  struct Row {
    const char* name;
    TankGeometry tank;
    double table_depth, table_width;
  };
  const double slope_1_2 = std::atan(0.5) * 180.0 / std::numbers::pi;
  const Row rows[] = {{"flat, L = 1 m", tank("rectangle", 1.0, 0.5), 0.24, 0.42},
                      {"V of 45 degrees, L = 1 m", tank("sloped", 1.0, 0.5), 0.18, 1.54},
                      {"V of slopes 1:2, L = 1 m (Table 3.6's geometry)", tank("sloped", 1.0, 0.27, slope_1_2), 0.18,
                       1.54},
                      {"parabolic, L = 1.41 m", tank("parabolic", 1.41, 0.5), 0.25, 0.60},
                      {"circular, L = 1.1 m", tank("circular", 1.1, 0.55), 0.25, 0.65}};
  const std::string source = "thesis Table 3.6 (printed to 0.01 m; the thesis tuned with its long-wave closed forms)";
  for (const Row& r : rows) {
    try {
      const TunedTank t = tune_for_omega(r.tank, 4.43, kG, 100.0, 1000.0);
      std::printf("  %-48s depth %.4f m (Table 3.6: %.2f), B %.3f m (Table 3.6: %.2f)\n", r.name, t.depth,
                  r.table_depth, *t.width, r.table_width);
      for (const auto& [what, measured, reference] :
           {std::tuple{"fill depth", t.depth, r.table_depth}, std::tuple{"tank width B for 100 kg", *t.width, r.table_width}}) {
        testing::check(testing::Check{.quantity = std::string(what) + " tuned to 4.43 rad/s (modal), " + r.name,
                                      .unit = "m",
                                      .measured = measured,
                                      .kind = testing::Tolerance::absolute,
                                      .reference = reference,
                                      .tolerance = 0.005,
                                      .source = source,
                                      .asserted = false});
      }
    } catch (const InputError& e) {
      // Exact theory can make a section untunable (the parabola: omega_1 below 4.43 at every depth).
      std::printf("  %-48s unreachable (%s), Table 3.6: %.2f m\n", r.name, e.what(), r.table_depth);
      testing::check(testing::Check{.quantity = std::string("fill depth tuned to 4.43 rad/s (modal), ") + r.name +
                                                " (unreachable: no depth reaches 4.43 rad/s)",
                                    .unit = "m",
                                    .measured = NAN,
                                    .kind = testing::Tolerance::absolute,
                                    .reference = r.table_depth,
                                    .tolerance = 0.005,
                                    .source = source,
                                    .asserted = false});
    }
  }
  const double flat = rectangular_depth_for_omega(1.0, 4.43, kG);
  testing::check_relative("fill depth tuned to 4.43 rad/s, flat, L = 1 m", depth_for_omega(rows[0].tank, 4.43, kG),
                          flat, 0.005, "inverse of eq. 4.29 (tanh dispersion)", "m");
  const double v45 = kG / (4.43 * 4.43);
  testing::check_relative("fill depth tuned to 4.43 rad/s, V of 45 degrees", depth_for_omega(rows[1].tank, 4.43, kG),
                          v45, 0.005, "g / omega^2 (Lamb, Hydrodynamics, sec. 258)", "m");
}

}  // namespace
}  // namespace sloshsph
