// SPDX-License-Identifier: BSD-3-Clause
/// The process-wide saturation counter of fixed64 (declared in real/fixed64.h).
#include <cstdint>

#include "real/fixed64.h"

namespace fixedpoint {
namespace {
// The one piece of state the real type keeps: how many results saturated. Plain, not atomic:
// the tracker runs on one thread and ARMv5TE has no 64-bit atomics.
std::uint64_t saturations = 0;
}  // namespace

std::uint64_t saturation_count() noexcept { return saturations; }
void reset_saturation_count() noexcept { saturations = 0; }

namespace detail {
void count_saturation() noexcept { ++saturations; }
}  // namespace detail
}  // namespace fixedpoint
