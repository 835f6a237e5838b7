// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_identity.h: the identity function f(x) = x as a vnl_unary_function.
#pragma once

#ifdef vnl_identity_h_
#error "edgetrack's drop-in vnl/vnl_identity.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_unary_function.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_identity : public vnl_unary_function<T, T> {
 public:
  vnl_unary_function<T, T>* Copy() const override { return new vnl_identity<T>(*this); }
  T f(const T& x) override { return x; }
};

}  // inline namespace edgetrack_ports
