#pragma once
// Discrete SPH operators of thesis section 2.2.3, for one particle i over its pairs (the pair
// layer, sph/pairs.hpp). The schemes build their sweeps from the same pair terms
// (laplacian_weight, divergence_term, velocity_gradient), so the lattice tests of these sums
// check the arithmetic the solver runs. Every particle has the same volume V = dp^2 (and mass
// rho0 V); grad_i W_ij = F(r) r_ij. Written once for 2 and 3 dimensions (the pairs of
// BasicPairList<D>): the Taylor expansions behind each sum hold in either.
#include <cmath>
#include <vector>

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

// Pair weight of the Laplacian of Cummins & Rudman (1999), thesis eqs. 2.5 and 2.16 with
// rho_i = rho_j:  lap(f)_i = sum_j lambda_ij (f_i - f_j),  lambda_ij = 2 V F_ij r^2 / (r^2 + eta^2).
// (The extracted eq. 2.5 prints (rho_i^2 + rho_j^2) where eqs. 2.16, 3.4 and 4.11 have
// (rho_i + rho_j)^2; only the latter gives lap(x^2) = 2.)
// eta^2 keeps the weight finite as r -> 0 and follows each scheme's source: the thesis's ISPH
// takes eta = 0.01 h (2.2.3, eta^2 = 1e-4 h^2), Shao et al. (2012) eq. 6 for the WCSPH scheme
// 0.01 h^2 (after Morris et al. 1997). Both are far below dp^2 at h/dp >= 1.2, where the pairs
// are, so the two choices differ by < 1% in the weight of the closest pair.
inline double laplacian_weight(double volume, double gradient_factor, double r2, double eta2) {
  return 2.0 * volume * gradient_factor * r2 / (r2 + eta2);
}

// V (u_j - u_i) . grad_i W_ij: pair term of div(u)_i (du = u_j - u_i).
template <int D>
double divergence_term(double volume, const BasicPair<D>& q, Vec<D> du) {
  return volume * q.f * dot(du, q.rij);
}

// grad(u)_i = sum_j V (u_j - u_i) (x) grad_i W_ij, the velocity gradient of the turbulence closures:
// c[a][b] = du_a/dx_b (in 2D c[0][1] is du/dy).
template <int D>
struct BasicVelocityGradient {
  double c[D][D] = {};
};
using VelocityGradient = BasicVelocityGradient<2>;

template <int D>
BasicVelocityGradient<D> velocity_gradient(const BasicPairList<D>& pairs, const std::vector<Vec<D>>& u,
                                           double volume, std::size_t i) {
  const Vec<D> ui = u[i];
  BasicVelocityGradient<D> g;
  pairs.for_each(i, [&](const BasicPair<D>& q) {
    if (q.f == 0.0) return;
    const Vec<D> du = (u[q.j] - ui) * (volume * q.f);
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) g.c[a][b] += component(du, a) * component(q.rij, b);
  });
  return g;
}

// grad(f)_i = sum_j V (f_j - f_i) grad_i W_ij: exact for linear f up to the kernel's
// lattice moment (within 1% at h = 1.4 dp).
template <int D>
Vec<D> gradient_difference(const BasicPairList<D>& pairs, const std::vector<double>& f, double volume, std::size_t i) {
  Vec<D> g;
  pairs.for_each(i, [&](const BasicPair<D>& q) { g += q.rij * (volume * (f[q.j] - f[i]) * q.f); });
  return g;
}

// Thesis eq. 2.4 with rho_i = rho_j: grad(f)_i = sum_j V (f_i + f_j) grad_i W_ij. Conserves
// momentum (antisymmetric in i, j); equal to gradient_difference plus 2 f_i sum_j V grad_i W_ij,
// which vanishes for a full, symmetric neighbourhood.
template <int D>
Vec<D> gradient_symmetric(const BasicPairList<D>& pairs, const std::vector<double>& f, double volume, std::size_t i) {
  Vec<D> g;
  pairs.for_each(i, [&](const BasicPair<D>& q) { g += q.rij * (volume * (f[q.j] + f[i]) * q.f); });
  return g;
}

// div(u)_i = sum_j V (u_j - u_i) . grad_i W_ij.
template <int D>
double divergence(const BasicPairList<D>& pairs, const std::vector<Vec<D>>& u, double volume, std::size_t i) {
  double d = 0.0;
  pairs.for_each(i, [&](const BasicPair<D>& q) { d += divergence_term(volume, q, u[q.j] - u[i]); });
  return d;
}

// lap(f)_i = sum_j lambda_ij (f_i - f_j) (thesis eq. 2.5).
template <int D>
double laplacian(const BasicPairList<D>& pairs, const std::vector<double>& f, double volume, double eta2,
                 std::size_t i) {
  double l = 0.0;
  pairs.for_each(i, [&](const BasicPair<D>& q) { l += laplacian_weight(volume, q.f, q.r2(), eta2) * (f[i] - f[q.j]); });
  return l;
}

// Kernel sum sum_j V W_ij including the particle itself (thesis eq. 2.2 with f = 1).
template <int D>
double kernel_sum(const BasicPairList<D>& pairs, double volume, std::size_t i) {
  double s = pairs.self_w();
  pairs.for_each(i, [&](const BasicPair<D>& q) { s += q.w; });
  return volume * s;
}

}  // namespace sloshsph
