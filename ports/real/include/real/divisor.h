// SPDX-License-Identifier: BSD-3-Clause
/// Several quotients over one divisor in any real: a point's depth divides both its projection
/// and the projection's derivative.
#pragma once

#include "real/real.h"

/// x / d for several x over one d, each quotient bit for bit as x / d. Floating point: the
/// division itself. Fixed point: fixedpoint::fixed64_divisor, which normalises d and computes
/// its reciprocal once (most of a division's work on a core without a divider).
template <class T>
class Divisor {
 public:
  explicit Divisor(T d) : d_(d) {}
  T divide(T x) const { return x / d_; }

 private:
  T d_;
};

template <int F>
class Divisor<fixedpoint::fixed64<F>> : public fixedpoint::fixed64_divisor<F> {
 public:
  using fixedpoint::fixed64_divisor<F>::fixed64_divisor;
};
