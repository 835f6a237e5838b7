// SPDX-License-Identifier: BSD-3-Clause
/// Counts the heap allocations of the test executable it is linked into (it replaces the global
/// operator new and delete): how many were made and how many bytes are live.
#pragma once

#include <cstddef>
#include <cstdint>

namespace edgetrack_test {

struct AllocationCount {
  std::uint64_t allocations = 0;  ///< operator new calls so far
  std::int64_t live_bytes = 0;    ///< bytes allocated and not yet freed
};

/// The counts now.
AllocationCount allocation_count();

}  // namespace edgetrack_test
