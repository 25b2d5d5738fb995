// Upright cylinders (issue 31, section 2; geometry/cylinder_tank.hpp): the fill is the cubic lattice
// inside r <= R - dp/2, as many particles as hold the water of the depth (the last layer a disc
// about the axis); the walls are outside the fluid region with normals towards it; the settled
// level is the fill's volume over pi R^2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sloshsph/geometry/cylinder_tank.hpp"

namespace sloshsph {
namespace {

TEST(CylinderTank, FillIsTheLatticeInsideTheWall) {
  const CylinderTank tank{0.15, 0.3};
  const double dp = 0.015, depth = 0.15;
  const std::vector<Vec3> fluid = fill_fluid(tank, dp, depth);
  // Reference: the water of the depth, round(pi R^2 h / dp^3) particles (3,142 here), in whole
  // layers of the lattice points inside r <= R - dp/2 (276 a layer: exact integers) and, in the
  // last, a disc of the points nearest the axis.
  int layer = 0;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i)
      if (std::hypot((i + 0.5) * dp - 0.15, (j + 0.5) * dp - 0.15) <= 0.15 - 0.5 * dp + 1e-12) ++layer;
  const std::size_t wanted = static_cast<std::size_t>(std::llround(std::numbers::pi * 0.15 * 0.15 * depth / (dp * dp * dp)));
  EXPECT_EQ(fluid.size(), wanted);
  EXPECT_EQ(cylinder_fill_count(tank, dp, depth), wanted);
  const std::size_t whole = wanted / static_cast<std::size_t>(layer), rest = wanted % static_cast<std::size_t>(layer);
  Vec3 sum{};
  double last_disc = 0.0, outside_it = 1.0;  // the last layer's largest radius, and the smallest radius of the others
  for (const Vec3& q : fluid) {
    EXPECT_GE(tank.signed_distance(q), 0.5 * dp - 1e-12);
    const int k = static_cast<int>(std::lround(q.z / dp - 0.5));
    EXPECT_LE(k, static_cast<int>(whole));
    if (k == static_cast<int>(whole)) last_disc = std::max(last_disc, tank.from_axis(q));
    if (k < static_cast<int>(whole)) sum += q;
  }
  std::size_t in_last = 0;
  for (const Vec3& q : fluid)
    if (static_cast<int>(std::lround(q.z / dp - 0.5)) == static_cast<int>(whole)) ++in_last;
  EXPECT_EQ(in_last, rest);
  // Every lattice point of a layer left out of the last one is no nearer the axis than those in it.
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      const double r = std::hypot((i + 0.5) * dp - 0.15, (j + 0.5) * dp - 0.15);
      if (r > 0.15 - 0.5 * dp + 1e-12) continue;
      bool taken = false;
      for (const Vec3& q : fluid)
        taken = taken || (std::lround(q.z / dp - 0.5) == static_cast<long>(whole) &&
                          std::abs(q.x - (i + 0.5) * dp) < 1e-12 && std::abs(q.y - (j + 0.5) * dp) < 1e-12);
      if (!taken) outside_it = std::min(outside_it, r);
    }
  EXPECT_GE(outside_it, last_disc - 1e-12);
  // The whole layers are symmetric about the axis (dp divides 2R): their centroid on it, to round-off.
  const double n_whole = static_cast<double>(whole * static_cast<std::size_t>(layer));
  EXPECT_NEAR(sum.x / n_whole, 0.15, 1e-12);
  EXPECT_NEAR(sum.y / n_whole, 0.15, 1e-12);
  // The settled level: the particles' volume over pi R^2, the depth to half a particle.
  const double level = cylinder_settled_level(tank, fluid.size(), dp);
  EXPECT_NEAR(level, depth, 0.5 * dp * dp * dp / (std::numbers::pi * 0.15 * 0.15));
}

TEST(CylinderTank, WallsSurroundTheFluidWithInwardNormals) {
  const CylinderTank tank{0.15, 0.3};
  const double dp = 0.015;
  const int layers = 2;
  const std::vector<WallSample3> walls = sample_walls(tank, dp, layers);
  std::size_t side = 0, bottom = 0;
  for (const WallSample3& w : walls) {
    EXPECT_LT(tank.signed_distance(w.position), 0.0);
    EXPECT_NEAR(norm(w.normal), 1.0, 1e-12);
    if (w.normal.z == 1.0) {
      ++bottom;
      EXPECT_LT(tank.from_axis(w.position), tank.radius);
      EXPECT_GT(w.position.z, -layers * dp);
    } else {
      ++side;
      // The side's normal points at the axis, and its layer stands (k + 1/2) dp outside the wall.
      const Vec3 to_axis{tank.radius - w.position.x, tank.radius - w.position.y, 0.0};
      EXPECT_NEAR(dot(w.normal, to_axis), norm(to_axis), 1e-9);
      const double layer = (tank.from_axis(w.position) - tank.radius) / dp - 0.5;
      EXPECT_NEAR(layer, std::round(layer), 1e-9);
    }
  }
  // The side's rings: round(2 pi (R + (k + 1/2) dp) / dp) around, on 20 levels from -2 dp to the top.
  const std::size_t around = std::lround(2.0 * std::numbers::pi * (0.15 + 0.5 * dp) / dp) +
                             std::lround(2.0 * std::numbers::pi * (0.15 + 1.5 * dp) / dp);
  EXPECT_EQ(side, around * (20 + 2));
  EXPECT_GT(bottom, 0u);
}

TEST(CylinderTank, FirstModeOfLinearTheory) {
  // omega^2 = g k tanh(k h), k = 1.8412 / R: R = 0.15 m, h = 0.15 m, g = 9.81 gives 10.7006 rad/s.
  EXPECT_NEAR(cylinder_first_sloshing_omega(0.15, 0.15, 9.81), 10.7006, 1e-4);
}

// The first mode's convective mass fraction against the modal integrals it comes from, computed
// here by quadrature: for a mode psi = J1(k r) cos(theta) of the free surface S (k = xi / R) under a
// motion along x, m_1 = rho (int_S x psi dS)^2 k tanh(k h) / int_S psi^2 dS (the rectangle's
// 8 tanh(pi h / L) / (pi^3 h / L) follows the same way), with int_S x psi dS = pi int r^2 J1 dr and
// int_S psi^2 dS = pi int r J1^2 dr (Simpson, 4,000 intervals; J1 from the standard library).
// Tolerance 1e-4, the digits of xi = 1.8412. Three depths (h/R = 0.5, 1, 2).
TEST(CylinderTank, ConvectiveMassFractionIsTheModalIntegrals) {
  const double R = 0.15, xi = 1.8412, k = xi / R;
  auto simpson = [](auto f, double a, double b, int n) {
    const double dx = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * dx);
    return sum * dx / 3.0;
  };
  const double moment = std::numbers::pi * simpson([k](double r) { return r * r * std::cyl_bessel_j(1.0, k * r); }, 0.0, R, 4000);
  const double norm2 = std::numbers::pi * simpson([k](double r) { const double j = std::cyl_bessel_j(1.0, k * r); return r * j * j; }, 0.0, R, 4000);
  for (const double h : {0.075, 0.15, 0.3}) {
    const double fraction = moment * moment * k * std::tanh(k * h) / norm2 / (std::numbers::pi * R * R * h);
    EXPECT_NEAR(cylinder_convective_mass_fraction(R, h), fraction, 1e-4 * fraction) << "h = " << h;
  }
  EXPECT_NEAR(cylinder_convective_mass_fraction(R, 0.15), 0.4322, 1e-4);  // h/R = 1
}

}  // namespace
}  // namespace sloshsph
