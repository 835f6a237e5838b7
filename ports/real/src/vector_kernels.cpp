// SPDX-License-Identifier: BSD-3-Clause
/// The kernels' choice: one process-wide setting, read where a batch of work starts.
#include "real/vector_kernels.h"

#include <atomic>

namespace vector_kernels {
namespace {

std::atomic<int> the_choice{static_cast<int>(Choice::kWidest)};

/// Whether the CPU runs AVX2; libgcc's test also checks that the OS saves the YMM registers.
bool cpu_runs_avx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool runs = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return runs;
#else
  return false;
#endif
}

}  // namespace

void choose(Choice choice) { the_choice.store(static_cast<int>(choice), std::memory_order_relaxed); }

Choice chosen() { return static_cast<Choice>(the_choice.load(std::memory_order_relaxed)); }

bool avx2() { return chosen() == Choice::kWidest && cpu_runs_avx2(); }

}  // namespace vector_kernels
