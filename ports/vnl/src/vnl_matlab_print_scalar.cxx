// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_matlab_print_scalar.h"

#include <cstdio>
#include <cstring>

inline namespace edgetrack_ports {

namespace {
vnl_matlab_print_format resolved(vnl_matlab_print_format format) {
  return format == vnl_matlab_print_format_default ? vnl_matlab_print_format_top() : format;
}

struct layout {
  int width;
  int precision;
  char conversion;  // 'f' or 'e'
};

/// upstream's widths and precisions for a real number of the given kind (float or double).
layout real_layout(vnl_matlab_print_format format, bool is_float) {
  switch (resolved(format)) {
    case vnl_matlab_print_format_long:
      return is_float ? layout{8, 5, 'f'} : layout{16, 13, 'f'};
    case vnl_matlab_print_format_short_e:
      return is_float ? layout{8, 4, 'e'} : layout{10, 4, 'e'};
    case vnl_matlab_print_format_long_e:
      return is_float ? layout{11, 7, 'e'} : layout{20, 14, 'e'};
    default:
      return is_float ? layout{6, 3, 'f'} : layout{8, 4, 'f'};
  }
}

/// "%W.Pf " or "%W.Pe ", and zero as "%Wd " in the f formats, as upstream.
void print_real(double v, layout l, char* buf, std::size_t buf_len) {
  if (v == 0 && l.conversion == 'f') {
    std::snprintf(buf, buf_len, "%*d ", l.width, 0);
  } else if (l.conversion == 'f') {
    std::snprintf(buf, buf_len, "%*.*f ", l.width, l.precision, v);
  } else {
    std::snprintf(buf, buf_len, "%*.*e ", l.width, l.precision, v);
  }
}

/// The real part as a real of width w, then "+Wi"/"-Wi" for the imaginary part, or blanks.
void print_complex(double re, double im, int width, int precision, vnl_matlab_print_format format, char* buf,
                   std::size_t buf_len) {
  const char conversion =
      resolved(format) == vnl_matlab_print_format_short_e || resolved(format) == vnl_matlab_print_format_long_e ? 'e'
                                                                                                                : 'f';
  if (re == 0) {
    std::snprintf(buf, buf_len, "%*d ", width, 0);
  } else {
    std::snprintf(buf, buf_len, conversion == 'e' ? "%*.*e " : "%*.*f ", width, precision, re);
  }
  const std::size_t used = std::strlen(buf);
  if (used + 1 >= buf_len) return;
  if (im == 0) {
    std::snprintf(buf + used, buf_len - used, " %*s  ", width - 1, "");
  } else {
    std::snprintf(buf + used, buf_len - used, conversion == 'e' ? "%c%*.*ei " : "%c%*.*fi ", im < 0 ? '-' : '+',
                  width - 1, precision, im < 0 ? -im : im);
  }
}

bool is_long(vnl_matlab_print_format format) {
  return resolved(format) == vnl_matlab_print_format_long || resolved(format) == vnl_matlab_print_format_long_e;
}
}  // namespace

void vnl_matlab_print_scalar(int v, char* buf, std::size_t buf_len, vnl_matlab_print_format) {
  std::snprintf(buf, buf_len, "%4d ", v);
}

void vnl_matlab_print_scalar(unsigned int v, char* buf, std::size_t buf_len, vnl_matlab_print_format) {
  std::snprintf(buf, buf_len, "%4u ", v);
}

void vnl_matlab_print_scalar(float v, char* buf, std::size_t buf_len, vnl_matlab_print_format format) {
  print_real(v, real_layout(format, true), buf, buf_len);
}

void vnl_matlab_print_scalar(double v, char* buf, std::size_t buf_len, vnl_matlab_print_format format) {
  print_real(v, real_layout(format, false), buf, buf_len);
}

void vnl_matlab_print_scalar(long double v, char* buf, std::size_t buf_len, vnl_matlab_print_format format) {
  vnl_matlab_print_scalar(static_cast<double>(v), buf, buf_len, format);  // as upstream
}

void vnl_matlab_print_scalar(std::complex<float> v, char* buf, std::size_t buf_len, vnl_matlab_print_format format) {
  const bool wide = is_long(format);
  print_complex(v.real(), v.imag(), wide ? 10 : 8, wide ? 6 : 4, format, buf, buf_len);
}

void vnl_matlab_print_scalar(std::complex<double> v, char* buf, std::size_t buf_len, vnl_matlab_print_format format) {
  const bool wide = is_long(format);
  print_complex(v.real(), v.imag(), wide ? 16 : 8, wide ? 12 : 4, format, buf, buf_len);
}

void vnl_matlab_print_scalar(std::complex<long double> v, char* buf, std::size_t buf_len,
                             vnl_matlab_print_format format) {
  vnl_matlab_print_scalar(std::complex<double>(v), buf, buf_len, format);
}

}  // inline namespace edgetrack_ports
