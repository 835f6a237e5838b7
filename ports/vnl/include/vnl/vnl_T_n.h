// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_T_n.h: vnl_T_n_impl(T, n) declares class vnl_T_n, a
/// vnl_vector_fixed<T, n> with the constructors from n values, as upstream's macro does
/// (our vnl_double_3 and friends are plain aliases, so this is only for user code that
/// declares its own).
#pragma once

#ifdef vnl_T_n_h_
#error "edgetrack's drop-in vnl/vnl_T_n.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_vector_fixed.h"

#define vnl_T_n_class_name(T, n) vnl_##T##_##n
#define vnl_T_n_impl(T, n)                                                           \
  class vnl_T_n_class_name(T, n) : public vnl_vector_fixed<T, n> {                   \
   public:                                                                           \
    using vnl_vector_fixed<T, n>::vnl_vector_fixed;                                  \
    vnl_T_n_class_name(T, n)() = default;                                            \
    vnl_T_n_class_name(T, n)(const vnl_vector_fixed<T, n>& v) : vnl_vector_fixed<T, n>(v) {} \
  }
