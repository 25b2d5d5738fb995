// The dimension-generic foundation of issue 31 in 3D: the kernels' 3D normalisation, the cell grid
// and Verlet list against brute force, the pair layer's pairs, W and F, on points in space, and
// the operators of thesis section 2.2.3 on a cubic lattice.
// (The 2D instantiations are the ones every other test and the regression references run.)
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/physics/excitation.hpp"
#include "sloshsph/physics/frame.hpp"
#include "sloshsph/physics/turbulence.hpp"
#include "sloshsph/sph/kernel.hpp"
#include "sloshsph/sph/neighbours.hpp"
#include "sloshsph/sph/operators.hpp"
#include "sloshsph/sph/pairs.hpp"
#include "neighbour_checks.hpp"

namespace sloshsph {
namespace {

// Integral of W over space, 4 pi int_0^2h W(r) r^2 dr (composite Simpson, 20000 intervals: the
// quadrature error is far below the 1e-6 tolerance).
template <class K>
double spherical_integral(const K& k) {
  const int n = 20000;
  const double b = k.support(), step = b / n;
  double s = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double r = i * step;
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    s += weight * k.w(r) * r * r;
  }
  return 4.0 * std::numbers::pi * s * step / 3.0;
}

TEST(ThreeD, WendlandIntegratesToOneInSpace) {
  // Reference: a kernel is normalised, integral W dV = 1 (Wendland C2 in 3D: 21/(16 pi h^3)).
  for (double h : {0.001, 0.014, 1.0}) EXPECT_NEAR(spherical_integral(WendlandC2(h, 3)), 1.0, 1e-6) << h;
}

TEST(ThreeD, CubicSplineIntegratesToOneInSpace) {
  // Reference: integral W dV = 1 (cubic B-spline in 3D: 1/(pi h^3)).
  for (double h : {0.001, 0.014, 1.0}) EXPECT_NEAR(spherical_integral(CubicSpline(h, 3)), 1.0, 1e-6) << h;
}

TEST(ThreeD, TwoDimensionalNormalisationUnchanged) {
  // The 2D constant is the thesis's eq. 2.3 as before, whether or not the dimension is given.
  const double h = 0.014;
  EXPECT_EQ(WendlandC2(h).norm, 7.0 / (4.0 * std::numbers::pi * h * h));
  EXPECT_EQ(WendlandC2(h, 2).norm, WendlandC2(h).norm);
  EXPECT_EQ(CubicSpline(h, 2).norm, 10.0 / (7.0 * std::numbers::pi * h * h));
}

std::vector<Vec3> random_points(std::size_t n, unsigned seed, double size) {
  return testing::random_points<3>(n, seed, size);
}

TEST(ThreeD, NeighbourListEqualsBruteForce) {
  // Reference: all pairs closer than the search radius, by brute force (neighbour_checks.hpp).
  const std::size_t total = testing::expect_list_equals_brute_force(random_points(3000, 5, 0.5), 2000, 0.04, 0.01);
  // Not a vacuous check: 3000 points in 0.125 m^3 give about 1.5 neighbours each within 0.05 m.
  EXPECT_GT(total, 2000u);
}

TEST(ThreeD, NeighbourListStaleAfterHalfTheSkinAlongZ) {
  auto pts = random_points(200, 3, 0.3);
  NeighbourList3 nl(0.04, 0.01);
  nl.build(pts, 200);
  EXPECT_FALSE(nl.stale(pts, 200));
  pts[17].z += 0.0049;
  EXPECT_FALSE(nl.stale(pts, 200));
  pts[17].z += 0.0002;
  EXPECT_TRUE(nl.stale(pts, 200));
}

TEST(ThreeD, CellOrderIsAPermutationAndFollowsTheCells) {
  const auto pts = random_points(500, 11, 0.5);
  const double cell = 0.05;
  const auto order = cell_order(pts, 400, cell);
  ASSERT_EQ(order.size(), 400u);
  CellGrid3 grid;
  grid.build(pts, 0, 400, cell);
  std::vector<bool> seen(400, false);
  int last_cell = -1;
  for (std::uint32_t i : order) {
    ASSERT_LT(i, 400u);
    EXPECT_FALSE(seen[i]);
    seen[i] = true;
    const int c = grid.cell_of(pts[i]);
    EXPECT_GE(c, last_cell) << "the order runs through the cells in their numbering, z slowest";
    last_cell = c;
  }
  EXPECT_EQ(grid.cells(2), static_cast<int>(0.5 / cell) + 2);
}

// A cubic lattice of n^3 points of spacing dp, each moved by up to `jitter` dp along each axis.
std::vector<Vec3> cubic_lattice(int n, double dp, double jitter) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(-jitter * dp, jitter * dp);
  std::vector<Vec3> x;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n; ++c) x.push_back({a * dp + u(rng), b * dp + u(rng), c * dp + u(rng)});
  return x;
}

