// Tank sections (geometry/tank): shapes, wall sampling, fluid fill, still-water polygon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

TankSpec rectangle_spec(double length, double height) {
  TankSpec s;
  s.shape = "rectangle";
  s.length = length;
  s.height = height;
  return s;
}

TankSpec parabolic_spec(double length, double height, double coefficient) {
  TankSpec s = rectangle_spec(length, height);
  s.shape = "parabolic";
  s.coefficient = coefficient;
  return s;
}

TankSpec circular_spec(double length, double height) {
  TankSpec s = rectangle_spec(length, height);
  s.shape = "circular";
  return s;
}

TankSpec sloped_spec(const std::string& shape, double length, double height, double angle, double bottom_width) {
  TankSpec s = rectangle_spec(length, height);
  s.shape = shape;
  s.angle = angle;
  s.bottom_width = bottom_width;
  return s;
}

TankSpec polyline_spec(std::vector<Vec2> points) {
  TankSpec s;
  s.shape = "polyline";
  s.points = std::move(points);
  return s;
}

// One shape with a fill depth, and the exact area of its section below that depth.
struct ShapeCase {
  std::string name;
  TankSpec spec;
  double depth;
  double exact_area;  // m^2, closed form (or the polygon itself for the polyline)
};

double circle_segment_area(double r, double h) {
  return r * r * std::acos((r - h) / r) - (r - h) * std::sqrt(2.0 * r * h - h * h);
}

std::vector<ShapeCase> shape_cases() {
  const double t26 = std::atan(0.5) * 180.0 / kPi;  // Table 3.5/3.6 sloped tank: slope 1:2
  // Skewed polyline: exact area by the shoelace formula of the section below y = 0.3, with
  // the crossings worked out by hand: (0.1 + 0.15 * 0.05 / 0.35, 0.3) and (1, 0.3).
  const std::vector<Vec2> skew{{0.0, 0.5}, {0.1, 0.35}, {0.25, 0.0}, {0.7, 0.05}, {1.0, 0.25}, {1.0, 0.5}};
  const std::vector<Vec2> ring{{0.1 + 0.15 * 0.05 / 0.35, 0.3}, {0.25, 0.0}, {0.7, 0.05}, {1.0, 0.25}, {1.0, 0.3}};
  double area2 = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) area2 += cross(ring[k], ring[(k + 1) % ring.size()]);
  return {
      {"rectangle", rectangle_spec(1.0, 0.5), 0.25, 0.25},
      // Table 3.6 parabolic tank: y = (x - 0.705)^2, walls of 3 mm above x = 0, 1.41.
      {"parabolic_t36", parabolic_spec(1.41, 0.5, 1.0), 0.25, 4.0 / 3.0 * 0.25 * 0.5},
      // Table 3.9: L = 1, the parabola meets the walls at 0.25 m; filled to 0.4 m (walls wetted).
      {"parabolic_walls", parabolic_spec(1.0, 0.5, 1.0), 0.4, 4.0 / 3.0 * 0.25 * 0.5 + 0.15 * 1.0},
      {"circular", circular_spec(1.0, 0.5), 0.2, circle_segment_area(0.5, 0.2)},
      {"circular_walls", circular_spec(1.0, 0.9), 0.7, 0.5 * kPi * 0.25 + 0.2 * 1.0},
      {"triangle45", sloped_spec("triangle", 1.0, 0.5, 45.0, 0.0), 0.1, 0.1 * 0.1},
      // Table 3.6 sloped tank: slope 1:2 meets the walls at 0.25 m, walls to 0.27 m.
      {"sloped_t36", sloped_spec("sloped", 1.0, 0.27, t26, 0.0), 0.18, 0.18 * 0.18 / 0.5},
      // Slopes meet the walls at 0.3 tan 30 = 0.173 m; filled below that.
      {"trapezoid", sloped_spec("trapezoid", 1.0, 0.5, 30.0, 0.4), 0.15,
       0.4 * 0.15 + 0.15 * 0.15 / std::tan(kPi / 6.0)},
      {"polyline", polyline_spec(skew), 0.3, 0.5 * area2},
  };
}

