// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_na.h: "not available", a NaN with R's bit pattern (payload 1954
/// = 0x7A2) that marks missing data as distinct from other NaNs; tests, conversion and text I/O
/// ("NA").
#pragma once

#ifdef vnl_na_h_
#error "edgetrack's drop-in vnl/vnl_na.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

inline namespace edgetrack_ports {

/// The NA value of the argument's type (the argument only picks the type).
double vnl_na(double dummy);
float vnl_na(float dummy);
/// True for NA only, not for other NaNs.
bool vnl_na_isna(double x);
bool vnl_na_isna(float x);
/// Any NaN becomes NA; other values are unchanged.
double vnl_na_nan_to_na(double v);
float vnl_na_nan_to_na(float v);
/// Reads a number or "NA" (then x is NA); writes "NA" for NA, otherwise the number.
void vnl_na_extract(std::istream& is, double& x);
void vnl_na_insert(std::ostream& os, double x);
void vnl_na_extract(std::istream& is, float& x);
void vnl_na_insert(std::ostream& os, float x);

/// Stream wrappers for double and float: `is >> vnl_na_stream(x)` and `os << vnl_na_stream(x)`.
template <class T>
struct vnl_na_stream_t {
  T& x_;
};
template <class T>
struct vnl_na_stream_const_t {
  const T& x_;
};
template <class T>
vnl_na_stream_t<T> vnl_na_stream(T& x) {
  return {x};
}
template <class T>
vnl_na_stream_const_t<T> vnl_na_stream(const T& x) {
  return {x};
}
template <class T>
std::istream& operator>>(std::istream& is, const vnl_na_stream_t<T>& na) {
  vnl_na_extract(is, na.x_);
  return is;
}
template <class T>
std::ostream& operator<<(std::ostream& os, const vnl_na_stream_t<T>& na) {
  vnl_na_insert(os, na.x_);
  return os;
}
template <class T>
std::ostream& operator<<(std::ostream& os, const vnl_na_stream_const_t<T>& na) {
  vnl_na_insert(os, na.x_);
  return os;
}

}  // inline namespace edgetrack_ports