TEST(ThreeD, PairListHoldsThePairsWithinTheSupportAndTheirKernel) {
  // On a jittered lattice at h = 1.4 dp, 1,728 points (27 blocks of the list's 64 rows): each
  // kept pair is a Verlet pair within 2h, in the row's order, with W and F of the 3D kernel.
  const double dp = 0.01, h = 1.4 * dp;
  const std::vector<Vec3> x = cubic_lattice(12, dp, 0.2);
  NeighbourList3 nl(2.0 * h, 0.2 * 2.0 * h);
  nl.build(x, x.size());
  PairList3 pairs;
  pairs.build(KernelType::wendland_c2, h, x, nl);
  const WendlandC2 k(h, 3);
  const double reach2 = kernel_reach2(k);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::vector<std::uint32_t> want;
    for (const std::uint32_t* j = nl.begin(i); j != nl.end(i); ++j)
      if (norm2(x[i] - x[*j]) <= reach2) want.push_back(*j);
    std::vector<std::uint32_t> got;
    pairs.for_each(i, [&](const Pair3& q) {
      got.push_back(q.j);
      EXPECT_EQ(q.rij.z, x[i].z - x[q.j].z);
      double w = 0.0, f = 0.0;
      k.w_and_gradient(std::sqrt(norm2(x[i] - x[q.j])), w, f);
      EXPECT_EQ(q.w, w) << "row " << i;
      EXPECT_EQ(q.f, f) << "row " << i;
    });
    ASSERT_EQ(got, want) << "row " << i;
    kept += got.size();
  }
  EXPECT_LT(kept, nl.total_pairs()) << "the skin's pairs are filtered out";
}

TEST(ThreeD, KernelSumAndGradientMomentOnACubicLattice) {
  // Reference: the particle approximations of 1 and of grad(r) = I on a regular cubic lattice at
  // h = 1.4 dp, for a particle whose kernel is full: sum_j V W_ij = 1 and
  // sum_j V r_ij (x) grad_i W_ij = -I. Wendland C2 gives 1.0045 and -0.9914 (evaluated
  // independently of this code); tolerance 1%.
  const double dp = 0.01, h = 1.4 * dp;
  const int n = 9;
  const std::vector<Vec3> x = cubic_lattice(n, dp, 0.0);
  NeighbourList3 nl(2.0 * h, 0.1 * h);
  nl.build(x, x.size());
  PairList3 pairs;
  pairs.build(KernelType::wendland_c2, h, x, nl);
  const std::size_t centre = (n / 2) * n * n + (n / 2) * n + n / 2;
  const double V = dp * dp * dp;
  double wsum = pairs.self_w();
  double m[3][3] = {};
  pairs.for_each(centre, [&](const Pair3& q) {
    wsum += q.w;
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) m[r][s] += V * component(q.rij, r) * q.f * component(q.rij, s);
  });
  EXPECT_NEAR(wsum * V, 1.0, 0.01);
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) EXPECT_NEAR(m[r][s], r == s ? -1.0 : 0.0, 0.01) << r << s;
  EXPECT_EQ(pairs.count(centre), 80u) << "lattice points with 0 < |r|^2 < (2.8 dp)^2";
}

// A regular cubic lattice of 13^3 points at h = 1.4 dp with its pairs; `interior` are the points
// whose kernel (2.8 dp) lies inside the lattice.
struct CubicLattice {
  double dp = 0.01;
  std::vector<Vec3> x = cubic_lattice(13, dp, 0.0);
  NeighbourList3 nl{2.8 * dp, 0.0};
  PairList3 pairs;
  CubicLattice() {
    nl.build(x, x.size());
    pairs.build(KernelType::wendland_c2, 1.4 * dp, x, nl);
  }
  bool interior(std::size_t i) const {
    const double lo = 3.0 * dp - 1e-12, hi = 9.0 * dp + 1e-12;
    const Vec3 p = x[i];
    return p.x >= lo && p.x <= hi && p.y >= lo && p.y <= hi && p.z >= lo && p.z <= hi;
  }
};

