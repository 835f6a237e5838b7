// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_int_matrix.h: vnl_matrix<int> with construction from a file and
/// from a double matrix (each element rounded to nearest).
#pragma once

#ifdef vnl_int_matrix_h_
#error "edgetrack's drop-in vnl/vnl_int_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>
#include <cstdio>
#include <fstream>

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

class vnl_int_matrix : public vnl_matrix<int> {
  using Base = vnl_matrix<int>;

 public:
  vnl_int_matrix() = default;
  /// Reads the matrix from a text file, one row per line.
  explicit vnl_int_matrix(const char* filename) {
    std::ifstream in(filename);
    if (!in || !read_ascii(in)) std::fprintf(stderr, "vnl_int_matrix: %s: cannot read a matrix\n", filename);
  }
  vnl_int_matrix(unsigned r, unsigned c) : Base(r, c) {}
  vnl_int_matrix(unsigned r, unsigned c, int fillvalue) : Base(r, c, fillvalue) {}
  vnl_int_matrix(const vnl_matrix<double>& d) : Base(d.rows(), d.cols()) {
    for (std::size_t i = 0; i < size(); ++i) data_block()[i] = static_cast<int>(std::lround(d.data_block()[i]));
  }
  vnl_int_matrix(const vnl_matrix<int>& d) : Base(d) {}
  vnl_int_matrix& operator=(const vnl_matrix<int>& d) {
    Base::operator=(d);
    return *this;
  }
};

}  // inline namespace edgetrack_ports
