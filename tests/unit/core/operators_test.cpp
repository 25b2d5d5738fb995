// SPH operators on a lattice (thesis section 2.2.3) at h = 1.4 dp.
#include <gtest/gtest.h>

#include "sloshsph/sph/kernel.hpp"
#include "sloshsph/sph/operators.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {
namespace {

struct Lattice {
  std::vector<Vec2> x;
  NeighbourList nl;
  double dp;
  std::size_t centre;
  explicit Lattice(double dp_, int n = 21) : nl(2.8 * dp_, 0.0), dp(dp_) {
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) x.push_back({a * dp, b * dp});
    centre = static_cast<std::size_t>((n / 2) * n + n / 2);
    nl.build(x, x.size());
  }
  // The pairs within the support of kernel k (sph/pairs.hpp), which the operators read.
  template <class K>
  PairList pairs(const K& k) const {
    PairList list;
    list.build(k, x, nl);
    return list;
  }
  // Interior particles: at least 3 dp (beyond the support 2.8 dp) from the lattice edge.
  bool interior(std::size_t i) const {
    const double lo = 3.0 * dp, hi = x.back().x - 3.0 * dp;
    return x[i].x >= lo - 1e-12 && x[i].x <= hi + 1e-12 && x[i].y >= lo - 1e-12 && x[i].y <= hi + 1e-12;
  }
};

TEST(Operators, GradientOfLinearField) {
  // Reference: grad(3x - 2y + 1) = (3, -2). Tolerance 1.5% (the kernel's lattice moment at h = 1.4 dp).
  Lattice L(0.01);
  const WendlandC2 k(1.4 * L.dp);
  const PairList P = L.pairs(k);
  std::vector<double> f;
  for (const Vec2& p : L.x) f.push_back(3.0 * p.x - 2.0 * p.y + 1.0);
  int checked = 0;
  for (std::size_t i = 0; i < L.x.size(); ++i) {
    if (!L.interior(i)) continue;
    const Vec2 g1 = gradient_difference(P, f, L.dp * L.dp, i);
    const Vec2 g2 = gradient_symmetric(P, f, L.dp * L.dp, i);
    for (const Vec2& g : {g1, g2}) {
      EXPECT_NEAR(g.x, 3.0, 0.015 * 3.0);
      EXPECT_NEAR(g.y, -2.0, 0.015 * 2.0);
    }
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(Operators, LaplacianOfQuadraticField) {
  // Reference: lap(x^2 + 2 y^2 - x y) = 2 + 4 = 6. Tolerance 3%.
  Lattice L(0.01);
  const WendlandC2 k(1.4 * L.dp);
  const PairList P = L.pairs(k);
  const double eta2 = 1e-4 * k.h * k.h;
  std::vector<double> f;
  for (const Vec2& p : L.x) f.push_back(p.x * p.x + 2.0 * p.y * p.y - p.x * p.y);
  for (std::size_t i = 0; i < L.x.size(); ++i) {
    if (!L.interior(i)) continue;
    EXPECT_NEAR(laplacian(P, f, L.dp * L.dp, eta2, i), 6.0, 0.03 * 6.0);
  }
}

TEST(Operators, DivergenceOfLinearVelocity) {
  // Reference: div(2x + y, x - 0.5 y) = 1.5. Tolerance 1.5% (as the gradient).
  Lattice L(0.02);
  const WendlandC2 k(1.4 * L.dp);
  const PairList P = L.pairs(k);
  std::vector<Vec2> u;
  for (const Vec2& p : L.x) u.push_back({2.0 * p.x + p.y, p.x - 0.5 * p.y});
  for (std::size_t i = 0; i < L.x.size(); ++i)
    if (L.interior(i)) {
      EXPECT_NEAR(divergence(P, u, L.dp * L.dp, i), 1.5, 0.015 * 1.5);
    }
}

TEST(Operators, SymmetricGradientIsAntisymmetricInPairs) {
  // Eq. 2.4 conserves momentum: sum_i V f-weighted pair forces cancel, so the total of
  // grad_sym(f)_i over all particles (including edges) is zero to round-off.
  Lattice L(0.01, 15);
  const WendlandC2 k(1.4 * L.dp);
  const PairList P = L.pairs(k);
  std::vector<double> f;
  for (const Vec2& p : L.x) f.push_back(1.0 + p.x * p.x + 3.0 * p.y);
  Vec2 total;
  for (std::size_t i = 0; i < L.x.size(); ++i) total += gradient_symmetric(P, f, L.dp * L.dp, i);
  EXPECT_NEAR(total.x, 0.0, 1e-9);
  EXPECT_NEAR(total.y, 0.0, 1e-9);
}

TEST(Operators, KernelSumOnLattice) {
  // Reference: 1 within 1% at h = 1.4 dp (interior), as the kernel test.
  Lattice L(0.005);
  const WendlandC2 k(1.4 * L.dp);
  EXPECT_NEAR(kernel_sum(L.pairs(k), L.dp * L.dp, L.centre), 1.0, 0.01);
}

}  // namespace
}  // namespace sloshsph