TEST(ThreeD, OperatorsOnLinearAndQuadraticFields) {
  // References: grad(3x - 2y + z + 1) = (3, -2, 1) by both gradients and grad(u) of
  // u = (2x + y, x - 0.5y, x + 0.25z), tolerance 1.5% of the largest component (the lattice
  // moment, -0.9914 above); div(u) = 1.75, 1.5%; lap(x^2 + 2y^2 - xy + 3z^2) = 12, 3% (the 2D
  // tests' tolerances).
  const CubicLattice L;
  const double V = L.dp * L.dp * L.dp;
  const double eta2 = 1e-4 * (1.4 * L.dp) * (1.4 * L.dp);
  std::vector<double> f, q;
  std::vector<Vec3> u;
  for (const Vec3& p : L.x) {
    f.push_back(3.0 * p.x - 2.0 * p.y + p.z + 1.0);
    q.push_back(p.x * p.x + 2.0 * p.y * p.y - p.x * p.y + 3.0 * p.z * p.z);
    u.push_back({2.0 * p.x + p.y, p.x - 0.5 * p.y, p.x + 0.25 * p.z});
  }
  const double grad_u[3][3] = {{2.0, 1.0, 0.0}, {1.0, -0.5, 0.0}, {1.0, 0.0, 0.25}};
  int checked = 0;
  for (std::size_t i = 0; i < L.x.size(); ++i) {
    if (!L.interior(i)) continue;
    for (const Vec3& g : {gradient_difference(L.pairs, f, V, i), gradient_symmetric(L.pairs, f, V, i)}) {
      EXPECT_NEAR(g.x, 3.0, 0.015 * 3.0);
      EXPECT_NEAR(g.y, -2.0, 0.015 * 3.0);
      EXPECT_NEAR(g.z, 1.0, 0.015 * 3.0);
    }
    const auto g = velocity_gradient(L.pairs, u, V, i);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(g.c[a][b], grad_u[a][b], 0.015 * 2.0) << a << b;
    EXPECT_NEAR(divergence(L.pairs, u, V, i), 1.75, 0.015 * 1.75);
    EXPECT_NEAR(laplacian(L.pairs, q, V, eta2, i), 12.0, 0.03 * 12.0);
    EXPECT_NEAR(kernel_sum(L.pairs, V, i), 1.0, 0.01);
    ++checked;
  }
  EXPECT_EQ(checked, 7 * 7 * 7);
}

TEST(ThreeD, ParticleStoreReordersAndRemovesWithAllThreeComponents) {
  // The store of the 2D schemes in 3D: a permutation and a removal of fluid carry x, y and z of
  // positions, velocities and normals with the particle; the walls stay where they are.
  Particles3 p;
  p.resize(5);
  p.n_fluid = 3;
  for (std::size_t i = 0; i < 5; ++i) {
    const double v = static_cast<double>(i);
    p.position[i] = {v, 10.0 + v, 20.0 + v};
    p.velocity[i] = {-v, -10.0 - v, -20.0 - v};
    p.id[i] = static_cast<std::int32_t>(i);
  }
  p.permute_fluid({2, 0, 1});
  EXPECT_EQ(p.id[0], 2);
  EXPECT_EQ(p.position[0].z, 22.0);
  EXPECT_EQ(p.velocity[1].z, -20.0);
  p.remove_fluid({0, 1, 0});
  ASSERT_EQ(p.n_fluid, 2u);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p.id[1], 1);
  EXPECT_EQ(p.position[1].z, 21.0);
  EXPECT_EQ(p.position[2].z, 23.0);  // the first wall particle
}

