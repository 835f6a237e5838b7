// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_math.h: the constants (pi, pi_over_2, pi_over_4 and the others
/// the paper had to add) and the small generic helpers (abs, sqr, cube, sgn, max, min, hypot).
/// The constants are doubles, as upstream; `vnl_math::constant<T>::pi` and friends give the
/// same values already converted to T at compile time, so fixed-point code never converts a
/// double at run time.
#pragma once

#ifdef vnl_math_h_
#error "edgetrack's drop-in vnl/vnl_math.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>
#include <complex>
#include <limits>
#include <type_traits>

inline namespace edgetrack_ports {

namespace vnl_math {

constexpr double e = 2.71828182845904523536;
constexpr double log2e = 1.44269504088896340736;
constexpr double log10e = 0.43429448190325182765;
constexpr double ln2 = 0.69314718055994530942;
constexpr double ln10 = 2.30258509299404568402;
constexpr double pi = 3.14159265358979323846;
constexpr double twopi = 6.28318530717958647692;
constexpr double pi_over_2 = 1.57079632679489661923;
constexpr double pi_over_4 = 0.78539816339744830962;
constexpr double pi_over_180 = 0.01745329251994329577;
constexpr double one_over_pi = 0.31830988618379067154;
constexpr double two_over_pi = 0.63661977236758134308;
constexpr double deg_per_rad = 57.2957795130823208768;
constexpr double sqrt2pi = 2.50662827463100050242;
constexpr double two_over_sqrtpi = 1.12837916709551257390;
constexpr double sqrt2 = 1.41421356237309504880;
constexpr double sqrt1_2 = 0.70710678118654752440;
constexpr double sqrt1_3 = 0.57735026918962573106;
constexpr double one_over_sqrt2pi = 0.39894228040143267794;
/// The Euler-Mascheroni constant (-digamma(1)).
constexpr double euler = 0.57721566490153286061;
constexpr double eps = std::numeric_limits<double>::epsilon();
/// sqrt(eps) of double and of float, as upstream spells them.
constexpr double sqrteps = 1.490116119384766e-08;
constexpr float float_eps = std::numeric_limits<float>::epsilon();
constexpr float float_sqrteps = 3.4526698300e-4f;

/// The constants above as T, computed at compile time.
template <class T>
struct constant {
  static constexpr T pi = T(vnl_math::pi);
  static constexpr T twopi = T(vnl_math::twopi);
  static constexpr T pi_over_2 = T(vnl_math::pi_over_2);
  static constexpr T pi_over_4 = T(vnl_math::pi_over_4);
  static constexpr T pi_over_180 = T(vnl_math::pi_over_180);
  static constexpr T deg_per_rad = T(vnl_math::deg_per_rad);
  static constexpr T sqrt2 = T(vnl_math::sqrt2);
  static constexpr T sqrt1_2 = T(vnl_math::sqrt1_2);
};

template <class T>
T abs(const T& x) {
  if constexpr (std::is_unsigned_v<T>) {
    return x;
  } else {
    return x < T(0) ? -x : x;
  }
}
template <class T>
T abs(const std::complex<T>& x) {
  return std::abs(x);
}
/// |x|^2: x*x, or norm(x) for complex x (upstream's vnl_math::squared_magnitude).
template <class T>
T squared_magnitude(const T& x) {
  return x * x;
}
template <class T>
T squared_magnitude(const std::complex<T>& x) {
  return std::norm(x);
}
/// The complex conjugate; the value itself for a real scalar.
template <class T>
T conj(const T& x) {
  return x;
}
template <class T>
std::complex<T> conj(const std::complex<T>& x) {
  return std::conj(x);
}
/// Floating-point classification; integers and fixed point are always finite.
template <class T>
bool isnan(const T& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::isnan(x);
  } else {
    return false;
  }
}
template <class T>
bool isnan(const std::complex<T>& x) {
  return vnl_math::isnan(x.real()) || vnl_math::isnan(x.imag());
}
template <class T>
bool isinf(const T& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::isinf(x);
  } else {
    return false;
  }
}
template <class T>
bool isfinite(const T& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::isfinite(x);
  } else {
    return true;
  }
}
template <class T>
bool isfinite(const std::complex<T>& x) {
  return vnl_math::isfinite(x.real()) && vnl_math::isfinite(x.imag());
}
/// Neither zero, subnormal, infinite nor NaN; a non-zero integer or fixed-point value is normal.
template <class T>
bool isnormal(const T& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::isnormal(x);
  } else {
    return !(x == T(0));
  }
}
/// Rounds to the nearest integer, exact halves to the even one (upstream's, independent of the
/// FPU's rounding mode here).
namespace detail {
template <class F>
int round_half_to_even(F x) {
  const F below = std::floor(x);
  const F fraction = x - below;
  const int r = static_cast<int>(below);
  if (fraction > F(0.5)) return r + 1;
  if (fraction < F(0.5)) return r;
  return r % 2 == 0 ? r : r + 1;
}
}  // namespace detail
inline int rnd_halfinttoeven(float x) { return detail::round_half_to_even(x); }
inline int rnd_halfinttoeven(double x) { return detail::round_half_to_even(x); }
/// Rounds to the nearest integer, exact halves upwards (towards +infinity).
inline int rnd_halfintup(float x) { return static_cast<int>(std::floor(x + 0.5f)); }
inline int rnd_halfintup(double x) { return static_cast<int>(std::floor(x + 0.5)); }
/// Rounds to the nearest integer, halves away from zero (upstream's rnd_halfintup differs
/// only on exact halves of negative numbers).
inline int rnd(double x) { return static_cast<int>(x < 0 ? x - 0.5 : x + 0.5); }
inline int rnd(float x) { return static_cast<int>(x < 0 ? x - 0.5f : x + 0.5f); }
inline int floor(double x) { return static_cast<int>(std::floor(x)); }
inline int floor(float x) { return static_cast<int>(std::floor(x)); }
inline int ceil(double x) { return static_cast<int>(std::ceil(x)); }
inline int ceil(float x) { return static_cast<int>(std::ceil(x)); }
/// x mod y with the sign of x (truncated) or of y (floored).
template <class T>
T remainder_truncated(T x, T y) {
  if constexpr (std::is_integral_v<T>) {
    return x % y;
  } else {
    using std::fmod;
    return fmod(x, y);
  }
}
template <class T>
T remainder_floored(T x, T y) {
  const T r = remainder_truncated(x, y);
  return (r != T(0) && ((r < T(0)) != (y < T(0)))) ? r + y : r;
}
/// The angle in [0, 2 pi) or (-pi, pi].
/// The angle in [0, 2 pi): a tiny negative angle whose sum with 2 pi rounds to 2 pi gives the
/// largest double below 2 pi, as upstream.
inline double angle_0_to_2pi(double angle) {
  const double a = std::fmod(angle, twopi);
  if (a >= 0) return a;
  const double wrapped = a + twopi;
  return wrapped < twopi ? wrapped : std::nextafter(twopi, 0.0);
}
/// The angle in [-pi, pi]: fmod by 2 pi, then one turn off either end, as upstream (small
/// negative angles stay exactly as they are).
inline double angle_minuspi_to_pi(double angle) {
  double a = std::fmod(angle, twopi);
  if (a > pi) a -= twopi;
  if (a < -pi) a += twopi;
  return a;
}
/// Real cube root, for negative x too.
inline double cuberoot(double x) { return std::cbrt(x); }
inline float cuberoot(float x) { return std::cbrt(x); }
template <class T>
T sqr(const T& x) {
  return x * x;
}
template <class T>
T cube(const T& x) {
  return x * x * x;
}
/// -1, 0 or +1.
template <class T>
int sgn(const T& x) {
  return x > T(0) ? 1 : (x < T(0) ? -1 : 0);
}
/// -1 or +1 (+1 for zero).
template <class T>
int sgn0(const T& x) {
  return x < T(0) ? -1 : 1;
}
template <class T>
T max(const T& a, const T& b) {
  return a < b ? b : a;
}
template <class T>
T min(const T& a, const T& b) {
  return b < a ? b : a;
}
/// sqrt(a^2 + b^2) without overflow or underflow of the squares.
template <class T>
T hypot(const T& a, const T& b) {
  using std::sqrt;
  const T x = vnl_math::abs(a);
  const T y = vnl_math::abs(b);
  const T big = x < y ? y : x;
  const T small = x < y ? x : y;
  if (big == T(0)) return T(0);
  const T ratio = small / big;
  return big * sqrt(T(1) + ratio * ratio);
}

}  // namespace vnl_math

