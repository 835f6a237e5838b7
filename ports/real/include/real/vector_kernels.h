// SPDX-License-Identifier: BSD-3-Clause
/// Which code the vectorised hot loops run: the widest vectors the CPU has (AVX2 on an x86-64
/// that runs it, chosen at run time so that a baseline x86-64 package still runs anywhere), the
/// build's baseline vectors (SSE2 on x86-64), or the scalar reference. Every vector kernel does,
/// lane by lane, the operations of its scalar reference in the same order (integer sums, or one
/// whole floating-point expression per lane, never a reordered sum), so the choice changes the
/// speed and never a result: the tests run each choice and compare every control point, match
/// and pose to the last bit.
#pragma once

namespace vector_kernels {

enum class Choice {
  kWidest,    ///< the default: the widest vectors of this CPU
  kBaseline,  ///< the vectors every CPU of the build's target has
  kScalar     ///< the scalar reference, one position at a time
};

/// Sets the choice for every tracker of the process (tests, benchmarks); kWidest until then.
void choose(Choice choice);
Choice chosen();

/// True when kWidest is chosen and the CPU (and the OS) run AVX2: an x86-64 build then takes
/// its AVX2 kernels.
bool avx2();

// GCC builds a kernel twice, vectorised and one by one, where the target has a vector unit; a
// 32-bit ARM without NEON (the PXA270, a Cortex-M3) has none, so its one copy is the reference.
#if defined(__GNUC__) && !defined(__clang__) && !(defined(__arm__) && !defined(__ARM_NEON))
#define EDGETRACK_VECTOR_KERNELS_TWICE 1
#endif

namespace detail {
#if defined(EDGETRACK_VECTOR_KERNELS_TWICE)
#if defined(__x86_64__)
template <class Body>
[[gnu::target("avx2")]] auto built_for_avx2(const Body& body) {
  return body();
}
#endif
template <class Body>
[[gnu::optimize("no-tree-vectorize")]] auto built_one_by_one(const Body& body) {
  return body();
}
#endif
}  // namespace detail

/// Runs body(), a lambda marked __attribute__((always_inline)) whose loops the compiler
/// vectorises one element per lane, built for the chosen kernels: for AVX2 when avx2(), without
/// vectorisation (the scalar reference) when kScalar is chosen, else for the build's target.
template <class Body>
auto run(const Body& body) {
#if defined(EDGETRACK_VECTOR_KERNELS_TWICE)
#if defined(__x86_64__)
  if (avx2()) return detail::built_for_avx2(body);
#endif
  if (chosen() == Choice::kScalar) return detail::built_one_by_one(body);
#endif
  return body();
}

}  // namespace vector_kernels