TEST(ThreeD, FrameForceAboutTheVerticalIsThePlaneOne) {
  // Reference: the 2D frame force (Euler, centrifugal, Coriolis about the out-of-plane axis) of the
  // same motion. A 3D frame turning about z at omega, alpha acts in the x-y plane as the 2D frame
  // does; to round-off (1e-12 of the largest term).
  FrameForce f2;
  f2.uniform = {0.3, -9.81};
  f2.omega = 0.7;
  f2.alpha = -1.3;
  f2.pivot = {0.25, 0.1};
  FrameForce3 f3;
  f3.uniform = {0.3, -9.81, 0.0};
  f3.omega = {0.0, 0.0, 0.7};
  f3.alpha = {0.0, 0.0, -1.3};
  f3.pivot = {0.25, 0.1, 0.5};
  const Vec2 r{0.9, -0.4}, u{1.5, 0.8};
  const Vec2 a2 = f2.at(r, u);
  const Vec3 a3 = f3.at({r.x, r.y, 2.0}, {u.x, u.y, 0.0});
  EXPECT_NEAR(a3.x, a2.x, 1e-12 * 10.0);
  EXPECT_NEAR(a3.y, a2.y, 1e-12 * 10.0);
  EXPECT_EQ(a3.z, 0.0);
  EXPECT_TRUE(f3.rotating());
  // A roll about x: the centrifugal force points away from the axis, omega^2 times the distance.
  FrameForce3 roll;
  roll.omega = {2.0, 0.0, 0.0};
  const Vec3 c = roll.at({0.0, 0.0, 0.5}, {});
  EXPECT_NEAR(c.z, 4.0 * 0.5, 1e-12);
  EXPECT_NEAR(c.y, 0.0, 1e-12);
}

// Issue 31, section 3: a 3D tank turned about the axis (0, -1, 0) is the 2D pitch of its section
// (x, z): the body force of a BaseMotion with angle, rate and acceleration, through frame_force
// (2D) and frame_force3 (3D), at points and velocities in the section's plane, gives the same x and
// z components and no y, to round-off (1e-12 of g). And a roll (axis x) of a tank at rest turns
// gravity towards -y for a positive angle (the right-handed sense about +x takes z towards -y).
TEST(ThreeD, PitchAboutMinusYIsTheSectionsPitch) {
  BaseMotion m;
  m.angle = 0.07;
  m.angular_velocity = -0.4;
  m.angular_acceleration = 1.9;
  m.acceleration = {0.3, -0.2};
  m.pivot = {0.45, 0.3};
  m.pivot_across = 0.1;
  m.axis = {0.0, -1.0, 0.0};
  const FrameForce f2 = frame_force(9.81, m);
  const FrameForce3 f3 = frame_force3(9.81, m);
  for (const auto& [r, u] : {std::pair<Vec2, Vec2>{{0.9, 0.05}, {0.4, -1.1}}, {{0.1, 0.6}, {-0.2, 0.3}}}) {
    const Vec2 a2 = f2.at(r, u);
    const Vec3 a3 = f3.at({r.x, 0.37, r.y}, {u.x, 0.0, u.y});
    EXPECT_NEAR(a3.x, a2.x, 1e-12 * 9.81);
    EXPECT_NEAR(a3.z, a2.y, 1e-12 * 9.81);
    EXPECT_NEAR(a3.y, 0.0, 1e-12 * 9.81);
  }
  BaseMotion roll;
  roll.angle = 0.1;
  roll.axis = {1.0, 0.0, 0.0};
  const FrameForce3 r3 = frame_force3(9.81, roll);
  EXPECT_NEAR(r3.uniform.y, -9.81 * std::sin(0.1), 1e-12);
  EXPECT_NEAR(r3.uniform.z, -9.81 * std::cos(0.1), 1e-12);
  EXPECT_EQ(r3.uniform.x, 0.0);
}

