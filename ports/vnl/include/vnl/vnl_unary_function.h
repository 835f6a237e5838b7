// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_unary_function.h: an abstract function object Return f(Argument)
/// with an optional range, used by vnl_identity and the minimisers.
#pragma once

#ifdef vnl_unary_function_h_
#error "edgetrack's drop-in vnl/vnl_unary_function.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

template <class Return, class Argument>
class vnl_unary_function {
 public:
  virtual ~vnl_unary_function() = default;
  virtual Return f(const Argument& x) = 0;
  /// The smallest and largest values f may return (upstream: numeric limits).
  virtual Return get_range_min() const;
  virtual Return get_range_max() const;
  /// A heap copy; nullptr unless a subclass provides one (as upstream).
  virtual vnl_unary_function* Copy() const { return nullptr; }
};
}  // inline namespace edgetrack_ports

#include <limits>

inline namespace edgetrack_ports {

template <class Return, class Argument>
Return vnl_unary_function<Return, Argument>::get_range_min() const {
  return std::numeric_limits<Return>::lowest();
}
template <class Return, class Argument>
Return vnl_unary_function<Return, Argument>::get_range_max() const {
  return std::numeric_limits<Return>::max();
}

}  // inline namespace edgetrack_ports
