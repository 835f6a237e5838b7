// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_header.h: the 20-byte header of a MATLAB level-4 .mat
/// matrix (type code, rows, cols, imaginary flag, name length with its '\0'), the type code's
/// parts as upstream defines them (byte order 0/1000, storage 0 column-wise / 100 row-wise,
/// precision 0 double / 10 single) and the byte swaps. Fields are std::int32_t (upstream:
/// vxl_int_32).
#pragma once

#ifdef vnl_matlab_header_h_
#error "edgetrack's drop-in vnl/vnl_matlab_header.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdint>

inline namespace edgetrack_ports {

struct vnl_matlab_header {
  std::int32_t type;  // one byte order + one storage + one precision specifier
  std::int32_t rows;
  std::int32_t cols;
  std::int32_t imag;
  std::int32_t namlen;

  enum type_t {
    vnl_DOUBLE_PRECISION = 0,
    vnl_SINGLE_PRECISION = 10,
    vnl_COLUMN_WISE = 0,
    vnl_ROW_WISE = 100,
    vnl_LITTLE_ENDIAN = 0,
    vnl_BIG_ENDIAN = 1000,
    vnl_none = 0
  };
};

namespace byteswap {
/// Reverses the 4 bytes at ptr.
inline void swap32(void* ptr) {
  unsigned char* p = static_cast<unsigned char*>(ptr);
  for (int i = 0; i < 2; ++i) {
    const unsigned char t = p[i];
    p[i] = p[3 - i], p[3 - i] = t;
  }
}
/// Reverses the 8 bytes at ptr.
inline void swap64(void* ptr) {
  unsigned char* p = static_cast<unsigned char*>(ptr);
  for (int i = 0; i < 4; ++i) {
    const unsigned char t = p[i];
    p[i] = p[7 - i], p[7 - i] = t;
  }
}
}  // namespace byteswap

}  // inline namespace edgetrack_ports