TEST(ThreeD, SpsClosureOfAPlaneFlowIsThePlaneOne) {
  // Reference: the 2D closure (thesis eqs. 2.8-2.9) of the same velocity gradient. A flow in the
  // x-y plane has |S| and the in-plane stresses of the 2D closure, no stress out of the plane but
  // the isotropic -2/3 k_t; the stress divergence's pair term (tau_i + tau_j) r_ij likewise.
  // To round-off (1e-12 of the largest term).
  VelocityGradient g2;
  g2.c[0][0] = 0.8;
  g2.c[0][1] = -1.7;
  g2.c[1][0] = 0.4;
  g2.c[1][1] = -0.8;
  BasicVelocityGradient<3> g3;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) g3.c[a][b] = g2.c[a][b];
  const SpsClosure closure{1e-4, 0.08 * 0.01};
  double nu2 = 0.0, nu3 = 0.0;
  const SymTensor2 t2 = sps_stress_of(g2, closure, nu2);
  const SymTensor3 t3 = sps_stress_of(g3, closure, nu3);
  EXPECT_NEAR(nu3, nu2, 1e-15);
  EXPECT_NEAR(t3.xx, t2.xx, 1e-12);
  EXPECT_NEAR(t3.xy, t2.xy, 1e-12);
  EXPECT_NEAR(t3.yy, t2.yy, 1e-12);
  EXPECT_EQ(t3.xz, 0.0);
  EXPECT_EQ(t3.yz, 0.0);
  const double kt = (nu2 / closure.ct_dp) * (nu2 / closure.ct_dp);
  EXPECT_GT(kt, 0.0);
  EXPECT_NEAR(t3.zz, -2.0 / 3.0 * kt, 1e-12);
  const Vec2 a2 = sum_times(t2, t2, Vec2{0.3, -0.2});
  const Vec3 a3 = sum_times(t3, t3, Vec3{0.3, -0.2, 0.0});
  EXPECT_NEAR(a3.x, a2.x, 1e-12);
  EXPECT_NEAR(a3.y, a2.y, 1e-12);
  EXPECT_EQ(a3.z, 0.0);
}

}  // namespace
}  // namespace sloshsph

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/geometry/screens.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/io/case_reader.hpp"

