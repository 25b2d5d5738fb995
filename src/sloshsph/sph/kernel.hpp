#pragma once
// Smoothing kernels with compact support 2h, in 2 or 3 dimensions: the dimension enters only the
// normalisation constant (the integral of W over the plane or space is 1).
// Each kernel offers w(r), and gradient_factor(r) = (dW/dr) / r, so that
// grad_i W_ij = gradient_factor(r_ij) * (r_i - r_j): no division by r, safe at r = 0.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

// Wendland C2 (thesis eq. 2.3): W = 7/(4 pi h^2) (1 + 2q)(1 - q/2)^4, q = r/h <= 2.
// dW/dq = 7/(4 pi h^2) (-5q)(1 - q/2)^3. The extracted thesis text prints the
// derivative with (1 - q/3)^3; the derivative of eq. 2.3 has (1 - q/2)^3.
// In 3D the same polynomial with 21/(16 pi h^3) (Wendland 1995; Dehnen & Aly 2012, Table 1, whose
// support radius H is our 2h).
struct WendlandC2 {
  double h;
  double inv_h;
  double norm;  // 7 / (4 pi h^2) in 2D, 21 / (16 pi h^3) in 3D

  explicit WendlandC2(double h_, int dimensions = 2) : h(h_), inv_h(1.0 / h_), norm(normalisation(h_, dimensions)) {}

  static double normalisation(double h, int dimensions) {
    if (dimensions == 3) return 21.0 / (16.0 * std::numbers::pi * h * h * h);
    return 7.0 / (4.0 * std::numbers::pi * h * h);
  }

  double support() const { return 2.0 * h; }

  double w(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    return w_of(q, 1.0 - 0.5 * q);
  }

  // (dW/dr) / r = norm * (-5 q (1 - q/2)^3) / (h r) = -5 norm (1 - q/2)^3 / h^2.
  double gradient_factor(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    return gradient_factor_of(1.0 - 0.5 * q);
  }

  // w(r) and gradient_factor(r) together and without a branch (the pair layer's one evaluation
  // per pair): the same values for q < 2, and 0 beyond (the gradient factor -0 there).
  void w_and_gradient(double r, double& w_out, double& f_out) const {
    const double q = r * inv_h;
    const double a0 = 1.0 - 0.5 * q;
    const double a = a0 < 0.0 ? 0.0 : a0;  // std::max(a0, 0.0), written so that loops of it vectorise
    w_out = w_of(q, a);
    f_out = gradient_factor_of(a);
  }

 private:
  // The two formulas, of q = r/h and a = 1 - q/2.
  double w_of(double q, double a) const {
    const double a2 = a * a;
    return norm * (1.0 + 2.0 * q) * a2 * a2;
  }
  double gradient_factor_of(double a) const { return -5.0 * norm * a * a * a * inv_h * inv_h; }
};

// Cubic B-spline (Monaghan & Lattanzio 1985): normalisation 10 / (7 pi h^2) in 2D, 1 / (pi h^3) in 3D.
struct CubicSpline {
  double h;
  double inv_h;
  double norm;

  explicit CubicSpline(double h_, int dimensions = 2) : h(h_), inv_h(1.0 / h_), norm(normalisation(h_, dimensions)) {}

  static double normalisation(double h, int dimensions) {
    if (dimensions == 3) return 1.0 / (std::numbers::pi * h * h * h);
    return 10.0 / (7.0 * std::numbers::pi * h * h);
  }

  double support() const { return 2.0 * h; }

  double w(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    if (q < 1.0) return norm * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    const double a = 2.0 - q;
    return norm * 0.25 * a * a * a;
  }

  // dW/dq = norm (-3q + 9/4 q^2) for q < 1, norm (-3/4 (2-q)^2) for 1 <= q < 2.
  double gradient_factor(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    if (q < 1.0) return norm * (-3.0 + 2.25 * q) * inv_h * inv_h;
    if (r <= 0.0) return 0.0;
    const double a = 2.0 - q;
    return norm * (-0.75 * a * a) * inv_h / r;
  }

  void w_and_gradient(double r, double& w_out, double& f_out) const {
    w_out = w(r);
    f_out = gradient_factor(r);
  }
};

// r^2 beyond which a kernel's w and gradient_factor are exactly 0: the pair loops skip such pairs
// (the Verlet skin's) before the square root. Widened by 1e-9 so that rounding can never make it
// stricter than the kernels' own q >= 2.
template <class K>
double kernel_reach2(const K& k) {
  const double s = k.support();
  return s * s * (1.0 + 1e-9);
}

// Calls f(kernel) with the concrete kernel type selected at run time, so that
// hot loops are compiled once per kernel with no per-pair dispatch.
template <class F>
decltype(auto) with_kernel(KernelType type, double h, F&& f, int dimensions = 2) {
  if (type == KernelType::cubic_spline) return f(CubicSpline(h, dimensions));
  return f(WendlandC2(h, dimensions));
}

// Calls f(a, b, c) for every point (a, b, c) of the square (dimensions 2, c = 0) or cubic (3)
// integer lattice within n steps of the origin along each axis, in one fixed order (c, a, b).
template <class F>
void for_each_lattice_point(int dimensions, int n, F&& f) {
  const int nc = dimensions == 3 ? n : 0;
  for (int c = -nc; c <= nc; ++c)
    for (int a = -n; a <= n; ++a)
      for (int b = -n; b <= n; ++b) f(a, b, c);
}

// sum_j W(|r_j|) over the full square (2D) or cubic (3D) lattice of spacing dp around a node, the
// node itself included: the kernel sum of a particle deep in undisturbed fluid, per unit volume
// (area) of a particle (times_particle_volume turns it into sum_j V_j W).
inline double lattice_number_density(KernelType type, double h, double dp, int dimensions = 2) {
  return with_kernel(
      type, h,
      [&](const auto& k) {
        const int n = static_cast<int>(std::ceil(k.support() / dp)) + 1;
        double sum = 0.0;
        for_each_lattice_point(dimensions, n,
                               [&](int a, int b, int c) { sum += k.w(dp * std::sqrt(double(a * a + b * b + c * c))); });
        return sum;
      },
      dimensions);
}

// x dp^D, multiplied out in this order (so that 2D keeps its bits): a density times a particle's
// volume (area in 2D) is its mass.
template <int D>
double times_particle_volume(double x, double dp) {
  if constexpr (D == 2) return x * dp * dp;
  else return x * dp * dp * dp;
}

}  // namespace sloshsph
