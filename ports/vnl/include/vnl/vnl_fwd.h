// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_fwd.h: forward declarations of vnl's classes and typedefs.
#pragma once

#ifdef vnl_fwd_h_
#error "edgetrack's drop-in vnl/vnl_fwd.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

template <class T>
class vnl_numeric_traits;
template <class T>
class vnl_c_vector;
template <class T>
class vnl_vector;
template <class T>
class vnl_vector_ref;
template <class T>
class vnl_matrix;
template <class T>
class vnl_matrix_ref;
template <class T, unsigned int n>
class vnl_vector_fixed;
template <class T, unsigned int num_rows, unsigned int num_cols>
class vnl_matrix_fixed;
template <class T, unsigned int n>
class vnl_vector_fixed_ref;
template <class T, unsigned int n>
class vnl_vector_fixed_ref_const;
template <class T, unsigned int num_rows, unsigned int num_cols>
class vnl_matrix_fixed_ref;
template <class T, unsigned int num_rows, unsigned int num_cols>
class vnl_matrix_fixed_ref_const;
template <class T>
class vnl_quaternion;
template <class Return, class Argument>
class vnl_unary_function;
template <class T>
class vnl_diag_matrix;
template <class T>
class vnl_sym_matrix;
template <class T>
class vnl_sparse_matrix;
template <class T>
class vnl_identity;
class vnl_real_polynomial;
class vnl_random;

using vnl_double_2 = vnl_vector_fixed<double, 2>;
using vnl_double_3 = vnl_vector_fixed<double, 3>;
using vnl_double_4 = vnl_vector_fixed<double, 4>;
using vnl_float_2 = vnl_vector_fixed<float, 2>;
using vnl_float_3 = vnl_vector_fixed<float, 3>;
using vnl_float_4 = vnl_vector_fixed<float, 4>;
using vnl_int_2 = vnl_vector_fixed<int, 2>;
using vnl_int_3 = vnl_vector_fixed<int, 3>;
using vnl_int_4 = vnl_vector_fixed<int, 4>;
using vnl_double_2x2 = vnl_matrix_fixed<double, 2, 2>;
using vnl_double_3x3 = vnl_matrix_fixed<double, 3, 3>;
using vnl_double_3x4 = vnl_matrix_fixed<double, 3, 4>;
using vnl_double_4x4 = vnl_matrix_fixed<double, 4, 4>;
using vnl_float_2x2 = vnl_matrix_fixed<float, 2, 2>;
using vnl_float_3x3 = vnl_matrix_fixed<float, 3, 3>;
using vnl_float_4x4 = vnl_matrix_fixed<float, 4, 4>;

}  // inline namespace edgetrack_ports