namespace sloshsph {
namespace {

// Issue 31, section 2: explicit slats across the breadth of a box. In a square box (0.6 x 0.6 m,
// dp = 20 mm) a slatted screen in the plane y = 0.3 m is the mirror image (x <-> y) of the same
// screen at x = 0.3 m: the same fluid particles and the same slat wall particles, mirrored, to
// round-off (1e-12 m; the turned walls are computed as 0.3 + (x - 0.3)).
std::string square_box(const std::string& where) {
  return "[tank]\ndimensions = 3\nshape = \"rectangle\"\nlength = 0.6\nbreadth = 0.6\nheight = 0.3\n"
         "[fill]\ndepth = 0.1\n[particles]\ndp = 0.02\n[time]\nend = 0.1\n"
         "[[screens]]\nname = \"S\"\n" + where + "\nslat_height = 0.02\nslat_gap = 0.02\nthickness = 0.004\n"
         "model = \"explicit\"\n";
}

TEST(ThreeD, ExplicitSlatsAcrossTheBreadthMirrorThoseAcrossTheLength) {
  const Scene3 along_x = build_scene3(read_case_text(square_box("x = 0.3"), "x.toml", {}));
  const Scene3 along_y = build_scene3(read_case_text(square_box("y = 0.3"), "y.toml", {}));
  const BasicParticles<3>& a = along_x.particles;
  const BasicParticles<3>& b = along_y.particles;
  ASSERT_EQ(a.n_fluid, b.n_fluid);
  ASSERT_EQ(a.size(), b.size());
  auto mirrored = [](Vec3 p) { return Vec3{p.y, p.x, p.z}; };
  auto sorted = [](std::vector<Vec3> v) {
    std::sort(v.begin(), v.end(), [](Vec3 p, Vec3 q) {
      const auto key = [](Vec3 r) { return std::array<long, 3>{std::lround(r.x * 1e6), std::lround(r.y * 1e6), std::lround(r.z * 1e6)}; };
      return key(p) < key(q);
    });
    return v;
  };
  std::vector<Vec3> fluid_a, fluid_b;
  for (std::size_t i = 0; i < a.n_fluid; ++i) fluid_a.push_back(mirrored(a.position[i]));
  for (std::size_t i = 0; i < b.n_fluid; ++i) fluid_b.push_back(b.position[i]);
  fluid_a = sorted(fluid_a), fluid_b = sorted(fluid_b);
  double worst = 0.0;
  for (std::size_t i = 0; i < fluid_a.size(); ++i) worst = std::max(worst, norm(fluid_a[i] - fluid_b[i]));
  EXPECT_LT(worst, 1e-12);
  // The slat walls: the wall particles whose normal is horizontal and not an end or side wall's, i.e.
  // those of the screen (the tank's walls are the same in both scenes, as a square box is symmetric).
  auto slat_walls = [&](const BasicParticles<3>& p, bool mirror) {
    std::vector<Vec3> out;
    for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
      const Vec3 q = p.position[w];
      if (q.x > 0.05 && q.x < 0.55 && q.y > 0.05 && q.y < 0.55 && q.z > 0.0) out.push_back(mirror ? mirrored(q) : q);
    }
    return sorted(out);
  };
  const std::vector<Vec3> slats_a = slat_walls(a, true), slats_b = slat_walls(b, false);
  ASSERT_EQ(slats_a.size(), slats_b.size());
  ASSERT_GT(slats_a.size(), 0u);
  worst = 0.0;
  for (std::size_t i = 0; i < slats_a.size(); ++i) worst = std::max(worst, norm(slats_a[i] - slats_b[i]));
  EXPECT_LT(worst, 1e-12);
}

// The wall particles of a scene that are not the tank's: those the same case without its screen lacks.
std::vector<Vec3> slat_walls_of(const Scene3& with, const Scene3& without) {
  const BasicParticles<3>& p = with.particles;
  const std::size_t tank_walls = without.particles.size() - without.particles.n_fluid;
  std::vector<Vec3> out(p.position.begin() + static_cast<std::ptrdiff_t>(p.n_fluid + tank_walls), p.position.end());
  return out;
}

// The closest any fluid particle of `scene` comes to any of `slats` (brute force).
double closest_fluid_to(const Scene3& scene, const std::vector<Vec3>& slats) {
  double closest = 1e9;
  for (std::size_t i = 0; i < scene.particles.n_fluid; ++i)
    for (const Vec3& q : slats) closest = std::min(closest, norm(scene.particles.position[i] - q));
  return closest;
}

// Issue 31, section 2: a fill block in an upright cylinder (R = 0.15 m, dp = 10 mm) is the rectangle
// (x, z) of the block over every y inside the circle. The block x < 0.15 m (the axis), z < 0.1 m
// holds, on each of its 10 levels, the lattice nodes ((i + 1/2) dp, (j + 1/2) dp) with x < R and
// r <= R - dp/2 (counted here from the circle: half a layer, dp dividing 2R); each particle starts
// at the hydrostatic pressure below the block's top, rho g (0.1 - z); the settled depth is their
// volume over pi R^2 (exact arithmetic, 1e-12).
TEST(ThreeD, FillBlocksInACylinderHoldTheLatticeInsideTheCircle) {
  const std::string cylinder = read_case_file_text(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/cylinder3d_sloshing.toml");
  std::string text = cylinder + "\n[[fill.blocks]]\nfrom = [0.0, 0.0]\nto = [0.15, 0.1]\n";
  text.replace(text.find("depth = 0.15"), 12, "");  // the depth from the blocks' water
  const CaseSpec spec = read_case_text(text, "block.toml", {});
  const Scene3 scene = build_scene3(spec);
  const double R = 0.15, dp = 0.01;
  std::size_t layer = 0, full_layer = 0;
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) {
      const bool inside = std::hypot((i + 0.5) * dp - R, (j + 0.5) * dp - R) <= R - 0.5 * dp + 1e-12;
      full_layer += inside ? 1 : 0;
      layer += inside && i < 15 ? 1 : 0;
    }
  EXPECT_EQ(2 * layer, full_layer);
  const Particles3& p = scene.particles;
  EXPECT_EQ(p.n_fluid, 10 * layer);
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    const Vec3 q = p.position[i];
    EXPECT_LT(q.x, R);
    EXPECT_LT(q.z, 0.1);
    EXPECT_LE(std::hypot(q.x - R, q.y - R), R - 0.5 * dp + 1e-12);
    EXPECT_NEAR(p.pressure[i], spec.fluid.density * spec.fluid.gravity * (0.1 - q.z), 1e-9);
  }
  EXPECT_NEAR(spec.fill.depth, static_cast<double>(p.n_fluid) * dp * dp * dp / (std::numbers::pi * R * R), 1e-12);
  EXPECT_NEAR(scene.still_level, spec.fill.depth, 1e-12);
}

