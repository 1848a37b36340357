#pragma once
// A 2D vector of doubles: positions, velocities and forces in the plane.
#include <cmath>

namespace talus {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr Vec2& operator*=(double s) {
    x *= s;
    y *= s;
    return *this;
  }
  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
  friend constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
/// z-component of the 3D cross product of two in-plane vectors.
constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
/// The in-plane vector omega e_z x a.
constexpr Vec2 cross(double omega, Vec2 a) {
  return {-omega * a.y, omega * a.x};
}
/// The vector rotated by +90 degrees: e_z x a.
constexpr Vec2 perp(Vec2 a) {
  return {-a.y, a.x};
}
constexpr double norm2(Vec2 a) {
  return dot(a, a);
}
inline double norm(Vec2 a) {
  return std::sqrt(norm2(a));
}
/// Whether p lies in the half-open box [lo, hi) (a point on a shared edge counts once).
constexpr bool inside_box(Vec2 p, Vec2 lo, Vec2 hi) {
  return p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y;
}

} // namespace talus
