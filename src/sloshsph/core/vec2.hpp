#pragma once
#include <cmath>

namespace sloshsph {

// A 2D vector in SI units. Plain aggregate so arrays of it stay trivially copyable.
struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

inline constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
inline constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
inline constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
inline constexpr Vec2& operator+=(Vec2& a, Vec2 b) { a.x += b.x; a.y += b.y; return a; }
inline constexpr Vec2& operator-=(Vec2& a, Vec2 b) { a.x -= b.x; a.y -= b.y; return a; }
inline constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::sqrt(dot(a, a)); }
inline constexpr double norm2(Vec2 a) { return dot(a, a); }
// Rotates a by +90 degrees.
inline constexpr Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
// Rotates a by `angle` radians, counter-clockwise.
inline Vec2 rotated(Vec2 a, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * a.x - s * a.y, s * a.x + c * a.y};
}
inline Vec2 normalized(Vec2 a) {
  const double n = norm(a);
  return n > 0.0 ? a / n : Vec2{};
}

}  // namespace sloshsph