double wetted_perimeter(const TankGeometry& tank, double depth) {
  const std::vector<Vec2> poly = still_water_polygon(tank, depth);
  double p = 0.0;
  for (std::size_t k = 0; k + 1 < poly.size(); ++k) p += norm(poly[k + 1] - poly[k]);
  return p;  // the closing edge (the free surface) is left out
}

TEST(TankShapes, SectionAreaMatchesClosedForms) {
  // Reference: the closed-form area of each section below the depth. Tolerance: the
  // curves are chains of chords no longer than L/2000 (sagitta < 1e-7 m here): 1e-6 relative.
  for (const ShapeCase& c : shape_cases()) {
    const TankGeometry tank = make_tank(c.spec, "test");
    EXPECT_NEAR(section_area(tank, c.depth), c.exact_area, 1e-6 * c.exact_area) << c.name;
  }
}

TEST(TankShapes, CurvesAreFinelyDiscretised) {
  for (const ShapeCase& c : shape_cases()) {
    if (c.spec.shape != "parabolic" && c.spec.shape != "circular") continue;
    const TankGeometry tank = make_tank(c.spec, "test");
    for (std::size_t k = 0; k + 1 < tank.wall.size(); ++k) {
      const double len = norm(tank.wall[k + 1] - tank.wall[k]);
      ASSERT_GT(len, 0.0) << c.name;
      const bool wall = tank.wall[k].x == tank.wall[k + 1].x;  // straight vertical wall
      if (!wall) {
        ASSERT_LE(len, c.spec.length / 2000.0) << c.name << " segment " << k;
      }
    }
    EXPECT_DOUBLE_EQ(tank.y_bottom, 0.0) << c.name;
    EXPECT_DOUBLE_EQ(tank.bottom_at(0.5 * c.spec.length), 0.0) << c.name;
  }
}

TEST(TankShapes, ParabolicWallsStartWhereTheParabolaMeetsThem) {
  const TankGeometry t = make_tank(parabolic_spec(1.41, 0.5, 1.0), "test");
  EXPECT_DOUBLE_EQ(t.x_min, 0.0);
  EXPECT_DOUBLE_EQ(t.x_max, 1.41);
  EXPECT_DOUBLE_EQ(t.y_top, 0.5);
  EXPECT_NEAR(t.wall[1].y, 0.705 * 0.705, 1e-12);  // the wall meets the parabola at y = c (L/2)^2
  EXPECT_NEAR(surface_width(t, 0.25), 1.0, 1e-6);    // Table 3.6: L_fluid = 1 m at 0.25 m
  // Parabola reaching the wall top inside the section, with length = its top width.
  const TankGeometry u = make_tank(parabolic_spec(2.0 * std::sqrt(0.3), 0.3, 1.0), "test");
  EXPECT_NEAR(u.wall.front().y, 0.3, 1e-12);
  EXPECT_NEAR(u.x_max - u.x_min, 2.0 * std::sqrt(0.3), 1e-12);
}

TEST(TankShapes, CircularIsALowerHalfCircle) {
  const TankGeometry t = make_tank(circular_spec(1.0, 0.5), "test");
  for (const Vec2& p : t.wall) EXPECT_NEAR(norm(p - Vec2{0.5, 0.5}), 0.5, 1e-12);
  EXPECT_NEAR(surface_width(t, 0.1), 0.6, 1e-6);  // Table 3.10: L_fluid = 0.6 m at h = 0.1 m
  const TankGeometry w = make_tank(circular_spec(1.0, 0.8), "test");
  EXPECT_EQ(w.wall.front().x, 0.0);
  EXPECT_EQ(w.wall.front().y, 0.8);
  EXPECT_EQ(w.wall[1].y, 0.5);
}

