// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_read.h: reading MATLAB level-4 .mat matrices, header by
/// header, in either byte order (a file written on a machine of the other order is swapped).
/// read_data(...) fills a scalar, a vector (one row or one column) or a 2D array given by row
/// pointers, and is false when the stored type (single or double, real or complex) is not the
/// destination's or the shape does not fit. vnl_matlab_read_or_die reads one vnl_vector or
/// vnl_matrix and, as upstream, aborts on a wrong name or type (false at the end of the data).
#pragma once

#ifdef vnl_matlab_read_h_
#error "edgetrack's drop-in vnl/vnl_matlab_read.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>
#include <istream>
#include <string>

#include "vnl/vnl_matlab_header.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

/// n values: for complex T the file's real block then its imaginary block, interleaved.
template <class T>
void vnl_matlab_read_data(std::istream& s, T* ptr, unsigned n);

class vnl_matlab_readhdr {
 public:
  /// Reads the first header.
  explicit vnl_matlab_readhdr(std::istream& s);

  /// The stream is good (and not at its end).
  explicit operator bool() const { return s_.good() && !s_.eof(); }
  bool operator!() const { return !bool(*this); }
  /// Skips the current matrix's data if it was not read, then reads the next header.
  void read_next();

  bool is_single() const { return (hdr_.type % 100) >= vnl_matlab_header::vnl_SINGLE_PRECISION; }
  bool is_rowwise() const { return (hdr_.type % 1000) >= vnl_matlab_header::vnl_ROW_WISE; }
  bool is_bigendian() const { return (hdr_.type % 10000) >= vnl_matlab_header::vnl_BIG_ENDIAN; }
  long rows() const { return hdr_.rows; }
  long cols() const { return hdr_.cols; }
  bool is_complex() const { return hdr_.imag != 0; }
  const char* name() const { return name_.c_str(); }

  bool read_data(float& v);
  bool read_data(float* p);
  bool read_data(float* const* m);
  bool read_data(double& v);
  bool read_data(double* p);
  bool read_data(double* const* m);
  bool read_data(std::complex<float>& v);
  bool read_data(std::complex<float>* p);
  bool read_data(std::complex<float>* const* m);
  bool read_data(std::complex<double>& v);
  bool read_data(std::complex<double>* p);
  bool read_data(std::complex<double>* const* m);

 private:
  void read_hdr();
  template <class T>
  bool stores();  // the file's values are of type T
  template <class T>
  bool read_values(T* p, long n);
  template <class T>
  bool read_matrix(T* const* m);

  std::istream& s_;
  vnl_matlab_header hdr_{};
  std::string name_;
  bool data_read_ = false;
  bool need_swap_ = false;
};

template <class T>
bool vnl_matlab_read_or_die(std::istream& s, vnl_vector<T>& v, const char* name = nullptr);
template <class T>
bool vnl_matlab_read_or_die(std::istream& s, vnl_matrix<T>& M, const char* name = nullptr);

}  // inline namespace edgetrack_ports
