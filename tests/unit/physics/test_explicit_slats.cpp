// Explicit slat screens as wall particles (geometry/screens explicit_slat_layout).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/screens.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {
namespace {

TankGeometry rectangle(double length, double height) {
  TankSpec s;
  s.shape = "rectangle";
  s.length = length;
  s.height = height;
  return make_tank(s, "test");
}

// The thesis screens (2.6.3): h_slat = 5 mm, h_gap = 7 mm, t_sc = 1 mm.
ScreenSpec slat_screen(double x, double y0, double y1) {
  ScreenSpec s;
  s.name = "slats";
  s.model = ScreenModel::explicit_slats;
  s.from = {x, y0};
  s.to = {x, y1};
  s.slat_height = 0.005;
  s.slat_gap = 0.007;
  s.thickness = 0.001;
  return s;
}

// Solid length recovered from the particles alone: project them on the line, group runs whose
// neighbours are closer than `join`, and add up each run's extent plus one particle pitch.
double solid_length_from_particles(const SlatLayout& layout, double pitch, double join) {
  std::vector<double> s;
  for (const WallSample& w : layout.walls) s.push_back(dot(w.position - layout.line.from, layout.line.direction()));
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }), s.end());
  double total = 0.0, start = s.front();
  for (std::size_t k = 1; k <= s.size(); ++k)
    if (k == s.size() || s[k] - s[k - 1] > join) {
      total += s[k - 1] - start + pitch;
      if (k < s.size()) start = s[k];
    }
  return total;
}

// Full height 0.6 m = 50 periods of 12 mm, dp = 1 mm: 50 slats of 5 x 1 particles, gaps of 7 mm,
// and the solidity 5/12 recovered from the particle layout to round-off (1e-9): the particles
// tile each slat exactly (n_a = h_slat / dp), so the layout carries the exact solid length.
TEST(ExplicitSlats, ThesisScreenAtFineResolution) {
  const TankGeometry tank = rectangle(0.966, 0.6);
  const double dp = 0.001;
  const SlatLayout layout = explicit_slat_layout(slat_screen(0.5796, 0.0, 0.6), dp, tank, "case.toml", "screens.0");
  ASSERT_EQ(layout.slats.size(), 50u);
  EXPECT_EQ(layout.walls.size(), 50u * 5u);
  for (std::size_t k = 0; k < layout.slats.size(); ++k) {
    EXPECT_NEAR(layout.slats[k].first, 0.012 * k, 1e-12);
    EXPECT_NEAR(layout.slats[k].second - layout.slats[k].first, 0.005, 1e-12);
    if (k > 0) {
      EXPECT_NEAR(layout.slats[k].first - layout.slats[k - 1].second, 0.007, 1e-12);  // gap
    }
  }
  EXPECT_NEAR(layout.solidity, 5.0 / 12.0, 1e-12);
  EXPECT_NEAR(solid_length_from_particles(layout, dp, 1.5 * dp) / layout.line.length, 5.0 / 12.0, 1e-9);
  // The first slat starts at the floor: its first particle is dp/2 above it, on the centre line.
  EXPECT_NEAR(layout.walls.front().position.y, 0.0005, 1e-12);
  for (const WallSample& w : layout.walls) {
    EXPECT_NEAR(w.position.x, 0.5796, 1e-12);
    EXPECT_NEAR(norm(w.normal), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(w.normal.x), 1.0, 1e-12);  // thin slat: the across-thickness face is nearest
  }
  EXPECT_TRUE(layout.warnings.empty());
}

