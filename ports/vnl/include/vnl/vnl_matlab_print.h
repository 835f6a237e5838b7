// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_print.h: vectors and matrices printed as MATLAB reads
/// them, each number by vnl_matlab_print_scalar. With a variable name "foo" a vector prints
/// as "foo = [ ... ]\n", a matrix as "foo = [ ...\n" then its rows with " ]" after the last,
/// a diagonal matrix as "foo = diag([ ... ])\n"; without a name only the numbers (a matrix
/// one row per line). Any scalar with a vnl_matlab_print_scalar overload works, `real` too.
#pragma once

#ifdef vnl_matlab_print_h_
#error "edgetrack's drop-in vnl/vnl_matlab_print.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iostream>

#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_matlab_print_format.h"
#include "vnl/vnl_matlab_print_scalar.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_matrix_ref.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

/// The numbers of a 1D array, one after the other.
template <class T>
std::ostream& vnl_matlab_print(std::ostream& s, const T* array, unsigned length,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  for (unsigned j = 0; j < length; ++j) vnl_matlab_print_scalar(s, array[j], format);
  return s;
}

/// A 2D array given by its row pointers, one row per line.
template <class T>
std::ostream& vnl_matlab_print(std::ostream& s, const T* const* array, unsigned rows, unsigned cols,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  for (unsigned i = 0; i < rows; ++i) vnl_matlab_print(s, array[i], cols, format) << '\n';
  return s;
}

namespace vnl_matlab_print_detail {
/// Rows of any matrix with operator[] giving a row pointer, in upstream's named form.
template <class Matrix>
std::ostream& print_rows(std::ostream& s, const Matrix& M, unsigned rows, unsigned cols, const char* variable_name,
                         vnl_matlab_print_format format) {
  if (variable_name) s << variable_name << " = [ ...\n";
  if (variable_name && rows == 0) return s << "];\n";
  for (unsigned i = 0; i < rows; ++i) {
    vnl_matlab_print(s, M[i], cols, format);
    if (variable_name && i + 1 == rows) s << " ]";
    s << '\n';
  }
  return s;
}
template <class T>
std::ostream& print_list(std::ostream& s, const T* data, unsigned n, const char* open, const char* close,
                         const char* variable_name, vnl_matlab_print_format format) {
  if (variable_name) s << variable_name << open;
  vnl_matlab_print(s, data, n, format);
  if (variable_name) s << close;
  return s;
}
}  // namespace vnl_matlab_print_detail

template <class T>
std::ostream& vnl_matlab_print(std::ostream& s, const vnl_diag_matrix<T>& D, const char* variable_name = nullptr,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  return vnl_matlab_print_detail::print_list(s, D.data_block(), D.size(), " = diag([ ", " ])\n", variable_name, format);
}
template <class T>
std::ostream& vnl_matlab_print(std::ostream& s, const vnl_matrix<T>& M, const char* variable_name = nullptr,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  return vnl_matlab_print_detail::print_rows(s, M, M.rows(), M.cols(), variable_name, format);
}
template <class T, unsigned int n, unsigned int m>
std::ostream& vnl_matlab_print(std::ostream& s, const vnl_matrix_fixed<T, n, m>& M, const char* variable_name = nullptr,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  return vnl_matlab_print_detail::print_rows(s, M, n, m, variable_name, format);
}
template <class T>
std::ostream& vnl_matlab_print(std::ostream& s, const vnl_matrix_ref<T>& M, const char* variable_name = nullptr,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  return vnl_matlab_print_detail::print_rows(s, M, M.rows(), M.cols(), variable_name, format);
}
template <class T>
std::ostream& vnl_matlab_print(std::ostream& s, const vnl_vector<T>& v, const char* variable_name = nullptr,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  return vnl_matlab_print_detail::print_list(s, v.data_block(), v.size(), " = [ ", " ]\n", variable_name, format);
}
template <class T, unsigned int n>
std::ostream& vnl_matlab_print(std::ostream& s, const vnl_vector_fixed<T, n>& v, const char* variable_name = nullptr,
                               vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  return vnl_matlab_print_detail::print_list(s, v.data_block(), n, " = [ ", " ]\n", variable_name, format);
}

/// Upstream's debugging macro: prints X with its own name on std::cerr (upstream goes through
/// X.as_ref(), which this port's containers do not have).
#define MATLABPRINT(X) (vnl_matlab_print(std::cerr, (X), #X))

}  // inline namespace edgetrack_ports
