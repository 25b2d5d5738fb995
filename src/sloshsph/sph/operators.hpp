#pragma once
// Discrete SPH operators of thesis section 2.2.3, for one particle i over its neighbour
// row. The schemes fuse these sums into their sweeps through the same pair weights
// (laplacian_weight, gradient_factor), and the unit tests check them on lattices.
// Every particle has the same volume V = dp^2 (and mass rho0 V); grad_i W_ij = F(r) r_ij.
#include <cmath>
#include <vector>

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {

// Pair weight of the Laplacian of Cummins & Rudman (1999), thesis eqs. 2.5 and 2.16 with
// rho_i = rho_j:  lap(f)_i = sum_j lambda_ij (f_i - f_j),  lambda_ij = 2 V F_ij r^2 / (r^2 + eta^2).
// (The extracted eq. 2.5 prints (rho_i^2 + rho_j^2) where eqs. 2.16, 3.4 and 4.11 have
// (rho_i + rho_j)^2; only the latter gives lap(x^2) = 2.)
inline double laplacian_weight(double volume, double gradient_factor, double r2, double eta2) {
  return 2.0 * volume * gradient_factor * r2 / (r2 + eta2);
}

// grad(f)_i = sum_j V (f_j - f_i) grad_i W_ij: exact for linear f up to the kernel's
// lattice moment (within 1% at h = 1.4 dp).
template <class K>
Vec2 gradient_difference(const K& k, const std::vector<Vec2>& x, const std::vector<double>& f, double volume,
                         const NeighbourList& nl, std::size_t i) {
  Vec2 g;
  for (auto it = nl.begin(i); it != nl.end(i); ++it) {
    const Vec2 rij = x[i] - x[*it];
    g += rij * (volume * (f[*it] - f[i]) * k.gradient_factor(norm(rij)));
  }
  return g;
}

// Thesis eq. 2.4 with rho_i = rho_j: grad(f)_i = sum_j V (f_i + f_j) grad_i W_ij. Conserves
// momentum (antisymmetric in i, j); equal to gradient_difference plus 2 f_i sum_j V grad_i W_ij,
// which vanishes for a full, symmetric neighbourhood.
template <class K>
Vec2 gradient_symmetric(const K& k, const std::vector<Vec2>& x, const std::vector<double>& f, double volume,
                        const NeighbourList& nl, std::size_t i) {
  Vec2 g;
  for (auto it = nl.begin(i); it != nl.end(i); ++it) {
    const Vec2 rij = x[i] - x[*it];
    g += rij * (volume * (f[*it] + f[i]) * k.gradient_factor(norm(rij)));
  }
  return g;
}

// div(u)_i = sum_j V (u_j - u_i) . grad_i W_ij.
template <class K>
double divergence(const K& k, const std::vector<Vec2>& x, const std::vector<Vec2>& u, double volume,
                  const NeighbourList& nl, std::size_t i) {
  double d = 0.0;
  for (auto it = nl.begin(i); it != nl.end(i); ++it) {
    const Vec2 rij = x[i] - x[*it];
    d += volume * k.gradient_factor(norm(rij)) * dot(u[*it] - u[i], rij);
  }
  return d;
}

// lap(f)_i = sum_j lambda_ij (f_i - f_j) (thesis eq. 2.5).
template <class K>
double laplacian(const K& k, const std::vector<Vec2>& x, const std::vector<double>& f, double volume, double eta2,
                 const NeighbourList& nl, std::size_t i) {
  double l = 0.0;
  for (auto it = nl.begin(i); it != nl.end(i); ++it) {
    const Vec2 rij = x[i] - x[*it];
    const double r2 = norm2(rij);
    l += laplacian_weight(volume, k.gradient_factor(std::sqrt(r2)), r2, eta2) * (f[i] - f[*it]);
  }
  return l;
}

// Kernel sum sum_j V W_ij including the particle itself (thesis eq. 2.2 with f = 1).
template <class K>
double kernel_sum(const K& k, const std::vector<Vec2>& x, double volume, const NeighbourList& nl, std::size_t i) {
  double s = k.w(0.0);
  for (auto it = nl.begin(i); it != nl.end(i); ++it) s += k.w(norm(x[i] - x[*it]));
  return volume * s;
}

}  // namespace sloshsph
