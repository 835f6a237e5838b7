// SPDX-License-Identifier: BSD-3-Clause
// vnl_sse as upstream's test_alignment.cxx: the kernels give the plain loops' results whatever
// the offset (alignment) of the matrix, vector and result inside a buffer, for sizes 3..7, and
// agree with the vnl_vector / vnl_c_vector operations built on the same arithmetic. Upstream
// checks float with its SSE path; ours is the portable path (no SIMD on the PXA270), run for
// double, float and the configured real.
#include <algorithm>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_c_vector.h"
#include "vnl/vnl_matrix_ref.h"
#include "vnl/vnl_random.h"
#include "vnl/vnl_sse.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_ref.h"
#include "vnl_test_types.h"

namespace {
constexpr unsigned kData = 13;  // not a multiple of 2 or 4: every offset parity occurs

template <class T>
T abs_diff(T a, T b) {
  return a < b ? b - a : a - b;
}

/// Checks every kernel on the n-element views at the given pointers; false on the first miss.
template <class T>
bool kernels_match(const T* mat, const T* vec, const T* vec2, T* result, unsigned n, T tol) {
  using sse = vnl_sse<T>;
  const vnl_vector_ref<T> v(n, const_cast<T*>(vec)), v2(n, const_cast<T*>(vec2));
  bool ok = true;
  sse::element_product(vec, vec2, result, n);
  for (unsigned i = 0; i < n; ++i) ok = ok && result[i] == vec[i] * vec2[i];
  T dot(0), ssd(0), sum(0);
  for (unsigned i = 0; i < n; ++i)
    dot += vec[i] * vec2[i], ssd += (vec[i] - vec2[i]) * (vec[i] - vec2[i]), sum += vec[i];
  ok = ok && abs_diff(sse::dot_product(vec, vec2, n), dot) <= tol && abs_diff(dot_product(v, v2), dot) <= tol;
  ok = ok && abs_diff(sse::euclid_dist_sq(vec, vec2, n), ssd) <= tol && abs_diff(T(vnl_vector_ssd(v, v2)), ssd) <= tol;
  ok = ok && abs_diff(sse::sum(vec, n), sum) <= tol && abs_diff(v.sum(), sum) <= tol;
  sse::matrix_x_vector(mat, vec, result, n, n);
  for (unsigned i = 0; i < n; ++i) {
    T row(0);
    for (unsigned j = 0; j < n; ++j) row += mat[i * n + j] * vec[j];
    ok = ok && abs_diff(result[i], row) <= tol;
  }
  sse::vector_x_matrix(vec, mat, result, n, n);
  for (unsigned j = 0; j < n; ++j) {
    T column(0);
    for (unsigned i = 0; i < n; ++i) column += mat[i * n + j] * vec[i];
    ok = ok && abs_diff(result[j], column) <= tol;
  }
  const T* lowest = std::min_element(vec, vec + n);  // the first of equal elements, as arg_min
  const T* highest = std::max_element(vec, vec + n);
  ok = ok && sse::max(vec, n) == *highest && sse::min(vec, n) == *lowest;
  ok = ok && sse::arg_max(vec, n) == unsigned(highest - vec) && sse::arg_min(vec, n) == unsigned(lowest - vec);
  ok = ok && v.max_value() == *highest && v.arg_max() == std::size_t(highest - vec) &&
       v.arg_min() == std::size_t(lowest - vec);
  return ok;
}

template <class T>
struct check_alignment {
  static void run(const std::string& name) {
    T matrix_data[kData * kData], vector_data[kData], result_data[kData];
    vnl_random rng(1234);
    for (unsigned i = 0; i < kData; ++i) {
      vector_data[i] = T(1.0 + 2.0 * rng.normal64());
      for (unsigned j = 0; j < kData; ++j) matrix_data[i * kData + j] = T(1.0 + 2.0 * rng.normal64());
    }
    const T tol = T(ulps<T>(kData * 1000.0));  // sums of up to 13 products of values below ~8
    for (unsigned n = 3; n < 8; ++n) {
      int misses = 0;
      for (unsigned m = 0; m + n < kData; ++m) {
        for (unsigned v = 0; v + n < kData; ++v) {
          for (unsigned r = 0; r + n < kData; ++r) {
            misses += !kernels_match<T>(matrix_data + m, vector_data + v, matrix_data + m, result_data + r, n, tol);
          }
        }
      }
      TEST((name + ": kernels at every offset, size " + std::to_string(n)).c_str(), misses, 0);
    }
    using sse = vnl_sse<T>;
    TEST((name + ": empty ranges give 0 and unsigned(-1)").c_str(),
         sse::max(vector_data, 0) == T(0) && sse::arg_min(vector_data, 0) == unsigned(-1), true);
    void* block = vnl_sse_alloc(5, sizeof(T));
    TEST((name + ": vnl_sse_alloc gives memory").c_str(), block != nullptr, true);
    vnl_sse_dealloc(block, 5, sizeof(T));
  }
};
}  // namespace

static void test_alignment() { for_each_test_scalar<check_alignment>(); }

TESTMAIN(test_alignment)
