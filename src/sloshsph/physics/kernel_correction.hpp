#pragma once
// Kernel gradient correction and renormalised gradients (Shao et al. 2012 eqs. 15-17;
// the same matrix renormalises the density gradient of delta-SPH, Dincer 2019 eqs. 8-9,
// after Randles & Libersky 1996 and Marrone et al. 2011).
//
// The moment matrix of particle i is
//   M_i = sum_j V_j grad_i W_ij (x) r_ji,   M_kl = sum_j V_j (d W_ij / d x_k) (r_j - r_i)_l,
// (Shao eq. 17 before inversion). For any linear field f, sum_j V_j (f_j - f_i) grad_i W_ij
// = M_i grad f, so L_i = M_i^-1 applied to that sum gives the exact gradient whatever the
// particle disorder or kernel truncation; the corrected kernel gradient is L_i grad_i W_ij
// (Shao eq. 16). For radial kernels grad_i W_ij = F(r) r_ij, so M_i = -sum V F r_ij r_ij^T is
// symmetric and, in a full lattice, close to the identity.
//
// Near a free surface M_i can be singular (a particle with few neighbours, all on a line):
// then no correction is applied (L_i = I), as the renormalisation would amplify noise.
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

struct Mat2 {
  double xx = 1.0, xy = 0.0, yx = 0.0, yy = 1.0;  // identity by default
};

inline Vec2 operator*(const Mat2& m, Vec2 v) { return {m.xx * v.x + m.xy * v.y, m.yx * v.x + m.yy * v.y}; }

inline Mat2 zero_mat2() { return {0.0, 0.0, 0.0, 0.0}; }

// Smallest eigenvalue of the symmetric part of m (m is symmetric for radial kernels).
inline double min_eigenvalue(const Mat2& m) {
  const double a = m.xx, d = m.yy, b = 0.5 * (m.xy + m.yx);
  const double mean = 0.5 * (a + d), diff = 0.5 * (a - d);
  return mean - std::sqrt(diff * diff + b * b);
}

// Smallest eigenvalue of M below which the correction is not applied. In the bulk M ~ I
// (eigenvalues ~1); a particle on a straight free surface keeps about half its support
// (eigenvalue ~0.5 normal to it). 0.1 rejects only nearly one-sided or line-like neighbourhoods,
// where the inverse would multiply the noise of the sum by more than 10.
inline constexpr double kMinCorrectionEigenvalue = 0.1;

// L = M^-1, or the identity when M is (nearly) singular. Returns whether M was inverted.
inline bool invert_moment_matrix(const Mat2& m, Mat2& inverse, double min_eigen = kMinCorrectionEigenvalue) {
  const double det = m.xx * m.yy - m.xy * m.yx;
  if (!(min_eigenvalue(m) > min_eigen) || !(std::abs(det) > 0.0)) {
    inverse = Mat2{};
    return false;
  }
  const double inv = 1.0 / det;
  inverse = {m.yy * inv, -m.xy * inv, -m.yx * inv, m.xx * inv};
  return true;
}

// Adds the pair j of particle i to the moment matrix: V_j grad_i W_ij (x) r_ji with
// grad_i W_ij = F r_ij and r_ji = -r_ij.
inline void add_moment(Mat2& m, Vec2 rij, double volume_j, double gradient_factor) {
  const double c = -volume_j * gradient_factor;
  m.xx += c * rij.x * rij.x;
  m.xy += c * rij.x * rij.y;
  m.yx += c * rij.y * rij.x;
  m.yy += c * rij.y * rij.y;
}

// 3D (issue 31): the same for 3 x 3 matrices.
struct Mat3 {
  double c[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};  // identity by default
};

inline Vec3 operator*(const Mat3& m, Vec3 v) {
  return {m.c[0][0] * v.x + m.c[0][1] * v.y + m.c[0][2] * v.z, m.c[1][0] * v.x + m.c[1][1] * v.y + m.c[1][2] * v.z,
          m.c[2][0] * v.x + m.c[2][1] * v.y + m.c[2][2] * v.z};
}

inline Mat3 zero_mat3() {
  Mat3 m;
  for (auto& row : m.c)
    for (double& v : row) v = 0.0;
  return m;
}

