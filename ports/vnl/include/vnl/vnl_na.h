// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_na.h: "not available", a NaN with R's bit pattern (payload 1954
/// = 0x7A2) that marks missing data as distinct from other NaNs; tests, conversion and text I/O
/// ("NA").
#pragma once

#ifdef vnl_na_h_
#error "edgetrack's drop-in vnl/vnl_na.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

/// The NA value of the argument's type (the argument only picks the type).
inline namespace edgetrack_ports {

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

/// Stream wrappers: `is >> vnl_na_stream(x)` and `os << vnl_na_stream(x)`.
struct vnl_na_stream_t {
  double* x;
};
struct vnl_na_stream_const_t {
  double x;
};
inline vnl_na_stream_t vnl_na_stream(double& x) { return {&x}; }
inline vnl_na_stream_const_t vnl_na_stream(const double& x) { return {x}; }
std::istream& operator>>(std::istream& is, const vnl_na_stream_t& na);
std::ostream& operator<<(std::ostream& os, const vnl_na_stream_const_t& na);

}  // inline namespace edgetrack_ports
