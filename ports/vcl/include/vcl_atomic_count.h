// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_atomic_count.h: a thread-safe counter (++, --, read). Upstream picks a
/// platform file from vcl/internal/; std::atomic does that job for every platform we build.
#pragma once

#ifdef vcl_atomic_count_h_
#error "edgetrack's drop-in vcl_atomic_count.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <atomic>

#include "vcl_compiler.h"

inline namespace edgetrack_ports {

class vcl_atomic_count {
 public:
  explicit vcl_atomic_count(long v) : value_(v) {}
  vcl_atomic_count(const vcl_atomic_count&) = delete;
  vcl_atomic_count& operator=(const vcl_atomic_count&) = delete;

  /// Increments and returns the new value.
  long operator++() { return ++value_; }
  /// Decrements and returns the new value.
  long operator--() { return --value_; }
  operator long() const { return value_.load(); }

 private:
  std::atomic<long> value_;
};

}  // inline namespace edgetrack_ports
