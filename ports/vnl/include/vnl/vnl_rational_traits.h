// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_rational_traits.h: vnl_numeric_traits for vnl_rational.
#pragma once

#ifdef vnl_rational_traits_h_
#error "edgetrack's drop-in vnl/vnl_rational_traits.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <limits>

#include "vnl/vnl_numeric_traits.h"
#include "vnl/vnl_rational.h"

inline namespace edgetrack_ports {

template <>
class vnl_numeric_traits<vnl_rational> {
 public:
  static inline const vnl_rational zero = vnl_rational(0, 1);
  static inline const vnl_rational one = vnl_rational(1, 1);
  static inline const vnl_rational maxval = vnl_rational(std::numeric_limits<vnl_rational::int_type>::max(), 1);
  using abs_t = vnl_rational;
  using double_t = vnl_rational;
  using real_t = double;
  using self = vnl_rational;
  using signed_t = vnl_rational;
};

}  // inline namespace edgetrack_ports
