// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_matlab_write.h"

#include <complex>
#include <cstring>

#include "vnl/vnl_matlab_header.h"

inline namespace edgetrack_ports {

namespace {
constexpr std::int32_t kNativeByteOrder =
    __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__ ? vnl_matlab_header::vnl_BIG_ENDIAN : vnl_matlab_header::vnl_LITTLE_ENDIAN;

template <class T>
struct matlab_scalar {  // float and double
  static constexpr bool is_complex = false;
  static constexpr bool is_single = sizeof(T) == 4;
  static T real_part(const T& x) { return x; }
  static T imag_part(const T&) { return T(0); }
};
template <class T>
struct matlab_scalar<std::complex<T>> {
  static constexpr bool is_complex = true;
  static constexpr bool is_single = sizeof(T) == 4;
  static T real_part(const std::complex<T>& x) { return x.real(); }
  static T imag_part(const std::complex<T>& x) { return x.imag(); }
};

template <class T>
void write_header(std::ostream& s, std::int32_t storage, unsigned rows, unsigned cols, const char* name) {
  vnl_matlab_header hdr;
  hdr.type =
      kNativeByteOrder + storage +
      (matlab_scalar<T>::is_single ? vnl_matlab_header::vnl_SINGLE_PRECISION : vnl_matlab_header::vnl_DOUBLE_PRECISION);
  hdr.rows = static_cast<std::int32_t>(rows);
  hdr.cols = static_cast<std::int32_t>(cols);
  hdr.imag = matlab_scalar<T>::is_complex ? 1 : 0;
  hdr.namlen = static_cast<std::int32_t>(std::strlen(name) + 1);
  s.write(reinterpret_cast<const char*>(&hdr), sizeof hdr);
  s.write(name, hdr.namlen);
}

/// The real parts of n values, then (for complex T) their imaginary parts.
template <class T>
void write_values(std::ostream& s, const T* const* rows, unsigned row_count, unsigned n) {
  for (unsigned r = 0; r < row_count; ++r) {
    for (unsigned i = 0; i < n; ++i) {
      const auto x = matlab_scalar<T>::real_part(rows[r][i]);
      s.write(reinterpret_cast<const char*>(&x), sizeof x);
    }
  }
  if (!matlab_scalar<T>::is_complex) return;
  for (unsigned r = 0; r < row_count; ++r) {
    for (unsigned i = 0; i < n; ++i) {
      const auto x = matlab_scalar<T>::imag_part(rows[r][i]);
      s.write(reinterpret_cast<const char*>(&x), sizeof x);
    }
  }
}
}  // namespace

template <class T>
bool vnl_matlab_write(std::ostream& s, const T& x, const char* name) {
  return vnl_matlab_write(s, &x, 1, name);
}

template <class T>
bool vnl_matlab_write(std::ostream& s, const T* v, unsigned n, const char* name) {
  write_header<T>(s, vnl_matlab_header::vnl_COLUMN_WISE, n, 1, name);
  write_values(s, &v, 1, n);
  return s.good();
}

template <class T>
bool vnl_matlab_write(std::ostream& s, const T* const* data, unsigned rows, unsigned cols, const char* name) {
  write_header<T>(s, vnl_matlab_header::vnl_ROW_WISE, rows, cols, name);
  write_values(s, data, rows, cols);
  return s.good();
}

#define VNL_MATLAB_WRITE_INSTANTIATE(T)                                           \
  template bool vnl_matlab_write(std::ostream&, const T&, const char*);           \
  template bool vnl_matlab_write(std::ostream&, const T*, unsigned, const char*); \
  template bool vnl_matlab_write(std::ostream&, const T* const*, unsigned, unsigned, const char*)
VNL_MATLAB_WRITE_INSTANTIATE(float);
VNL_MATLAB_WRITE_INSTANTIATE(double);
VNL_MATLAB_WRITE_INSTANTIATE(std::complex<float>);
VNL_MATLAB_WRITE_INSTANTIATE(std::complex<double>);

}  // inline namespace edgetrack_ports