TEST(TankShapes, SlopedSections) {
  // Table 3.4/3.8 sloped tank: 45 degrees, L = 1, h_tank = 0.5: a V reaching the wall top.
  const TankGeometry v = make_tank(sloped_spec("sloped", 1.0, 0.5, 45.0, 0.0), "test");
  EXPECT_EQ(v.wall.size(), 3u);
  EXPECT_NEAR(surface_width(v, 0.1), 0.2, 1e-12);  // Table 3.4: L_fluid = 0.2 m
  // Slopes reaching the top before x = 0: the section is narrower than tank.length.
  const TankGeometry n = make_tank(sloped_spec("triangle", 1.0, 0.3, 45.0, 0.0), "test");
  EXPECT_NEAR(n.x_min, 0.2, 1e-12);
  EXPECT_NEAR(n.x_max, 0.8, 1e-12);
  // Table 3.6 sloped tank: slope 1:2 meets the walls at 0.25 m < 0.27 m.
  const TankGeometry s = make_tank(sloped_spec("sloped", 1.0, 0.27, std::atan(0.5) * 180.0 / kPi, 0.0), "test");
  ASSERT_EQ(s.wall.size(), 5u);
  EXPECT_NEAR(s.wall[1].y, 0.25, 1e-12);
  EXPECT_NEAR(surface_width(s, 0.18), 0.72, 1e-12);  // Table 3.6: L_fluid = 0.72 m
  const TankGeometry z = make_tank(sloped_spec("trapezoid", 1.0, 0.5, 30.0, 0.4), "test");
  ASSERT_EQ(z.wall.size(), 6u);
  EXPECT_NEAR(z.wall[2].x, 0.3, 1e-12);
  EXPECT_NEAR(z.wall[3].x, 0.7, 1e-12);
}

// Splits the output of sample_walls into its layers (each layer is appended in turn).
std::vector<std::vector<WallSample>> wall_layers(const TankGeometry& tank, double dp, int layers) {
  std::vector<std::vector<WallSample>> out;
  std::size_t done = 0;
  const std::vector<WallSample> all = sample_walls(tank, dp, layers);
  for (int l = 1; l <= layers; ++l) {
    const std::size_t upto = sample_walls(tank, dp, l).size();
    out.emplace_back(all.begin() + static_cast<std::ptrdiff_t>(done), all.begin() + static_cast<std::ptrdiff_t>(upto));
    done = upto;
  }
  return out;
}

TEST(TankShapes, WallSamplesAreSpacedAtMostDpAndLieOutsideTheFluid) {
  // Thesis 3.3.2.1 ("nonlinear curved grid"): consecutive wall particles of a layer are
  // at most dp apart (delta <= dp) and, to avoid clusters, at least dp/2 apart. Every
  // wall particle is outside the container: the first layer is offset dp/2 outward,
  // so its signed distance is <= -dp/2 (1e-9 relative for rounding).
  const double dp = 0.01;
  for (const ShapeCase& c : shape_cases()) {
    const TankGeometry tank = make_tank(c.spec, "test");
    const auto layers = wall_layers(tank, dp, 2);
    for (std::size_t l = 0; l < layers.size(); ++l) {
      const std::vector<WallSample>& layer = layers[l];
      ASSERT_GT(layer.size(), 10u) << c.name;
      double smallest = 1e9, largest = 0.0, outermost_inside = -1e9;
      for (std::size_t k = 0; k < layer.size(); ++k) {
        outermost_inside = std::max(outermost_inside, tank.signed_distance(layer[k].position));
        EXPECT_NEAR(norm(layer[k].normal), 1.0, 1e-9) << c.name;
        if (k == 0) continue;
        const double gap = norm(layer[k].position - layer[k - 1].position);
        smallest = std::min(smallest, gap);
        largest = std::max(largest, gap);
      }
      EXPECT_LE(largest, dp * (1.0 + 1e-9)) << c.name << " layer " << l;
      EXPECT_GE(smallest, 0.5 * dp) << c.name << " layer " << l;
      EXPECT_LE(outermost_inside, -(l + 0.5) * dp * (1.0 - 1e-9)) << c.name << " layer " << l;
    }
  }
}

