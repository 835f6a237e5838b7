// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_print_scalar.h: one number as MATLAB prints it, into a
/// buffer of buf_len characters (always terminated) or onto a stream, in upstream's widths:
/// integers "%4d ", doubles "%8.4f " short and "%16.13f " long (zero as a bare 0), "%10.4e "
/// and "%20.14e " for the e formats, floats narrower; complex numbers as "re +imi". A
/// fixed-point real prints as its double value (text output, not arithmetic on real).
#pragma once

#ifdef vnl_matlab_print_scalar_h_
#error "edgetrack's drop-in vnl/vnl_matlab_print_scalar.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>
#include <cstddef>
#include <ostream>

#include "real/fixed64.h"
#include "vnl/vnl_matlab_print_format.h"

inline namespace edgetrack_ports {

void vnl_matlab_print_scalar(int v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);
void vnl_matlab_print_scalar(unsigned int v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);
void vnl_matlab_print_scalar(float v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);
void vnl_matlab_print_scalar(double v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);
void vnl_matlab_print_scalar(long double v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);
void vnl_matlab_print_scalar(std::complex<float> v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);
void vnl_matlab_print_scalar(std::complex<double> v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);
void vnl_matlab_print_scalar(std::complex<long double> v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format = vnl_matlab_print_format_default);

template <int F>
void vnl_matlab_print_scalar(fixedpoint::fixed64<F> v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  vnl_matlab_print_scalar(static_cast<double>(v), buf, buf_len, format);
}

/// The number onto a stream.
template <class T>
std::ostream& vnl_matlab_print_scalar(std::ostream& s, T value,
                                      vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  char buf[1024];
  vnl_matlab_print_scalar(value, buf, sizeof buf, format);
  return s << buf;
}

}  // inline namespace edgetrack_ports
