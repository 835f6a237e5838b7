// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_file_vector.h: a vnl_vector read from a text file (all of its
/// whitespace-separated values); converts to false when the file cannot be read.
#pragma once

#ifdef vnl_file_vector_h_
#error "edgetrack's drop-in vnl/vnl_file_vector.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdio>
#include <fstream>

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_file_vector : public vnl_vector<T> {
 public:
  explicit vnl_file_vector(const char* filename) {
    std::ifstream in(filename);
    ok_ = in && this->read_ascii(in) && !this->empty();
    if (!ok_) std::fprintf(stderr, "vnl_file_vector: %s: cannot read a vector\n", filename);
  }
  explicit operator bool() const { return ok_; }
  bool operator!() const { return !ok_; }

 private:
  bool ok_ = false;
};

}  // inline namespace edgetrack_ports