TEST(TankShapes, FluidFillsTheSectionAtHalfDpFromTheWall) {
  // Every fluid particle is at least dp/2 from the wall (1e-9 m for rounding).
  // Area: each particle stands for a dp x dp cell. A cell of an accepted centre (>= dp/2
  // from the wall) reaches at most dp/sqrt(2) - dp/2 = 0.207 dp beyond the wall, and every
  // point farther than dp (1/2 + 1/sqrt(2)) = 1.207 dp from the wall lies in an accepted cell;
  // the depths are multiples of dp, so the top row ends exactly at the still level. Hence
  // A - 1.21 dp P <= N dp^2 <= A + 0.21 dp P, P the wetted wall length (corners aside).
  const double dp = 0.01;
  for (const ShapeCase& c : shape_cases()) {
    const TankGeometry tank = make_tank(c.spec, "test");
    const std::vector<Vec2> fluid = fill_fluid(tank, dp, c.depth);
    ASSERT_FALSE(fluid.empty()) << c.name;
    double closest = 1e9;
    for (const Vec2& p : fluid) closest = std::min(closest, tank.signed_distance(p));
    EXPECT_GE(closest, 0.5 * dp - 1e-9) << c.name;
    const double area = static_cast<double>(fluid.size()) * dp * dp;
    const double perimeter = wetted_perimeter(tank, c.depth);
    std::printf("  %-16s fluid %6zu particles, N dp^2 = %.5f m^2, exact %.5f m^2, wetted wall %.3f m, "
                "(N dp^2 - A)/(dp P) = %+.3f\n",
                c.name.c_str(), fluid.size(), area, c.exact_area, perimeter, (area - c.exact_area) / (dp * perimeter));
    EXPECT_GE(area, c.exact_area - 1.21 * dp * perimeter) << c.name;
    EXPECT_LE(area, c.exact_area + 0.21 * dp * perimeter) << c.name;
  }
}

TEST(TankShapes, RectangleFillAndWallsAreLatticeAligned) {
  // Rectangle: exactly (L/dp) x (h/dp) fluid particles, and every wall particle on the
  // ((i + 1/2) dp, (j + 1/2) dp) lattice of the fluid.
  const double dp = 0.01;
  const TankGeometry tank = make_tank(rectangle_spec(1.0, 0.5), "test");
  EXPECT_EQ(fill_fluid(tank, dp, 0.25).size(), 100u * 25u);
  for (const WallSample& w : sample_walls(tank, dp, 3)) {
    const double i = w.position.x / dp - 0.5, j = w.position.y / dp - 0.5;
    EXPECT_NEAR(i, std::round(i), 1e-9);
    EXPECT_NEAR(j, std::round(j), 1e-9);
  }
}

TEST(TankShapes, FluidBlocksFillTheirLatticeNodesOnce) {
  // An L-shaped union of two overlapping blocks in a 1 m x 0.5 m rectangle, dp = 10 mm:
  // a column 0.2 m x 0.4 m and a layer 1 m x 0.1 m; the overlap counted once.
  const double dp = 0.01;
  const TankGeometry tank = make_tank(rectangle_spec(1.0, 0.5), "test");
  const std::vector<FluidBlock> blocks = {{{0.0, 0.0}, {0.2, 0.4}}, {{0.0, 0.0}, {1.0, 0.1}}};
  const std::vector<Vec2> fluid = fill_blocks(tank, dp, blocks);
  EXPECT_EQ(fluid.size(), 20u * 40u + 80u * 10u);
  // Hydrostatic heads: the top of the highest block that holds the point.
  EXPECT_DOUBLE_EQ(block_surface(blocks, {0.105, 0.055}), 0.4);
  EXPECT_DOUBLE_EQ(block_surface(blocks, {0.505, 0.055}), 0.1);
  EXPECT_DOUBLE_EQ(block_surface(blocks, {0.505, 0.2}), 0.2);  // outside: its own height
}

template <class F>
void expect_input_error(F&& f, const std::string& key, const std::string& label) {
  try {
    f();
    ADD_FAILURE() << label << ": no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), key) << label << ": " << e.what();
    EXPECT_EQ(e.where(), "case.toml") << label;
  }
}

