#pragma once
// A vector in three dimensions of any number type R (number.hpp): the contact laws' vectors in
// 3D (the normal, the tangential velocity, force and spring, the spins and torques). Only what
// the laws need; the operations round as the same lines on doubles do, element by element.
// Through magnitude, copy_sign and select, a tangential law's lines (tangential_laws.hpp) serve
// a 2D contact, whose tangential quantities are scalars along t, and a 3D one, whose are vectors
// in the tangent plane.
#include <type_traits>

#include "talus/number.hpp"

namespace talus {

template <class R> struct Vec3Of { R x{}, y{}, z{}; };
using Vec3 = Vec3Of<double>;

template <class R> Vec3Of<R> operator+(const Vec3Of<R>& a, const Vec3Of<R>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class R> Vec3Of<R> operator-(const Vec3Of<R>& a, const Vec3Of<R>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class R> Vec3Of<R> operator-(const Vec3Of<R>& a) {
  return {-a.x, -a.y, -a.z};
}
template <class R> Vec3Of<R>& operator+=(Vec3Of<R>& a, const Vec3Of<R>& b) {
  a = a + b;
  return a;
}
/// A vector times a number: the number R of its elements, or a double (the timestep).
template <class R> Vec3Of<R> operator*(const R& s, const Vec3Of<R>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class R> Vec3Of<R> operator*(const Vec3Of<R>& a, const R& s) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class R>
Vec3Of<R> operator*(const Vec3Of<R>& a, double s) requires(!std::is_same_v<R, double>) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class R>
Vec3Of<R> operator*(double s, const Vec3Of<R>& a) requires(!std::is_same_v<R, double>) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class R> Vec3Of<R> operator/(const Vec3Of<R>& a, const R& s) {
  return {a.x / s, a.y / s, a.z / s};
}

template <class R> R dot(const Vec3Of<R>& a, const Vec3Of<R>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class R> Vec3Of<R> cross(const Vec3Of<R>& a, const Vec3Of<R>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// |a|: a tangential law's "magnitude" of a vector, as of a 2D contact's signed scalar.
template <class R> R magnitude(const Vec3Of<R>& a) {
  return square_root(dot(a, a));
}
/// A vector of length `size` along `direction` (the vector copy_sign: a 2D law's scalar gets the
/// sign, a 3D law's vector the direction). A zero direction gives NaN: the laws select it away.
template <class R> Vec3Of<R> copy_sign(R size, const Vec3Of<R>& direction) {
  return (size / magnitude(direction)) * direction;
}
/// a where `condition` holds, else b, element by element.
template <class M, class R> Vec3Of<R> select(M condition, const Vec3Of<R>& a, const Vec3Of<R>& b) {
  return {select(condition, a.x, b.x), select(condition, a.y, b.y), select(condition, a.z, b.z)};
}

/// The force of size f against the velocity v (none when v is zero): the viscous Coulomb law's
/// direction, for a 3D contact's tangential velocity.
template <class R> Vec3Of<R> opposing(R f, const Vec3Of<R>& v) {
  return select(magnitude(v) > 0.0, -copy_sign(f, v), Vec3Of<R>{});
}

} // namespace talus
