#pragma once
// The few operations a contact law needs of its number type, so that one law serves one contact
// (double) or several side by side (a SIMD type such as the native engine's Lanes). A number
// type R is supported by specialising Number<R>; double is supported here. Comparisons of an R
// give its Mask type (bool for double), and select() picks per element by such a mask.
#include <cmath>

namespace talus {

template <class R> struct Number;

template <> struct Number<double> {
  static double square_root(double x) { return std::sqrt(x); }
  static double select(bool condition, double a, double b) { return condition ? a : b; }
  static double magnitude(double x) { return std::abs(x); }
  static double copy_sign(double size, double sign) { return std::copysign(size, sign); }
  static double power(double x, double y) { return std::pow(x, y); }
  /// Whether every element is zero (a shortcut the laws may take for all of them at once).
  static bool all_zero(double x) { return x == 0.0; }
};

template <class R> R square_root(R x) {
  return Number<R>::square_root(x);
}
/// a where `condition` holds, else b. Both are evaluated: neither may have side effects.
template <class M, class R> R select(M condition, R a, R b) {
  return Number<R>::select(condition, a, b);
}
template <class R> R magnitude(R x) {
  return Number<R>::magnitude(x);
}
/// The magnitude of `size` with the sign of `sign` (std::copysign).
template <class R> R copy_sign(R size, R sign) {
  return Number<R>::copy_sign(size, sign);
}
/// x to the power y (std::pow), y the same for every element.
template <class R> R power(R x, double y) {
  return Number<R>::power(x, y);
}
template <class R> bool all_zero(R x) {
  return Number<R>::all_zero(x);
}
/// The force of size f against the velocity v (none when v is zero): along a 2D contact's
/// tangent, -f for v > 0, f for v < 0 (vector3.hpp has the 3D contact's).
template <class R> R opposing(R f, R v) {
  return select(v > 0.0, -f, select(v < 0.0, f, R{}));
}
/// std::max(x, 0.0): 0 for a negative x, x itself otherwise (NaN stays NaN).
template <class R> R not_below_zero(R x) {
  return select(x < 0.0, R{}, x);
}
/// std::min(a, b): b if b < a, else a.
template <class R> R smaller(R a, R b) {
  return select(b < a, b, a);
}

} // namespace talus
