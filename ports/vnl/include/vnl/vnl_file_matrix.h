// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_file_matrix.h: a vnl_matrix read from a text file, one row per
/// line (vnl_matrix::read_ascii); converts to false when the file cannot be read. A bad file
/// gets one line on stderr naming it.
#pragma once

#ifdef vnl_file_matrix_h_
#error "edgetrack's drop-in vnl/vnl_file_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdio>
#include <fstream>

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_file_matrix : public vnl_matrix<T> {
 public:
  explicit vnl_file_matrix(const char* filename) {
    std::ifstream in(filename);
    ok_ = in && this->read_ascii(in) && !this->empty();
    if (!ok_) std::fprintf(stderr, "vnl_file_matrix: %s: cannot read a matrix\n", filename);
  }
  explicit operator bool() const { return ok_; }
  bool operator!() const { return !ok_; }

 private:
  bool ok_ = false;
};

}  // inline namespace edgetrack_ports