TEST(TankShapes, BadShapesAreInputErrors) {
  auto make = [](TankSpec s) { return [s] { (void)make_tank(s, "case.toml"); }; };
  expect_input_error(make(circular_spec(1.0, 0.4)), "tank.height", "circular lower than its radius");
  expect_input_error(make(parabolic_spec(2.0, 0.5, 1.0)), "tank.length", "parabola narrower than length");
  expect_input_error(make(parabolic_spec(1.0, 0.5, -1.0)), "tank.coefficient", "negative coefficient");
  expect_input_error(make(sloped_spec("triangle", 1.0, 0.5, 45.0, 0.2)), "tank.bottom_width", "triangle with flat");
  expect_input_error(make(sloped_spec("trapezoid", 1.0, 0.5, 45.0, 0.0)), "tank.bottom_width", "trapezoid, no flat");
  expect_input_error(make(sloped_spec("sloped", 1.0, 0.5, 1.0, 1.0)), "tank.bottom_width", "flat wider than tank");
  expect_input_error(make(sloped_spec("sloped", 1.0, 0.5, 90.0, 0.0)), "tank.angle", "vertical slope");
  expect_input_error(make(sloped_spec("sloped", 1.0, 0.5, 0.0, 0.0)), "tank.angle", "flat slope");
  expect_input_error(make(rectangle_spec(0.0, 0.5)), "tank.length", "zero length");
  TankSpec unknown = rectangle_spec(1.0, 0.5);
  unknown.shape = "hexagon";
  expect_input_error(make(unknown), "tank.shape", "unknown shape");

  expect_input_error(make(polyline_spec({{0, 1}, {1, 1}})), "tank.points", "two points");
  expect_input_error(make(polyline_spec({{0, 0.5}, {0.5, 0.6}, {1, 1}})), "tank.points", "end not highest");
  expect_input_error(make(polyline_spec({{1, 1}, {1, 0}, {0, 0}, {0, 1}})), "tank.points", "right to left");
  expect_input_error(make(polyline_spec({{0, 1}, {1, 0}, {0, 0}, {1, 1}})), "tank.points", "bow tie");
  expect_input_error(make(polyline_spec({{0, 1}, {0, 0}, {0, 0}, {1, 0}, {1, 1}})), "tank.points", "repeated point");
  expect_input_error(make(polyline_spec({{0, 1}, {0, 0}, {1, 0}, {0.5, 0}, {1, 1}})), "tank.points", "folds back");
  // A valid polyline keeps its coordinates; y_bottom is its lowest point.
  const TankGeometry t = make_tank(polyline_spec({{-1, 2}, {-1, 1.5}, {0, 1}, {1, 1.5}, {1, 2}}), "case.toml");
  EXPECT_EQ(t.y_bottom, 1.0);
  EXPECT_EQ(t.x_min, -1.0);
  EXPECT_NEAR(section_area(t, 0.5), 0.5, 1e-12);
}

TEST(TankShapes, StillWaterPolygonErrors) {
  const TankGeometry rect = make_tank(rectangle_spec(1.0, 0.5), "test");
  EXPECT_THROW(still_water_polygon(rect, 0.6), InputError);  // above the walls
  EXPECT_THROW(still_water_polygon(rect, 0.0), InputError);
  EXPECT_NEAR(section_area(rect, 0.5), 0.5, 1e-15);  // brim-full is allowed
  // W-shaped bottom whose ridge rises above the level: two pools.
  const TankGeometry w = make_tank(polyline_spec({{0, 1}, {0, 0}, {0.5, 0.4}, {1, 0}, {1, 1}}), "test");
  try {
    (void)still_water_polygon(w, 0.3);
    ADD_FAILURE() << "two pools accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "fill.depth");
  }
  EXPECT_NEAR(section_area(w, 0.6), 0.6 - 0.2, 1e-12);  // one pool above the ridge
}

}  // namespace
}  // namespace sloshsph
