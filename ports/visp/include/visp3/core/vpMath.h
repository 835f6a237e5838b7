// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpMath.h: the angle conversions, rounding and small helpers that the
/// moving edges and the transformation classes use, on `real` where upstream has double.
/// In fixed-point builds the functions also take double (set-up code written for upstream).
#pragma once

#ifdef vpMATH_HH
#error "edgetrack's drop-in visp3/core/vpMath.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>

#include "real/real.h"

inline namespace edgetrack_ports {

class vpMath {
 public:
  static constexpr real pi() { return real(M_PI); }

  /// Upstream's order, (rad * 180) / pi: in fixed point it also keeps pi's full precision.
  static inline real deg(real rad) { return (rad * 180) / real(M_PI); }
  static inline real rad(real deg) { return (deg * real(M_PI)) / 180; }
  static inline real sqr(real x) { return x * x; }
  /// Nearest integer, halves away from zero (as std::round).
  static inline int round(real x) {
    using std::round;
    return static_cast<int>(round(x));
  }
  static inline int sign(real x) { return x < 0 ? -1 : (x > 0 ? 1 : 0); }
  static inline bool nul(real x, real s = real(0.001)) { return abs(x) < s; }
  static inline bool equal(real x, real y, real s = real(0.001)) { return abs(x - y) < s; }
  static inline bool greater(real x, real y, real s = real(0.001)) { return x > (y - s); }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  static inline real deg(double rad) { return deg(real(rad)); }
  static inline real rad(double deg) { return rad(real(deg)); }
  static inline real sqr(double x) { return sqr(real(x)); }
  static inline int round(double x) { return static_cast<int>(std::round(x)); }
#endif

  template <class Type>
  static Type maximum(const Type& a, const Type& b) { return (a > b) ? a : b; }
  template <class Type>
  static Type minimum(const Type& a, const Type& b) { return (a < b) ? a : b; }
  template <class Type>
  static Type abs(const Type& x) { return (x < 0) ? -x : x; }
  template <class Type>
  static void swap(Type& a, Type& b) {
    const Type t = b;
    b = a;
    a = t;
  }

  /// sin(x) / x, by its series near 0 (|x| < 1e-8 in double, 2^-10 in fixed point).
  static real sinc(real x);
  static real sinc(real sinx, real x);
  /// (1 - cos x) / x^2.
  static real mcosc(real cosx, real x);
  /// (1 - sin(x) / x) / x^2.
  static real msinc(real sinx, real x);
  static int modulo(int a, int n) { return ((a % n) + n) % n; }
};

}  // inline namespace edgetrack_ports