// Thicker slats: t_sc = 3 mm at dp = 1 mm gives 3 particle columns at x0 - 1 mm, x0, x0 + 1 mm, the
// outer ones with normals across the slat (outward), every normal a unit vector.
TEST(ExplicitSlats, ThicknessDiscretisedAtDp) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  ScreenSpec s = slat_screen(0.5, 0.0, 0.12);
  s.thickness = 0.003;
  const SlatLayout layout = explicit_slat_layout(s, 0.001, tank, "case.toml", "screens.0");
  ASSERT_EQ(layout.slats.size(), 10u);
  EXPECT_EQ(layout.walls.size(), 10u * 5u * 3u);
  int left = 0, middle = 0, right = 0;
  for (const WallSample& w : layout.walls) {
    EXPECT_NEAR(norm(w.normal), 1.0, 1e-12);
    if (std::abs(w.position.x - 0.499) < 1e-12) {
      ++left;
      EXPECT_GT(w.normal.x * (w.position.x - 0.5), 0.0);  // outward
    } else if (std::abs(w.position.x - 0.5) < 1e-12) {
      ++middle;
    } else if (std::abs(w.position.x - 0.501) < 1e-12) {
      ++right;
      EXPECT_GT(w.normal.x * (w.position.x - 0.5), 0.0);
    }
  }
  EXPECT_EQ(left, 50);
  EXPECT_EQ(middle, 50);
  EXPECT_EQ(right, 50);
}

// A line that ends inside a slat: 0.1 m = 8 periods + 4 mm, so 9 slats, the last one cut to 4 mm.
// The layout solidity is then (8 x 5 + 4) / 100 = 0.44 (exact).
TEST(ExplicitSlats, LastSlatCutAtTheEnd) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  const SlatLayout layout = explicit_slat_layout(slat_screen(0.5, 0.0, 0.1), 0.001, tank, "case.toml", "screens.0");
  ASSERT_EQ(layout.slats.size(), 9u);
  EXPECT_NEAR(layout.slats.back().second - layout.slats.back().first, 0.004, 1e-12);
  EXPECT_NEAR(layout.solidity, 0.44, 1e-12);
}

// Coarse resolution (dp = 5 mm, the thesis ER resolution): the slats are thinner than dp and the gaps
// narrower than 2 dp, and the layout says so. Each slat is then one particle; the solidity of the
// layout is still 5/12 (it is the geometric one), but the particles' kernels close the gaps.
TEST(ExplicitSlats, WarnsWhenDpIsTooCoarse) {
  const TankGeometry tank = rectangle(0.966, 0.6);
  const SlatLayout layout = explicit_slat_layout(slat_screen(0.5, 0.0, 0.12), 0.005, tank, "case.toml", "screens.2");
  EXPECT_EQ(layout.walls.size(), 10u);
  ASSERT_EQ(layout.warnings.size(), 2u);
  EXPECT_NE(layout.warnings[0].find("screens.2.thickness"), std::string::npos);
  EXPECT_NE(layout.warnings[1].find("screens.2.slat_gap"), std::string::npos);
  // The convenience overload returns the same particles.
  EXPECT_EQ(explicit_slat_walls(slat_screen(0.5, 0.0, 0.12), 0.005, tank).size(), 10u);
}

// Slats clipped to the tank like the porous elements; bad sizes name their key.
TEST(ExplicitSlats, ClippingAndErrors) {
  const TankGeometry tank = rectangle(1.0, 0.6);
  const SlatLayout layout = explicit_slat_layout(slat_screen(0.5, -0.1, 0.9), 0.001, tank, "case.toml", "screens.0");
  EXPECT_NEAR(layout.line.length, 0.6, 1e-9);
  EXPECT_EQ(layout.slats.size(), 50u);

  auto key = [&](const ScreenSpec& s) {
    try {
      explicit_slat_layout(s, 0.001, tank, "case.toml", "screens.4");
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "case.toml");
      return e.key();
    }
    return std::string();
  };
  ScreenSpec s = slat_screen(0.5, 0.0, 0.6);
  s.slat_gap = 0.0;
  EXPECT_EQ(key(s), "screens.4.slat_gap");
  s = slat_screen(0.5, 0.0, 0.6);
  s.slat_height = 0.0;
  EXPECT_EQ(key(s), "screens.4.slat_height");
  s = slat_screen(0.5, 0.0, 0.6);
  s.thickness = 0.0;
  EXPECT_EQ(key(s), "screens.4.thickness");
  EXPECT_EQ(key(slat_screen(1.2, 0.0, 0.6)), "screens.4.from");
}

}  // namespace
}  // namespace sloshsph