// Issue 31: an elastic plate in a 3D box (cases/hydrostatic_plate.toml made a slab 4 dp broad) is its
// section's plate particles (plate_layout) on each of the 4 lattice planes across the breadth,
// section particle k on plane m at k * 4 + m, normals with no y part; they are the last wall
// particles; no fluid particle is closer than 0.9 dp to one (as in 2D). A cylinder has no plates.
TEST(ThreeD, PlateStandsOnTheLatticePlanesAcrossTheBreadth) {
  std::string text = read_case_file_text(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/hydrostatic_plate.toml");
  text.replace(text.find("shape = \"rectangle\""), 19, "dimensions = 3\nshape = \"rectangle\"\nbreadth = 0.08");
  text.replace(text.find("[[probes.pressure]]"), std::string::npos, "");
  const CaseSpec spec = read_case_text(text, "plate3d.toml", {});
  const Scene3 scene = build_scene3(spec);
  const double dp = 0.02;
  ASSERT_EQ(scene.plates.size(), 1u);
  const std::vector<double> planes = {0.01, 0.03, 0.05, 0.07};
  ASSERT_EQ(scene.plate_planes.size(), planes.size());
  for (std::size_t m = 0; m < planes.size(); ++m) EXPECT_NEAR(scene.plate_planes[m], planes[m], 1e-15);
  const PlateLayout& layout = scene.plates[0];
  const Particles3& p = scene.particles;
  const std::size_t count = layout.walls.size() * planes.size();
  EXPECT_EQ(scene.plate_first[0] + count, p.size());  // the last wall particles
  std::vector<Vec3> plate;
  for (std::size_t k = 0; k < layout.walls.size(); ++k)
    for (std::size_t m = 0; m < planes.size(); ++m) {
      const std::size_t w = scene.plate_first[0] + k * planes.size() + m;
      EXPECT_NEAR(p.position[w].x, layout.walls[k].position.x, 1e-15);
      EXPECT_NEAR(p.position[w].y, planes[m], 1e-15);
      EXPECT_NEAR(p.position[w].z, layout.walls[k].position.y, 1e-15);
      EXPECT_EQ(p.normal[w].y, 0.0);
      plate.push_back(p.position[w]);
    }
  double closest = 1.0;
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    for (const Vec3& q : plate) closest = std::min(closest, norm(p.position[i] - q));
  EXPECT_GE(closest, 0.9 * dp);
  // The water above the plate only (the block from its upper face): 100 x 50 section nodes a plane.
  EXPECT_EQ(p.n_fluid, 100u * 50u * planes.size());
  const std::string cylinder = read_case_file_text(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/cylinder3d_sloshing.toml");
  EXPECT_THROW(read_case_text(cylinder + "\n[[plates]]\nname = \"p\"\nx = 0.15\nheight = 0.1\nthickness = 0.02\n"
                              "youngs_modulus = 1e7\ndensity = 1100\n",
                              "cyl.toml", {}),
               InputError);
}

// Issue 31, section 2: explicit slats in an upright cylinder (R = 0.15 m, dp = 10 mm). A screen in
// the plane x = 0.12 m is the section's slat walls (explicit_slat_walls) on every lattice line y =
// (j + 1/2) dp inside the circle: each slat particle keeps its section position (x, z), stands
// inside the circle, and the count is the section's walls times the lines whose point lies inside
// (counted here from the circle). The same screen in the plane y = 0.12 m is its mirror image (x <->
// y, to 1e-12 m). No fluid particle is closer than 0.9 dp to a slat particle (as in 2D).
TEST(ThreeD, ExplicitSlatsInACylinderSpanTheChordOfTheirPlane) {
  const std::string cylinder = read_case_file_text(std::string(SLOSHSPH_SOURCE_DIR) + "/cases/cylinder3d_sloshing.toml");
  const std::string slats = "\n[[screens]]\nname = \"S\"\nslat_height = 0.02\nslat_gap = 0.02\nthickness = 0.004\n"
                            "model = \"explicit\"\n";
  const CaseSpec spec_x = read_case_text(cylinder + slats + "x = 0.12\n", "x.toml", {});
  const Scene3 bare = build_scene3(read_case_text(cylinder, "bare.toml", {}));
  const Scene3 at_x = build_scene3(spec_x);
  const Scene3 at_y = build_scene3(read_case_text(cylinder + slats + "y = 0.12\n", "y.toml", {}));
  const std::vector<Vec3> walls_x = slat_walls_of(at_x, bare), walls_y = slat_walls_of(at_y, bare);
  const double R = 0.15, dp = 0.01;
  TankSpec section_spec = spec_x.tank;
  section_spec.shape = "rectangle";
  section_spec.length = 2.0 * R;
  ScreenSpec screen = spec_x.screens.at(0);
  screen.from = {0.12, 0.0};
  screen.to = {0.12, section_spec.height};
  const std::vector<WallSample> section = explicit_slat_walls(screen, dp, make_tank(section_spec, "test"));
  std::size_t expected = 0;
  for (const WallSample& w : section)
    for (int j = 0; j < 30; ++j)
      if (std::hypot(w.position.x - R, (j + 0.5) * dp - R) < R) ++expected;
  EXPECT_EQ(walls_x.size(), expected);
  ASSERT_GT(walls_x.size(), section.size());
  for (const Vec3& q : walls_x) {
    EXPECT_LT(std::hypot(q.x - R, q.y - R), R);
    EXPECT_NEAR(q.x, 0.12, 0.5 * 0.004 + 1e-12);
  }
  ASSERT_EQ(walls_x.size(), walls_y.size());
  auto key = [](Vec3 r) { return std::array<long, 3>{std::lround(r.x * 1e6), std::lround(r.y * 1e6), std::lround(r.z * 1e6)}; };
  std::vector<std::array<long, 3>> mirrored_x, keys_y;
  for (const Vec3& q : walls_x) mirrored_x.push_back(key({q.y, q.x, q.z}));
  for (const Vec3& q : walls_y) keys_y.push_back(key(q));
  std::sort(mirrored_x.begin(), mirrored_x.end());
  std::sort(keys_y.begin(), keys_y.end());
  EXPECT_EQ(mirrored_x, keys_y);
  EXPECT_GE(closest_fluid_to(at_x, walls_x), 0.9 * dp);
  EXPECT_GE(closest_fluid_to(at_y, walls_y), 0.9 * dp);
  EXPECT_LT(at_x.particles.n_fluid, bare.particles.n_fluid);
}

// Explicit slats through a segment of the plan: in the square box of square_box (dp = 20 mm), a
// screen on the diagonal from (0.1, 0.1) to (0.5, 0.5). Its slat particles lie within half the
// slat thickness of the segment's vertical plane and over the segment's length; their number is the
// section's walls times round(length / dp) lines; the set is its own mirror image about the
// diagonal (x <-> y, to 1e-9 m: the thickness offsets come in pairs); no fluid particle is closer
// than 0.9 dp to one.
TEST(ThreeD, ExplicitSlatsThroughThePlanStandInTheSegmentsPlane) {
  const Scene3 bare = build_scene3(read_case_text(square_box("x = 0.3").substr(0, square_box("x = 0.3").find("[[screens]]")),
                                                  "bare.toml", {}));
  const CaseSpec spec = read_case_text(square_box("plan_from = [0.1, 0.1]\nplan_to = [0.5, 0.5]"), "d.toml", {});
  const Scene3 diagonal = build_scene3(spec);
  const std::vector<Vec3> walls = slat_walls_of(diagonal, bare);
  const double length = std::sqrt(2.0) * 0.4, dp = 0.02;
  ScreenSpec screen = spec.screens.at(0);
  screen.from = {0.3, 0.0};
  screen.to = {0.3, 0.3};
  TankSpec section_spec = spec.tank;
  const std::vector<WallSample> section = explicit_slat_walls(screen, dp, make_tank(section_spec, "test"));
  EXPECT_EQ(walls.size(), section.size() * static_cast<std::size_t>(std::lround(length / dp)));
  const double c = std::sqrt(0.5);
  std::vector<std::array<long, 3>> keys, mirrored;
  for (const Vec3& q : walls) {
    const double along = (q.x - 0.1) * c + (q.y - 0.1) * c, across = -(q.x - 0.1) * c + (q.y - 0.1) * c;
    EXPECT_NEAR(across, 0.0, 0.5 * 0.004 + 1e-12);
    EXPECT_GT(along, 0.0);
    EXPECT_LT(along, length);
    keys.push_back({std::lround(q.x * 1e9), std::lround(q.y * 1e9), std::lround(q.z * 1e9)});
    mirrored.push_back({std::lround(q.y * 1e9), std::lround(q.x * 1e9), std::lround(q.z * 1e9)});
  }
  std::sort(keys.begin(), keys.end());
  std::sort(mirrored.begin(), mirrored.end());
  EXPECT_EQ(keys, mirrored);
  EXPECT_GE(closest_fluid_to(diagonal, walls), 0.9 * dp);
}

}  // namespace
}  // namespace sloshsph
