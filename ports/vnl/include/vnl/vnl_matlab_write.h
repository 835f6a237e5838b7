// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_write.h: a scalar, a 1D array (a column) or a 2D array
/// given by row pointers (stored row-wise, upstream's flag 100) as one MATLAB level-4 matrix
/// named variable_name (non-null), in the machine's byte order; for float, double and their
/// complex types (the real block, then the imaginary one). True when the stream is still good.
#pragma once

#ifdef vnl_matlab_write_h_
#error "edgetrack's drop-in vnl/vnl_matlab_write.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <ostream>

inline namespace edgetrack_ports {

template <class T>
bool vnl_matlab_write(std::ostream& s, const T& x, const char* variable_name);
template <class T>
bool vnl_matlab_write(std::ostream& s, const T* v, unsigned size, const char* variable_name);
template <class T>
bool vnl_matlab_write(std::ostream& s, const T* const* data, unsigned rows, unsigned cols, const char* variable_name);

}  // inline namespace edgetrack_ports
