// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_alloc.h: upstream's raw-memory allocator interface. Upstream
/// keeps SGI-style free lists of small blocks in static state; ours forwards to operator new
/// and delete (no shared state), which modern allocators make as fast.
#pragma once

#ifdef vnl_alloc_h_
#error "edgetrack's drop-in vnl/vnl_alloc.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>
#include <cstring>
#include <new>

inline namespace edgetrack_ports {

class vnl_alloc {
 public:
  /// n bytes (n > 0).
  static void* allocate(std::size_t n) { return ::operator new(n); }
  static void deallocate(void* p, std::size_t /*n*/) { ::operator delete(p); }
  /// A block of new_sz bytes holding the first min(old_sz, new_sz) bytes of p.
  static void* reallocate(void* p, std::size_t old_sz, std::size_t new_sz) {
    void* result = allocate(new_sz);
    std::memcpy(result, p, old_sz < new_sz ? old_sz : new_sz);
    deallocate(p, old_sz);
    return result;
  }
};

}  // inline namespace edgetrack_ports
