#pragma once
// Vectors of 2 and 3 components in SI units: one template, Vec<D>, so that the code written once
// for both dimensions (issue 31: kernels, neighbour search, pairs) reads the same for each. Vec2 and
// Vec3 name the two. Every operation of Vec<2> is written as the 2D code had it (the same
// expressions in the same order), so 2D results keep their bits.
#include <cmath>

namespace sloshsph {

template <int D>
struct Vec;

// Plain aggregates, so arrays of them stay trivially copyable (checkpoints write them as bytes).
template <>
struct Vec<2> {
  double x = 0.0;
  double y = 0.0;
};

template <>
struct Vec<3> {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

// Component k (0: x, 1: y, 2: z) of a vector, for code that loops over the axes.
template <int D>
constexpr double component(Vec<D> a, int k) {
  if constexpr (D == 2) return k == 0 ? a.x : a.y;
  else return k == 0 ? a.x : (k == 1 ? a.y : a.z);
}

// The same component, to be written.
template <int D>
constexpr double& component_ref(Vec<D>& a, int k) {
  if constexpr (D == 2) return k == 0 ? a.x : a.y;
  else return k == 0 ? a.x : (k == 1 ? a.y : a.z);
}

// Applies op to the components pairwise: {op(a.x, b.x), op(a.y, b.y)[, op(a.z, b.z)]}.
template <int D, class Op>
constexpr Vec<D> componentwise(Vec<D> a, Vec<D> b, Op op) {
  if constexpr (D == 2) return {op(a.x, b.x), op(a.y, b.y)};
  else return {op(a.x, b.x), op(a.y, b.y), op(a.z, b.z)};
}
template <int D, class Op>
constexpr Vec<D> componentwise(Vec<D> a, Op op) {
  if constexpr (D == 2) return {op(a.x), op(a.y)};
  else return {op(a.x), op(a.y), op(a.z)};
}

template <int D>
constexpr Vec<D> operator+(Vec<D> a, Vec<D> b) { return componentwise(a, b, [](double u, double v) { return u + v; }); }
template <int D>
constexpr Vec<D> operator-(Vec<D> a, Vec<D> b) { return componentwise(a, b, [](double u, double v) { return u - v; }); }
template <int D>
constexpr Vec<D> operator-(Vec<D> a) { return componentwise(a, [](double u) { return -u; }); }
template <int D>
constexpr Vec<D> operator*(double s, Vec<D> a) { return componentwise(a, [s](double u) { return s * u; }); }
template <int D>
constexpr Vec<D> operator*(Vec<D> a, double s) { return componentwise(a, [s](double u) { return s * u; }); }
template <int D>
constexpr Vec<D> operator/(Vec<D> a, double s) { return componentwise(a, [s](double u) { return u / s; }); }
template <int D>
constexpr Vec<D>& operator+=(Vec<D>& a, Vec<D> b) { return a = a + b; }
template <int D>
constexpr Vec<D>& operator-=(Vec<D>& a, Vec<D> b) { return a = a - b; }
template <int D>
constexpr double dot(Vec<D> a, Vec<D> b) {
  if constexpr (D == 2) return a.x * b.x + a.y * b.y;
  else return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <int D>
double norm(Vec<D> a) { return std::sqrt(dot(a, a)); }
template <int D>
constexpr double norm2(Vec<D> a) { return dot(a, a); }
template <int D>
Vec<D> normalized(Vec<D> a) {
  const double n = norm(a);
  return n > 0.0 ? a / n : Vec<D>{};
}

// Every component finite.
template <int D>
bool is_finite(Vec<D> a) {
  for (int k = 0; k < D; ++k)
    if (!std::isfinite(component(a, k))) return false;
  return true;
}

// 2D only: the scalar cross product, and rotations in the plane.
inline constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
// Rotates a by +90 degrees.
inline constexpr Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
// Rotates a by `angle` radians, counter-clockwise.
inline Vec2 rotated(Vec2 a, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * a.x - s * a.y, s * a.x + c * a.y};
}

// 3D: the vector cross product.
inline constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// A moment r x F in D dimensions: in 2D the scalar about the out-of-plane axis (counter-clockwise
// in the x-y plane positive), in 3D the vector.
template <int D>
using Moment = decltype(cross(Vec<D>{}, Vec<D>{}));

}  // namespace sloshsph
