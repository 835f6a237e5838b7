// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_block.h: element-wise operations on plain arrays of n T's:
/// sum, product, extrema and their indices, copy, reverse, scale, the four arithmetic
/// operations, negate, invert, axpy (y += a x) and fill. An extremum of an empty block is an
/// error, reported by vnl_block_raise_exception (one line on stderr, then vcl_abort).
#pragma once

#ifdef vnl_block_h_
#error "edgetrack's drop-in vnl/vnl_block.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>

inline namespace edgetrack_ports {

[[noreturn]] void vnl_block_raise_exception(const char* file, int line, const char* why);

template <class T>
T vnl_block_sum(const T x[], unsigned n) {
  T total(0);
  for (unsigned i = 0; i < n; ++i) total += x[i];
  return total;
}
template <class T>
T vnl_block_product(const T x[], unsigned n) {
  T total(1);
  for (unsigned i = 0; i < n; ++i) total *= x[i];
  return total;
}
template <class T>
unsigned vnl_block_arg_min(const T x[], unsigned n) {
  if (n == 0) vnl_block_raise_exception(__FILE__, __LINE__, "n is 0");
  unsigned best = 0;
  for (unsigned i = 1; i < n; ++i) {
    if (x[i] < x[best]) best = i;
  }
  return best;
}
template <class T>
unsigned vnl_block_arg_max(const T x[], unsigned n) {
  if (n == 0) vnl_block_raise_exception(__FILE__, __LINE__, "n is 0");
  unsigned best = 0;
  for (unsigned i = 1; i < n; ++i) {
    if (x[best] < x[i]) best = i;
  }
  return best;
}
template <class T>
T vnl_block_min_value(const T* x, unsigned n) {
  return x[vnl_block_arg_min(x, n)];
}
template <class T>
T vnl_block_max_value(const T* x, unsigned n) {
  return x[vnl_block_arg_max(x, n)];
}
template <class T>
void vnl_block_copy(const T x[], T y[], unsigned n) {
  std::copy_n(x, n, y);
}
template <class T>
void vnl_block_reverse(T x[], unsigned n) {
  std::reverse(x, x + n);
}
/// x *= a, or y = a x.
template <class T>
void vnl_block_scale(T a, T x[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) x[i] *= a;
}
template <class T>
void vnl_block_scale(T a, const T x[], T y[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) y[i] = a * x[i];
}
/// y += x, or z = x + y.
template <class T>
void vnl_block_add(const T x[], T y[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) y[i] += x[i];
}
template <class T>
void vnl_block_add(const T x[], const T y[], T z[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) z[i] = x[i] + y[i];
}
/// z = x - y.
template <class T>
void vnl_block_sub(const T x[], const T y[], T z[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) z[i] = x[i] - y[i];
}
/// y *= x, or z = x * y, element by element.
template <class T>
void vnl_block_mul(const T x[], T y[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) y[i] *= x[i];
}
template <class T>
void vnl_block_mul(const T x[], const T y[], T z[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) z[i] = x[i] * y[i];
}
/// z = x / y, element by element.
template <class T>
void vnl_block_div(const T x[], const T y[], T z[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) z[i] = x[i] / y[i];
}
template <class T>
void vnl_block_negate(const T x[], T y[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) y[i] = -x[i];
}
/// y = 1 / x, element by element.
template <class T>
void vnl_block_invert(const T x[], T y[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) y[i] = T(1) / x[i];
}
/// y += a x.
template <class T>
void vnl_block_axpy(T a, const T x[], T y[], unsigned n) {
  for (unsigned i = 0; i < n; ++i) y[i] += a * x[i];
}
template <class T>
void vnl_block_fill(T x[], unsigned n, T value) {
  std::fill_n(x, n, value);
}

}  // inline namespace edgetrack_ports
