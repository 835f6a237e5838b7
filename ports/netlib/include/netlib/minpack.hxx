// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for minpack.h. Include it only to instantiate the solver for a scalar that the
/// library does not instantiate (the LM comparison instantiates four scalars in one program).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "netlib/minpack.h"
#include "real/sum_of_products.h"
#include "real/vector_kernels.h"

inline namespace edgetrack_ports {

namespace netlib {
namespace minpack_detail {

// MINPACK's named constants; converted at compile time, so a fixed-point T runs no double code.
template <class T>
struct k {
  static constexpr T p0001 = T(1.0e-4);
  static constexpr T p001 = T(0.001);
  static constexpr T p05 = T(0.05);
  static constexpr T p1 = T(0.1);
  static constexpr T p25 = T(0.25);
  static constexpr T p5 = T(0.5);
  static constexpr T p75 = T(0.75);
  static constexpr T p9 = T(0.9);
};

template <class T>
T max_of(const T& a, const T& b) {
  return a < b ? b : a;
}
template <class T>
T min_of(const T& a, const T& b) {
  return b < a ? b : a;
}
/// |a| through the type's own abs (fabs for floating point: no branch).
template <class T>
T abs_of(const T& a) {
  using std::abs;
  return abs(a);
}


/// Runs body() built for the chosen vectors (vector_kernels.h) on x86-64, where AVX2 takes four
/// doubles where SSE2 takes two (the AVX2 target has no fused multiply-add: the same roundings);
/// elsewhere as built, the choice's test costing more than it could save.
template <class Body>
__attribute__((always_inline)) inline auto in_chosen_vectors(const Body& body) {
#if defined(__x86_64__)
  return vector_kernels::run(body);
#else
  return body();
#endif
}

/// Floating point: whether every |x[i]| is 0 or in (rdwarf, agiant), where enorm adds the
/// squares plainly, in order (a NaN is not). Separate from the sums, so that the test takes as
/// many components per instruction as the chosen vectors hold (in_chosen_vectors): the
/// comparisons of each component are or-ed into a 64-bit flag, which GCC vectorises.
template <class T>
bool all_plain(int n, const T* x, const T& rdwarf, const T& agiant) {
  const T* __restrict in = x;
  const T small = rdwarf, large = agiant;
  return in_chosen_vectors([&]() __attribute__((always_inline)) {
    long long outside = 0;
    for (int i = 0; i < n; ++i) {
      const T xabs = abs_of(in[i]);
      outside |= static_cast<long long>(((xabs <= small) & (xabs != T(0))) | !(xabs < large));
    }
    return outside == 0;
  });
}

/// Floating point: all_plain(n, x, rdwarf, agiant), and in the same pass `sum`, the squares of
/// x[0..n) added plainly, in order, built for the chosen vectors (each square and test in a lane,
/// the additions one after another as written).
template <class T>
bool plain_sum_of_squares(int n, const T* x, const T& rdwarf, const T& agiant, T& sum) {
  const T* __restrict in = x;
  const T small = rdwarf, large = agiant;
  T squares(0);
  const bool plain = in_chosen_vectors([&]() __attribute__((always_inline)) {
    T s(0);
    long long outside = 0;
    for (int i = 0; i < n; ++i) {
      const T xabs = abs_of(in[i]);
      outside |= static_cast<long long>(((xabs <= small) & (xabs != T(0))) | !(xabs < large));
      s += in[i] * in[i];
    }
    squares = s;
    return outside == 0;
  });
  sum = squares;
  return plain;
}

/// y[i] += s x[i]: MINPACK's loop for floating point, each element's product and sum in a lane
/// (in_chosen_vectors); for fixed point the same operations without the 128-bit product when s
/// is large (real/fixed64.h).
template <class T>
void add_multiple_of(int n, const T& s, const T* x, T* y) {
  if constexpr (!std::numeric_limits<T>::is_iec559) {
    add_multiple(n, s, x, y);
  } else {
    const T* __restrict from = x;
    T* __restrict to = y;
    const T scale = s;
    in_chosen_vectors([&]() __attribute__((always_inline)) {
      for (int i = 0; i < n; ++i) to[i] += from[i] * scale;
    });
  }
}

/// x[i] /= d for i < n (MINPACK's own divisions), each in a lane (in_chosen_vectors).
template <class T>
void divide_each(int n, T* x, const T& d) {
  T* __restrict to = x;
  const T divisor = d;
  in_chosen_vectors([&]() __attribute__((always_inline)) {
    for (int i = 0; i < n; ++i) to[i] /= divisor;
  });
}

/// Swaps x[i] and y[i] for i < n (the pivot's column exchange), each in a lane (in_chosen_vectors).
template <class T>
void swap_each(int n, T* x, T* y) {
  T* __restrict p = x;
  T* __restrict q = y;
  in_chosen_vectors([&]() __attribute__((always_inline)) {
    for (int i = 0; i < n; ++i) {
      const T swap = p[i];
      p[i] = q[i];
      q[i] = swap;
    }
  });
}

/// Floating point: C sums of products of `a` with the columns b[0], ..., b[C - 1], each summed in
/// sum_of_products' order in an accumulator of its own, side by side, so that each addition waits
/// for another column's instead of its own previous one. The same sums bit for bit.
/// Built for the chosen vectors (in_chosen_vectors), GCC takes four rows of the C columns at
/// once and adds them to the C sums row after row, each column's sum in a lane.
template <int C, class T>
void side_by_side_sums(int n, const T* a, T* const* b, T* sums) {
  const T* column[C];
  for (int c = 0; c < C; ++c) column[c] = b[c];
  in_chosen_vectors([&]() __attribute__((always_inline)) {
    T s[C] = {};
    for (int i = 0; i < n; ++i) {
      const T ai = a[i];
      for (int c = 0; c < C; ++c) s[c] += ai * column[c][i];
    }
    for (int c = 0; c < C; ++c) sums[c] = s[c];
  });
}

/// How many sums run side by side: a pose's six Jacobian columns (and with a right-hand side,
/// the five columns and it that the first reflection updates) in one pass, within x86-64's
/// sixteen vector registers.
constexpr int kSideBySide = 6;

/// Fixed point: sums[c] = sum_of_products(n, a, b[c]) for c < count, out of line: inlined into
/// the factorisation, GCC's ARMv5TE code for it takes more guest instructions per frame.
template <class T>
__attribute__((noinline)) void each_sum_of_products(int n, const T* a, T* const* b, int count, T* sums) {
  for (int c = 0; c < count; ++c) sums[c] = sum_of_products(n, a, b[c]);
}

/// sums[c] = sum_of_products(n, a, b[c]) for c < count, at most kSideBySide side by side.
template <class T>
void sums_of_products(int n, const T* a, T* const* b, int count, T* sums) {
  if constexpr (std::numeric_limits<T>::is_iec559) {
    for (int first = 0; first < count; first += kSideBySide) {
      switch (count - first) {
        case 1: side_by_side_sums<1>(n, a, b + first, sums + first); break;
        case 2: side_by_side_sums<2>(n, a, b + first, sums + first); break;
        case 3: side_by_side_sums<3>(n, a, b + first, sums + first); break;
        case 4: side_by_side_sums<4>(n, a, b + first, sums + first); break;
        case 5: side_by_side_sums<5>(n, a, b + first, sums + first); break;
        default: side_by_side_sums<kSideBySide>(n, a, b + first, sums + first); break;
      }
    }
  } else {
    each_sum_of_products(n, a, b, count, sums);
  }
}

}  // namespace minpack_detail

template <class T>
minpack_machine<T> minpack_machine_constants() {
  using std::sqrt;
  using K = minpack_detail::k<T>;
  minpack_machine<T> machine;
  machine.epsmch = std::numeric_limits<T>::epsilon();
  machine.dwarf = std::numeric_limits<T>::min();
  machine.rdwarf = K::p9 * sqrt(std::numeric_limits<T>::min());
  machine.rgiant = K::p9 * sqrt(std::numeric_limits<T>::max());
  return machine;
}

template <class T>
T enorm(int n, const T* x) {
  return enorm(n, x, minpack_machine_constants<T>());
}

template <class T>
T enorm(int n, const T* x, const minpack_machine<T>& machine) {
  using minpack_detail::abs_of;
  using std::sqrt;
  // Fixed point: the exact sum of the raw squares (real/fixed64.h), which needs no scaling.
  if constexpr (!std::numeric_limits<T>::is_iec559) return euclidean_norm(n, x);
  const T agiant = machine.rgiant / T(n);
  // All plain (residuals and Jacobians in pixels always are): the three sums below reduce to
  // sqrt(s2), s2 the squares added in order.
  T squares(0);
  if (minpack_detail::plain_sum_of_squares(n, x, machine.rdwarf, agiant, squares)) return sqrt(squares);
  // Three sums: small components scaled by the largest small one (x3max), large ones by the
  // largest large one (x1max), the rest plainly.
  T s1(0), s2(0), s3(0), x1max(0), x3max(0);
  for (int i = 0; i < n; ++i) {
    const T xabs = abs_of(x[i]);
    // A zero (a residual or Jacobian row of weight 0) joins the plain sum, where it adds +0 and
    // changes nothing, as in MINPACK's small-component branch: so the test stays true on
    // weighted data and a host CPU predicts it. Bitwise operators: one branch, not three.
    if (((xabs > machine.rdwarf) | (xabs == T(0))) & (xabs < agiant)) {
      s2 += xabs * xabs;
    } else if (xabs > machine.rdwarf) {
      if (xabs > x1max) {
        const T ratio = x1max / xabs;
        s1 = T(1) + s1 * (ratio * ratio);
        x1max = xabs;
      } else {
        const T ratio = xabs / x1max;
        s1 += ratio * ratio;
      }
    } else if (xabs > x3max) {
      const T ratio = x3max / xabs;
      s3 = T(1) + s3 * (ratio * ratio);
      x3max = xabs;
    } else if (xabs != T(0)) {
      const T ratio = xabs / x3max;
      s3 += ratio * ratio;
    }
  }
  if (s1 != T(0)) return x1max * sqrt(s1 + (s2 / x1max) / x1max);
  if (s2 != T(0)) {
    if (s2 >= x3max) return sqrt(s2 * (T(1) + (x3max / s2) * (x3max * s3)));
    return sqrt(x3max * ((s2 / x3max) + (x3max * s3)));
  }
  return x3max * sqrt(s3);
}

namespace minpack_detail {

/// norms[c] = enorm(m, a + c * lda) for c < C. Floating point: the plain sums of the C columns
/// side by side (each in enorm's order, each waiting for another's additions instead of its own),
/// and enorm itself for a column with a component outside the plain range.
template <int C, class T>
void side_by_side_norms(int m, const T* a, int lda, T* norms, const minpack_machine<T>& machine) {
  using std::sqrt;
  const T agiant = machine.rgiant / T(m);
  T s[C];
  in_chosen_vectors([&]() __attribute__((always_inline)) {
    T sum[C] = {};
    for (int i = 0; i < m; ++i)
      for (int c = 0; c < C; ++c) sum[c] += a[c * lda + i] * a[c * lda + i];
    for (int c = 0; c < C; ++c) s[c] = sum[c];
  });
  // Columns stored one after another (lda == m) are tested in one pass; a column is tested alone
  // only when some component of them is outside the plain range.
  const bool all = lda == m && all_plain(C * m, a, machine.rdwarf, agiant);
  for (int c = 0; c < C; ++c)
    norms[c] = all || all_plain(m, a + c * lda, machine.rdwarf, agiant) ? sqrt(s[c]) : enorm(m, a + c * lda, machine);
}

/// The norms of the n columns of a (m rows, leading dimension lda), as enorm gives each.
template <class T>
void column_norms(int m, int n, const T* a, int lda, T* norms, const minpack_machine<T>& machine) {
  if constexpr (std::numeric_limits<T>::is_iec559) {
    for (int first = 0; first < n; first += kSideBySide) {
      const T* const column = a + first * lda;
      switch (n - first) {
        case 1: side_by_side_norms<1>(m, column, lda, norms + first, machine); break;
        case 2: side_by_side_norms<2>(m, column, lda, norms + first, machine); break;
        case 3: side_by_side_norms<3>(m, column, lda, norms + first, machine); break;
        case 4: side_by_side_norms<4>(m, column, lda, norms + first, machine); break;
        case 5: side_by_side_norms<5>(m, column, lda, norms + first, machine); break;
        default: side_by_side_norms<kSideBySide>(m, column, lda, norms + first, machine); break;
      }
    }
  } else {
    for (int j = 0; j < n; ++j) norms[j] = enorm(m, a + j * lda, machine);
  }
}

/// qrfac, and with `b` (m values, or null) also b replaced by Q^T b: each Householder reflection
/// is applied to b in the step that makes it, as to the columns still to reduce, with the same
/// operations lmder applies to its residuals after qrfac (the same products and updates, in
/// the same order), so that b's sums run beside the columns' instead of after them.
template <class T>
void householder_qr(int m, int n, T* a, int lda, bool pivot, int* ipvt, T* rdiag, T* acnorm, T* wa, T* b,
                    const minpack_machine<T>& machine) {
  using std::sqrt;
  using K = minpack_detail::k<T>;
  using minpack_detail::add_multiple_of;
  using minpack_detail::max_of;
  minpack_detail::column_norms(m, n, a, lda, acnorm, machine);
  for (int j = 0; j < n; ++j) {
    rdiag[j] = acnorm[j];
    wa[j] = rdiag[j];
    if (pivot) ipvt[j] = j;
  }
  const int minmn = m < n ? m : n;
  for (int j = 0; j < minmn; ++j) {
    T* const aj = a + j * lda;
    if (pivot) {
      // Bring the column of largest remaining norm to position j.
      int kmax = j;
      for (int k = j; k < n; ++k) {
        if (rdiag[k] > rdiag[kmax]) kmax = k;
      }
      if (kmax != j) {
        minpack_detail::swap_each(m, aj, a + kmax * lda);
        rdiag[kmax] = rdiag[j];
        wa[kmax] = wa[j];
        const int swap = ipvt[j];
        ipvt[j] = ipvt[kmax];
        ipvt[kmax] = swap;
      }
    }
    // Householder reflection that zeroes column j below the diagonal. The first column's norm is
    // the acnorm of the column brought there, from the same numbers.
    T ajnorm = j == 0 ? acnorm[pivot ? ipvt[0] : 0] : enorm(m - j, aj + j, machine);
    if (ajnorm != T(0)) {
      if (aj[j] < T(0)) ajnorm = -ajnorm;
      if constexpr (std::numeric_limits<T>::is_iec559) {
        minpack_detail::divide_each(m - j, aj + j, ajnorm);  // MINPACK's own operations, bit for bit
      } else {
        // Fixed point: one division and m - j multiplications instead of m - j divisions
        // (a division costs ten multiplications there); the result moves by at most an ulp.
        const T inverse = T(1) / ajnorm;
        for (int i = j; i < m; ++i) aj[i] *= inverse;
      }
      aj[j] += T(1);
      // Apply it to the remaining columns (and b) and update their norms. A column's products
      // with aj do not depend on the other columns' updates: they are summed side by side.
      const int count = n - j - 1 + (b ? 1 : 0);
      // Column k of the remaining ones, k == n for b.
      const auto target = [&](int k) { return (k < n ? a + k * lda : b) + j; };
      T products[minpack_detail::kSideBySide];
      for (int k = j + 1; k <= j + count; ++k) {
        const int slot = (k - j - 1) % minpack_detail::kSideBySide;
        if (slot == 0) {
          const int size = j + count + 1 - k < minpack_detail::kSideBySide ? j + count + 1 - k : minpack_detail::kSideBySide;
          T* group[minpack_detail::kSideBySide];
          for (int g = 0; g < size; ++g) group[g] = target(k + g);
          minpack_detail::sums_of_products(m - j, aj + j, group, size, products);
        }
        const T temp = products[slot] / aj[j];
        // target -= temp aj: negating temp first changes no rounding (both types round
        // symmetrically), so b gets lmder's -(sum) / aj[j] update.
        add_multiple_of(m - j, -temp, aj + j, target(k));
        if (pivot && k < n && rdiag[k] != T(0)) {
          const T* const ak = a + k * lda;
          const T ratio = ak[j] / rdiag[k];
          rdiag[k] *= sqrt(max_of(T(0), T(1) - ratio * ratio));
          const T drop = rdiag[k] / wa[k];
          if (K::p05 * (drop * drop) <= machine.epsmch) {
            rdiag[k] = enorm(m - j - 1, ak + j + 1, machine);
            wa[k] = rdiag[k];
          }
        }
      }
    }
    rdiag[j] = -ajnorm;
  }
}

}  // namespace minpack_detail

template <class T>
void qrfac(int m, int n, T* a, int lda, bool pivot, int* ipvt, T* rdiag, T* acnorm, T* wa,
           const minpack_machine<T>& machine) {
  minpack_detail::householder_qr(m, n, a, lda, pivot, ipvt, rdiag, acnorm, wa, static_cast<T*>(nullptr), machine);
}

template <class T>
void qrsolv(int n, T* r, int ldr, const int* ipvt, const T* diag, const T* qtb, T* x, T* sdiag, T* wa,
            const minpack_machine<T>&) {
  using std::sqrt;
  using K = minpack_detail::k<T>;
  using minpack_detail::abs_of;
  // Copy R^T into the lower triangle (diagonal kept in x) and Q^T b into wa.
  for (int j = 0; j < n; ++j) {
    for (int i = j; i < n; ++i) r[i + j * ldr] = r[j + i * ldr];
    x[j] = r[j + j * ldr];
    wa[j] = qtb[j];
  }
  // Eliminate the diagonal matrix D with Givens rotations, row by row.
  for (int j = 0; j < n; ++j) {
    const int l = ipvt[j];
    if (diag[l] != T(0)) {
      for (int k = j; k < n; ++k) sdiag[k] = T(0);
      sdiag[j] = diag[l];
      T qtbpj(0);
      for (int k = j; k < n; ++k) {
        if (sdiag[k] == T(0)) continue;
        T& rkk = r[k + k * ldr];
        T sin, cos;
        if (abs_of(rkk) < abs_of(sdiag[k])) {
          const T cotan = rkk / sdiag[k];
          sin = K::p5 / sqrt(K::p25 + K::p25 * (cotan * cotan));
          cos = sin * cotan;
        } else {
          const T tan = sdiag[k] / rkk;
          cos = K::p5 / sqrt(K::p25 + K::p25 * (tan * tan));
          sin = cos * tan;
        }
        rkk = cos * rkk + sin * sdiag[k];
        const T temp = cos * wa[k] + sin * qtbpj;
        qtbpj = -sin * wa[k] + cos * qtbpj;
        wa[k] = temp;
        for (int i = k + 1; i < n; ++i) {
          const T rik = cos * r[i + k * ldr] + sin * sdiag[i];
          sdiag[i] = -sin * r[i + k * ldr] + cos * sdiag[i];
          r[i + k * ldr] = rik;
        }
      }
    }
    sdiag[j] = r[j + j * ldr];
    r[j + j * ldr] = x[j];
  }
  // Back-substitute in the triangular S; a singular S gives a least-squares solution.
  int nsing = n;
  for (int j = 0; j < n; ++j) {
    if (sdiag[j] == T(0) && nsing == n) nsing = j;
    if (nsing < n) wa[j] = T(0);
  }
  for (int j = nsing - 1; j >= 0; --j) {
    T sum(0);
    for (int i = j + 1; i < nsing; ++i) sum += r[i + j * ldr] * wa[i];
    wa[j] = (wa[j] - sum) / sdiag[j];
  }
  for (int j = 0; j < n; ++j) x[ipvt[j]] = wa[j];
}

template <class T>
void lmpar(int n, T* r, int ldr, const int* ipvt, const T* diag, const T* qtb, T delta, T* par, T* x, T* sdiag, T* wa1,
           T* wa2, const minpack_machine<T>& machine) {
  using std::sqrt;
  using K = minpack_detail::k<T>;
  using minpack_detail::abs_of;
  using minpack_detail::max_of;
  using minpack_detail::min_of;
  // Gauss-Newton direction (least-squares solution if R is singular).
  int nsing = n;
  for (int j = 0; j < n; ++j) {
    wa1[j] = qtb[j];
    if (r[j + j * ldr] == T(0) && nsing == n) nsing = j;
    if (nsing < n) wa1[j] = T(0);
  }
  for (int j = nsing - 1; j >= 0; --j) {
    wa1[j] /= r[j + j * ldr];
    const T temp = wa1[j];
    for (int i = 0; i < j; ++i) wa1[i] -= r[i + j * ldr] * temp;
  }
  for (int j = 0; j < n; ++j) x[ipvt[j]] = wa1[j];

  int iter = 0;
  for (int j = 0; j < n; ++j) wa2[j] = diag[j] * x[j];
  T dxnorm = enorm(n, wa2, machine);
  T fp = dxnorm - delta;
  if (fp > K::p1 * delta) {
    // Lower bound parl from the Newton step (zero when R is rank deficient).
    T parl(0);
    if (nsing >= n) {
      for (int j = 0; j < n; ++j) {
        const int l = ipvt[j];
        wa1[j] = diag[l] * (wa2[l] / dxnorm);
      }
      for (int j = 0; j < n; ++j) {
        T sum(0);
        for (int i = 0; i < j; ++i) sum += r[i + j * ldr] * wa1[i];
        wa1[j] = (wa1[j] - sum) / r[j + j * ldr];
      }
      const T temp = enorm(n, wa1, machine);
      parl = fp / delta / temp / temp;
    }
    // Upper bound paru from the scaled gradient.
    for (int j = 0; j < n; ++j) {
      T sum(0);
      for (int i = 0; i <= j; ++i) sum += r[i + j * ldr] * qtb[i];
      wa1[j] = sum / diag[ipvt[j]];
    }
    const T gnorm = enorm(n, wa1, machine);
    T paru = gnorm / delta;
    if (paru == T(0)) paru = machine.dwarf / min_of(delta, K::p1);
    *par = max_of(*par, parl);
    *par = min_of(*par, paru);
    if (*par == T(0)) *par = gnorm / dxnorm;

    for (;;) {
      ++iter;
      if (*par == T(0)) *par = max_of(machine.dwarf, K::p001 * paru);
      const T root = sqrt(*par);
      for (int j = 0; j < n; ++j) wa1[j] = root * diag[j];
      qrsolv(n, r, ldr, ipvt, wa1, qtb, x, sdiag, wa2, machine);
      for (int j = 0; j < n; ++j) wa2[j] = diag[j] * x[j];
      dxnorm = enorm(n, wa2, machine);
      const T previous_fp = fp;
      fp = dxnorm - delta;
      // Accept par when |D x| is within 10% of delta, in the exceptional cases, or after 10 tries.
      if (abs_of(fp) <= K::p1 * delta || (parl == T(0) && fp <= previous_fp && previous_fp < T(0)) || iter == 10) break;
      if (dxnorm == T(0)) break;  // D x = 0: the Newton correction below would divide by zero
      // Newton correction.
      for (int j = 0; j < n; ++j) {
        const int l = ipvt[j];
        wa1[j] = diag[l] * (wa2[l] / dxnorm);
      }
      for (int j = 0; j < n; ++j) {
        wa1[j] /= sdiag[j];
        const T temp = wa1[j];
        for (int i = j + 1; i < n; ++i) wa1[i] -= r[i + j * ldr] * temp;
      }
      const T temp = enorm(n, wa1, machine);
      const T parc = fp / delta / temp / temp;
      if (fp > T(0)) parl = max_of(parl, *par);
      if (fp < T(0)) paru = min_of(paru, *par);
      *par = max_of(parl, *par + parc);
    }
  }
  if (iter == 0) *par = T(0);
}

template <class T>
int fdjac2(minpack_func_mn<T> fcn, void* p, int m, int n, T* x, const T* fvec, T* fjac, int ldfjac, T epsfcn, T* wa,
           const minpack_machine<T>& machine) {
  using minpack_detail::abs_of;
  using minpack_detail::max_of;
  using std::sqrt;
  const T eps = sqrt(max_of(epsfcn, machine.epsmch));
  int iflag = 0;
  for (int j = 0; j < n; ++j) {
    const T temp = x[j];
    T h = eps * abs_of(temp);
    if (h == T(0)) h = eps;
    x[j] = temp + h;
    iflag = fcn(p, m, n, x, wa, 2);
    if (iflag < 0) return iflag;
    x[j] = temp;
    for (int i = 0; i < m; ++i) fjac[i + j * ldfjac] = (wa[i] - fvec[i]) / h;
  }
  return iflag;
}

namespace minpack_detail {

/// The outer and inner loops shared by lmder and lmdif. `problem` provides
/// residuals(x, fvec), jacobian(x, fvec, fjac, nfev) and progress(x, fvec), each returning the
/// callback's value (negative: stop).
template <class T, class Problem>
int levenberg_marquardt(Problem& problem, int m, int n, T* x, T* fvec, T* fjac, int ldfjac, T ftol, T xtol, T gtol,
                        int maxfev, T* diag, int mode, T factor, int nprint, int* nfev, int* ipvt, T* qtf, T* wa1,
                        T* wa2, T* wa3, T* wa4) {
  using std::sqrt;
  using K = k<T>;
  const minpack_machine<T> machine = minpack_machine_constants<T>();
  int info = 0;
  int iflag = 0;
  *nfev = 0;
  T fnorm(0), xnorm(0), delta(0), par(0);
  int iter = 1;

  bool valid =
      n > 0 && m >= n && ldfjac >= m && ftol >= T(0) && xtol >= T(0) && gtol >= T(0) && maxfev > 0 && factor > T(0);
  if (valid && mode == 2) {
    for (int j = 0; j < n; ++j) {
      if (diag[j] <= T(0)) valid = false;
    }
  }
  if (valid) {
    iflag = problem.residuals(x, fvec);
    *nfev = 1;
  }
  if (!valid || iflag < 0) goto done;
  fnorm = enorm(m, fvec, machine);

  for (;;) {  // outer loop: one Jacobian per iteration
    iflag = problem.jacobian(x, fvec, fjac, nfev);
    if (iflag < 0) goto done;
    if (nprint > 0) {
      iflag = 0;
      if ((iter - 1) % nprint == 0) iflag = problem.progress(x, fvec);
      if (iflag < 0) goto done;
    }
    // qtf = the first n components of Q^T fvec: wa4 goes through the factorisation's reflections.
    for (int i = 0; i < m; ++i) wa4[i] = fvec[i];
    householder_qr(m, n, fjac, ldfjac, true, ipvt, wa1, wa2, wa3, wa4, machine);
    if (iter == 1) {
      // Scale by the column norms of the first Jacobian; set the first step bound.
      if (mode != 2) {
        for (int j = 0; j < n; ++j) diag[j] = wa2[j] == T(0) ? T(1) : wa2[j];
      }
      for (int j = 0; j < n; ++j) wa3[j] = diag[j] * x[j];
      xnorm = enorm(n, wa3, machine);
      delta = factor * xnorm;
      if (delta == T(0)) delta = factor;
    }
    for (int j = 0; j < n; ++j) {
      fjac[j + j * ldfjac] = wa1[j];
      qtf[j] = wa4[j];
    }
    // Norm of the scaled gradient, and the gtol test.
    T gnorm(0);
    if (fnorm != T(0)) {
      for (int j = 0; j < n; ++j) {
        const int l = ipvt[j];
        if (wa2[l] == T(0)) continue;
        T sum(0);
        for (int i = 0; i <= j; ++i) sum += fjac[i + j * ldfjac] * (qtf[i] / fnorm);
        gnorm = max_of(gnorm, abs_of(sum / wa2[l]));
      }
    }
    if (gnorm <= gtol) info = 4;
    if (info != 0) goto done;
    if (mode != 2) {
      for (int j = 0; j < n; ++j) diag[j] = max_of(diag[j], wa2[j]);
    }

    T ratio(0);
    do {  // inner loop: shrink the trust region until a step reduces the residual
      lmpar(n, fjac, ldfjac, ipvt, diag, qtf, delta, &par, wa1, wa2, wa3, wa4, machine);
      for (int j = 0; j < n; ++j) {
        wa1[j] = -wa1[j];
        wa2[j] = x[j] + wa1[j];
        wa3[j] = diag[j] * wa1[j];
      }
      const T pnorm = enorm(n, wa3, machine);
      if (iter == 1) delta = min_of(delta, pnorm);
      iflag = problem.residuals(wa2, wa4);
      ++*nfev;
      if (iflag < 0) goto done;
      const T fnorm1 = enorm(m, wa4, machine);

      // Scaled actual and predicted reductions, and the directional derivative.
      T actred(-1);
      if (K::p1 * fnorm1 < fnorm) {
        const T q = fnorm1 / fnorm;
        actred = T(1) - q * q;
      }
      for (int j = 0; j < n; ++j) {
        wa3[j] = T(0);
        const T temp = wa1[ipvt[j]];
        for (int i = 0; i <= j; ++i) wa3[i] += fjac[i + j * ldfjac] * temp;
      }
      const T temp1 = enorm(n, wa3, machine) / fnorm;
      const T temp2 = sqrt(par) * pnorm / fnorm;
      const T prered = temp1 * temp1 + temp2 * temp2 / K::p5;
      const T dirder = -(temp1 * temp1 + temp2 * temp2);
      ratio = T(0);
      if (prered != T(0)) ratio = actred / prered;

      // Update the step bound.
      if (ratio <= K::p25) {
        T temp = actred >= T(0) ? K::p5 : K::p5 * dirder / (dirder + K::p5 * actred);
        if (K::p1 * fnorm1 >= fnorm || temp < K::p1) temp = K::p1;
        delta = temp * min_of(delta, pnorm / K::p1);
        par = par / temp;
      } else if (par == T(0) || ratio >= K::p75) {
        delta = pnorm / K::p5;
        par = K::p5 * par;
      }

      if (ratio >= K::p0001) {  // successful step: accept it
        for (int j = 0; j < n; ++j) {
          x[j] = wa2[j];
          wa2[j] = diag[j] * x[j];
        }
        for (int i = 0; i < m; ++i) fvec[i] = wa4[i];
        xnorm = enorm(n, wa2, machine);
        fnorm = fnorm1;
        ++iter;
      }

      // Convergence tests.
      const bool f_converged = abs_of(actred) <= ftol && prered <= ftol && K::p5 * ratio <= T(1);
      if (f_converged) info = 1;
      if (delta <= xtol * xnorm) info = f_converged ? 3 : 2;
      if (info != 0) goto done;
      // Termination tests: evaluation budget and tolerances below machine precision.
      if (*nfev >= maxfev) info = 5;
      if (abs_of(actred) <= machine.epsmch && prered <= machine.epsmch && K::p5 * ratio <= T(1)) info = 6;
      if (delta <= machine.epsmch * xnorm) info = 7;
      if (gnorm <= machine.epsmch) info = 8;
      if (info != 0) goto done;
    } while (ratio < K::p0001);
  }

done:
  if (iflag < 0) info = iflag;
  if (nprint > 0) problem.progress(x, fvec);
  return info;
}

template <class T>
struct AnalyticProblem {
  minpack_funcder_mn<T> fcn;
  void* p;
  int m, n;
  T* fjac;
  int ldfjac;
  int* njev;
  int residuals(const T* x, T* fvec) { return fcn(p, m, n, x, fvec, fjac, ldfjac, 1); }
  int jacobian(const T* x, T* fvec, T* fjac, int*) {
    ++*njev;
    return fcn(p, m, n, x, fvec, fjac, ldfjac, 2);
  }
  int progress(const T* x, T* fvec) { return fcn(p, m, n, x, fvec, fjac, ldfjac, 0); }
};

template <class T>
struct DifferenceProblem {
  minpack_func_mn<T> fcn;
  void* p;
  int m, n, ldfjac;
  T epsfcn;
  T* wa4;
  minpack_machine<T> machine;
  int residuals(const T* x, T* fvec) { return fcn(p, m, n, x, fvec, 1); }
  int jacobian(T* x, const T* fvec, T* fjac, int* nfev) {
    const int iflag = fdjac2(fcn, p, m, n, x, fvec, fjac, ldfjac, epsfcn, wa4, machine);
    *nfev += n;
    return iflag;
  }
  int progress(const T* x, T* fvec) { return fcn(p, m, n, x, fvec, 0); }
};

}  // namespace minpack_detail

template <class T>
int lmder(minpack_funcder_mn<T> fcn, void* p, int m, int n, T* x, T* fvec, T* fjac, int ldfjac, T ftol, T xtol, T gtol,
          int maxfev, T* diag, int mode, T factor, int nprint, int* nfev, int* njev, int* ipvt, T* qtf, T* wa1, T* wa2,
          T* wa3, T* wa4) {
  *njev = 0;
  minpack_detail::AnalyticProblem<T> problem{fcn, p, m, n, fjac, ldfjac, njev};
  return minpack_detail::levenberg_marquardt(problem, m, n, x, fvec, fjac, ldfjac, ftol, xtol, gtol, maxfev, diag, mode,
                                             factor, nprint, nfev, ipvt, qtf, wa1, wa2, wa3, wa4);
}

template <class T>
int lmdif(minpack_func_mn<T> fcn, void* p, int m, int n, T* x, T* fvec, T ftol, T xtol, T gtol, int maxfev, T epsfcn,
          T* diag, int mode, T factor, int nprint, int* nfev, T* fjac, int ldfjac, int* ipvt, T* qtf, T* wa1, T* wa2,
          T* wa3, T* wa4) {
  minpack_detail::DifferenceProblem<T> problem{fcn, p, m, n, ldfjac, epsfcn, wa4, minpack_machine_constants<T>()};
  return minpack_detail::levenberg_marquardt(problem, m, n, x, fvec, fjac, ldfjac, ftol, xtol, gtol, maxfev, diag, mode,
                                             factor, nprint, nfev, ipvt, qtf, wa1, wa2, wa3, wa4);
}

}  // namespace netlib

/// Explicitly instantiates the MINPACK routines for T (used by instances/).
#define NETLIB_MINPACK_INSTANTIATE(T)                                                                                 \
  namespace netlib {                                                                                                  \
  template minpack_machine<T> minpack_machine_constants<T>();                                                         \
  template T enorm<T>(int, const T*);                                                                                 \
  template T enorm<T>(int, const T*, const minpack_machine<T>&);                                                      \
  template void qrfac<T>(int, int, T*, int, bool, int*, T*, T*, T*, const minpack_machine<T>&);                       \
  template void qrsolv<T>(int, T*, int, const int*, const T*, const T*, T*, T*, T*, const minpack_machine<T>&);       \
  template void lmpar<T>(int, T*, int, const int*, const T*, const T*, T, T*, T*, T*, T*, T*,                         \
                         const minpack_machine<T>&);                                                                  \
  template int fdjac2<T>(minpack_func_mn<T>, void*, int, int, T*, const T*, T*, int, T, T*,                           \
                         const minpack_machine<T>&);                                                                  \
  template int lmder<T>(minpack_funcder_mn<T>, void*, int, int, T*, T*, T*, int, T, T, T, int, T*, int, T, int, int*, \
                        int*, int*, T*, T*, T*, T*, T*);                                                              \
  template int lmdif<T>(minpack_func_mn<T>, void*, int, int, T*, T*, T, T, T, int, T, T*, int, T, int, int*, T*, int, \
                        int*, T*, T*, T*, T*, T*);                                                                    \
  }

}  // inline namespace edgetrack_ports
