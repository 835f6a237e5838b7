// SPDX-License-Identifier: BSD-3-Clause
/// Out-of-line copies of every fixed64 operation that runs per frame, for both S47.16 and
/// S40.23, compiled into an object that check_float_free.sh disassembles: none of them may
/// call a soft-float routine (ARM) or use a floating-point instruction (host). Conversions to
/// and from double are left out on purpose: they are the set-up and I/O paths.
#include "real/fixed64.h"

namespace fixed64_probe {
template <int F>
struct Operations {
  using T = fixedpoint::fixed64<F>;
  static T add(T a, T b) { return a + b; }
  static T subtract(T a, T b) { return a - b; }
  static T multiply(T a, T b) { return a * b; }
  static T divide(T a, T b) { return a / b; }
  static T negate(T a) { return -a; }
  static bool less(T a, T b) { return a < b; }
  static T from_int(int i) { return T(i); }
  static int to_int(T a) { return static_cast<int>(a); }
  static T abs(T a) { return fixedpoint::abs(a); }
  static T sqrt(T a) { return fixedpoint::sqrt(a); }
  static T floor(T a) { return fixedpoint::floor(a); }
  static T ceil(T a) { return fixedpoint::ceil(a); }
  static T round(T a) { return fixedpoint::round(a); }
  static T sin(T a) { return fixedpoint::sin(a); }
  static T cos(T a) { return fixedpoint::cos(a); }
  static T tan(T a) { return fixedpoint::tan(a); }
  static T atan(T a) { return fixedpoint::atan(a); }
  static T atan2(T a, T b) { return fixedpoint::atan2(a, b); }
  static T asin(T a) { return fixedpoint::asin(a); }
  static T acos(T a) { return fixedpoint::acos(a); }
  static T exp(T a) { return fixedpoint::exp(a); }
  static T log(T a) { return fixedpoint::log(a); }
};
template struct Operations<16>;
template struct Operations<23>;
}  // namespace fixed64_probe