/// Type-selected infinities, as upstream's: +infinity for the floating types, the largest value
/// for the integers.
inline long double vnl_huge_val(long double) { return std::numeric_limits<long double>::infinity(); }
inline double vnl_huge_val(double) { return std::numeric_limits<double>::infinity(); }
inline float vnl_huge_val(float) { return std::numeric_limits<float>::infinity(); }
inline long vnl_huge_val(long) { return std::numeric_limits<long>::max(); }
inline int vnl_huge_val(int) { return std::numeric_limits<int>::max(); }
inline short vnl_huge_val(short) { return std::numeric_limits<short>::max(); }
inline char vnl_huge_val(char) { return std::numeric_limits<char>::max(); }

// The free-function spellings of older VXL (the paper's era), for code written against them.
template <class T>
T vnl_math_abs(const T& x) {
  return vnl_math::abs(x);
}
template <class T>
T vnl_math_sqr(const T& x) {
  return vnl_math::sqr(x);
}
template <class T>
T vnl_math_cube(const T& x) {
  return vnl_math::cube(x);
}
template <class T>
int vnl_math_sgn(const T& x) {
  return vnl_math::sgn(x);
}
template <class T>
int vnl_math_sgn0(const T& x) {
  return vnl_math::sgn0(x);
}
template <class T>
T vnl_math_max(const T& a, const T& b) {
  return vnl_math::max(a, b);
}
template <class T>
T vnl_math_min(const T& a, const T& b) {
  return vnl_math::min(a, b);
}
template <class T>
T vnl_math_hypot(const T& a, const T& b) {
  return vnl_math::hypot(a, b);
}

}  // inline namespace edgetrack_ports
