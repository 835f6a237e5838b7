// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_error.h: the reports vnl makes on a bad index or size. Each
/// prints one line naming the function and the numbers on stderr, then calls vcl_abort (an
/// index or size error is a programming error, as upstream treats it).
#pragma once

#ifdef vnl_error_h_
#error "edgetrack's drop-in vnl/vnl_error.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cassert>
#include <limits>
#include <type_traits>

inline namespace edgetrack_ports {

[[noreturn]] void vnl_error_vector_index(const char* fcn, int index);
[[noreturn]] void vnl_error_vector_dimension(const char* fcn, int l1, int l2);
[[noreturn]] void vnl_error_vector_va_arg(int n);
[[noreturn]] void vnl_error_matrix_row_index(const char* fcn, unsigned r);
[[noreturn]] void vnl_error_matrix_col_index(const char* fcn, unsigned c);
[[noreturn]] void vnl_error_matrix_dimension(const char* fcn, int r1, int c1, int r2, int c2);
[[noreturn]] void vnl_error_matrix_nonsquare(const char* fcn);
[[noreturn]] void vnl_error_matrix_va_arg(int n);

/// Asserts that an integer value fits in an int (upstream's guard before narrowing).
template <typename T>
inline void vnl_error_assert_int_range(T v) {
  static_assert(std::is_integral_v<T>);
  if constexpr (sizeof(T) > sizeof(int) || (std::is_unsigned_v<T> && sizeof(T) == sizeof(int))) {
    assert(static_cast<long long>(v) <= static_cast<long long>(std::numeric_limits<int>::max()));
    if constexpr (std::is_signed_v<T>) assert(static_cast<long long>(v) >= std::numeric_limits<int>::min());
  }
  (void)v;
}

}  // inline namespace edgetrack_ports
