// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_bignum_traits.h: vnl_numeric_traits for vnl_bignum (maxval is
/// +Infinity, as upstream).
#pragma once

#ifdef vnl_bignum_traits_h_
#error "edgetrack's drop-in vnl/vnl_bignum_traits.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_bignum.h"
#include "vnl/vnl_numeric_traits.h"

inline namespace edgetrack_ports {

template <>
class vnl_numeric_traits<vnl_bignum> {
 public:
  static inline const vnl_bignum zero = vnl_bignum(0L);
  static inline const vnl_bignum one = vnl_bignum(1L);
  static inline const vnl_bignum maxval = vnl_bignum("+Inf");
  using abs_t = vnl_bignum;
  using double_t = vnl_bignum;
  using real_t = double;
  using self = vnl_bignum;
  using signed_t = vnl_bignum;
};

}  // inline namespace edgetrack_ports
