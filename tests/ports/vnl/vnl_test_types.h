// SPDX-License-Identifier: BSD-3-Clause
/// Test helpers for the vnl tests: the scalars each test runs for (double, float and the
/// configured `real`) and a tolerance per scalar, named after it.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "real/real.h"

/// `scale` units in the last place of T, as a double tolerance for TEST_NEAR.
template <class T>
double ulps(double scale) {
  return scale * static_cast<double>(std::numeric_limits<T>::epsilon());
}

/// Runs `check<T>(name)` for double, float and the configured real (once if real is one of them).
template <template <class> class Check>
void for_each_test_scalar() {
  Check<double>::run("double");
  Check<float>::run("float");
  if (std::string(real_name()) != "double" && std::string(real_name()) != "float") Check<real>::run(real_name());
}

/// fixedpoint::saturation_count() for fixed-point T, 0 for floating point.
template <class T>
std::uint64_t saturation_count() {
  if constexpr (std::numeric_limits<T>::is_iec559) {
    return 0;
  } else {
    return fixedpoint::saturation_count();
  }
}