// Smallest eigenvalue of the symmetric part of m: the trigonometric solution of the characteristic
// cubic of a symmetric 3 x 3 matrix (Smith 1961, Commun. ACM 4(4), 168).
inline double min_eigenvalue(const Mat3& m) {
  double a[3][3];
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) a[k][l] = 0.5 * (m.c[k][l] + m.c[l][k]);
  const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  if (off == 0.0) return std::min(a[0][0], std::min(a[1][1], a[2][2]));
  const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
  const double p2 = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) + (a[2][2] - q) * (a[2][2] - q) +
                    2.0 * off;
  const double p = std::sqrt(p2 / 6.0);
  double b[3][3];
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) b[k][l] = (a[k][l] - (k == l ? q : 0.0)) / p;
  const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                     b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
  const double r = std::max(-1.0, std::min(1.0, 0.5 * det));
  const double phi = std::acos(r) / 3.0;
  return q + 2.0 * p * std::cos(phi + 2.0 * 3.141592653589793238 / 3.0);
}

inline bool invert_moment_matrix(const Mat3& m, Mat3& inverse, double min_eigen = kMinCorrectionEigenvalue) {
  const auto& a = m.c;
  const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1], c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2],
               c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  if (!(min_eigenvalue(m) > min_eigen) || !(std::abs(det) > 0.0)) {
    inverse = Mat3{};
    return false;
  }
  const double inv = 1.0 / det;
  auto& r = inverse.c;
  r[0][0] = c00 * inv;
  r[1][0] = c01 * inv;
  r[2][0] = c02 * inv;
  r[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * inv;
  r[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * inv;
  r[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * inv;
  r[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * inv;
  r[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * inv;
  r[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * inv;
  return true;
}

inline void add_moment(Mat3& m, Vec3 rij, double volume_j, double gradient_factor) {
  const double c = -volume_j * gradient_factor;
  const double r[3] = {rij.x, rij.y, rij.z};
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) m.c[k][l] += c * r[k] * r[l];
}

template <int D>
using Mat = std::conditional_t<D == 2, Mat2, Mat3>;

template <int D>
Mat<D> zero_mat() {
  if constexpr (D == 2) return zero_mat2();
  else return zero_mat3();
}

template <int D>
struct BasicRenormalisedGradient {
  Vec<D> gradient;   // L_i sum_j V_j (f_j - f_i) grad_i W_ij
  Mat<D> correction; // L_i (identity when not corrected)
  bool corrected = false;
};
using RenormalisedGradient = BasicRenormalisedGradient<2>;

// The renormalised gradient of f at particle i over the neighbours j of its row for which
// accept(j) is true (Shao eqs. 15-17; Dincer eqs. 8-9). `volume` holds V_j = m_j / rho_j.
template <int D, class Accept>
BasicRenormalisedGradient<D> renormalised_gradient(const BasicPairList<D>& pairs, const std::vector<double>& f,
                                                   const std::vector<double>& volume, std::size_t i, Accept&& accept,
                                                   double min_eigen = kMinCorrectionEigenvalue) {
  Mat<D> m = zero_mat<D>();
  Vec<D> sum;
  pairs.for_each(i, [&](const BasicPair<D>& q) {
    const std::size_t j = q.j;
    if (!accept(j) || q.f == 0.0) return;
    add_moment(m, q.rij, volume[j], q.f);
    sum += q.rij * (volume[j] * (f[j] - f[i]) * q.f);
  });
  BasicRenormalisedGradient<D> g;
  g.corrected = invert_moment_matrix(m, g.correction, min_eigen);
  g.gradient = g.correction * sum;
  return g;
}

// L_i alone (Shao eq. 17), over the neighbours accepted by `accept`.
template <int D, class Accept>
Mat<D> kernel_correction_matrix(const BasicPairList<D>& pairs, const std::vector<double>& volume, std::size_t i,
                                Accept&& accept, double min_eigen = kMinCorrectionEigenvalue) {
  Mat<D> m = zero_mat<D>();
  pairs.for_each(i, [&](const BasicPair<D>& q) {
    if (accept(q.j) && q.f != 0.0) add_moment(m, q.rij, volume[q.j], q.f);
  });
  Mat<D> l;
  invert_moment_matrix(m, l, min_eigen);
  return l;
}

}  // namespace sloshsph
