// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_decnum_traits.h: vnl_numeric_traits for vnl_decnum (maxval is
/// +Inf and real_t vnl_decnum itself, as upstream).
#pragma once

#ifdef vnl_decnum_traits_h_
#error "edgetrack's drop-in vnl/vnl_decnum_traits.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_decnum.h"
#include "vnl/vnl_numeric_traits.h"

inline namespace edgetrack_ports {

template <>
class vnl_numeric_traits<vnl_decnum> {
 public:
  static inline const vnl_decnum zero = vnl_decnum(0L);
  static inline const vnl_decnum one = vnl_decnum(1L);
  static inline const vnl_decnum maxval = vnl_decnum("+Inf");
  using abs_t = vnl_decnum;
  using double_t = vnl_decnum;
  using real_t = vnl_decnum;
  using self = vnl_decnum;
  using signed_t = vnl_decnum;
};

}  // inline namespace edgetrack_ports
