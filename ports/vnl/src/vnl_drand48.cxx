// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_drand48.h"

#include <cstdint>

inline namespace edgetrack_ports {

namespace {
constexpr std::uint64_t kMultiplier = 0x5DEECE66DULL;  // POSIX's a and c
constexpr std::uint64_t kIncrement = 0xB;
constexpr std::uint64_t kMask48 = (std::uint64_t{1} << 48) - 1;
constexpr std::uint64_t kDefaultState = 0x1234ABCD330EULL;  // the state before any srand48

// Process-wide, as upstream's and the C library's (see the header).
std::uint64_t drand48_state = kDefaultState;
}  // namespace

double vnl_drand48() {
  drand48_state = (kMultiplier * drand48_state + kIncrement) & kMask48;
  // A 48-bit integer times 2^-48 is exact in a double.
  return static_cast<double>(drand48_state) * (1.0 / static_cast<double>(std::uint64_t{1} << 48));
}

void vnl_srand48(long seed) {
  const auto low32 = static_cast<std::uint64_t>(static_cast<std::uint32_t>(seed));
  drand48_state = (low32 << 16) | 0x330E;
}

}  // inline namespace edgetrack_ports
