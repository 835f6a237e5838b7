// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_hungarian_algorithm.h: the minimum-cost assignment of rows to
/// columns of a cost matrix (rectangular too: the smaller side is all assigned). Upstream steps
/// through Munkres' formulation; ours is the O(n^3) shortest-augmenting-path form of the same
/// Hungarian method with row and column potentials, which finds an optimal assignment too (on
/// ties it may pick another optimal one). Costs must be finite.
#pragma once

#ifdef vnl_hungarian_algorithm_h_
#error "edgetrack's drop-in vnl/vnl_hungarian_algorithm.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>
#include <limits>
#include <vector>

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_hungarian_algorithm {
 public:
  using AssignmentMatrixType = vnl_matrix<int>;
  using AssignmentVectorType = std::vector<unsigned>;

  vnl_hungarian_algorithm() = default;
  /// Solves at once.
  explicit vnl_hungarian_algorithm(const vnl_matrix<T>& cost) {
    SetCostMatrix(cost);
    StartAssignment();
  }
  /// The assignment vector (row i -> column, or unsigned(-1) for a row left unassigned).
  operator std::vector<unsigned>() { return GetAssignmentVector(); }

  void SetCostMatrix(const vnl_matrix<T>& cost) { cost_ = cost; }
  void StartAssignment();
  /// The sum of the assigned costs.
  T GetTotalCost() const { return total_cost_; }
  /// rows x cols, 1 where row i is assigned to column j.
  AssignmentMatrixType GetAssignmentMatrix() const;
  AssignmentVectorType GetAssignmentVector() const { return assignment_; }

 private:
  vnl_matrix<T> cost_;
  AssignmentVectorType assignment_;
  T total_cost_ = T(0);
};

template <class T>
void vnl_hungarian_algorithm<T>::StartAssignment() {
  // Work on the transpose when there are more rows than columns, so rows <= columns.
  const bool transposed = cost_.rows() > cost_.cols();
  const vnl_matrix<T> a = transposed ? cost_.transpose() : cost_;
  const std::size_t n = a.rows(), m = a.cols();
  // 1-based arrays as in the textbook form: u, v potentials; p[j] the row matched to column j.
  std::vector<T> u(n + 1, T(0)), v(m + 1, T(0)), min_to(m + 1);
  std::vector<std::size_t> p(m + 1, 0), way(m + 1, 0);
  const T infinity = std::numeric_limits<T>::max();
  for (std::size_t i = 1; i <= n; ++i) {
    p[0] = i;
    std::size_t j0 = 0;
    std::fill(min_to.begin(), min_to.end(), infinity);
    std::vector<bool> used(m + 1, false);
    do {  // grow the alternating tree from row i until it reaches a free column
      used[j0] = true;
      const std::size_t i0 = p[j0];
      T delta = infinity;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const T reduced = a(i0 - 1, j - 1) - u[i0] - v[j];
        if (reduced < min_to[j]) min_to[j] = reduced, way[j] = j0;
        if (min_to[j] < delta) delta = min_to[j], j1 = j;
      }
      for (std::size_t j = 0; j <= m; ++j) {
        if (used[j]) {
          u[p[j]] += delta, v[j] -= delta;
        } else {
          min_to[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {  // flip the augmenting path
      const std::size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  assignment_.assign(cost_.rows(), static_cast<unsigned>(-1));
  total_cost_ = T(0);
  for (std::size_t j = 1; j <= m; ++j) {
    if (p[j] == 0) continue;
    const std::size_t row = transposed ? j - 1 : p[j] - 1, col = transposed ? p[j] - 1 : j - 1;
    assignment_[row] = static_cast<unsigned>(col);
    total_cost_ += cost_(row, col);
  }
}

template <class T>
typename vnl_hungarian_algorithm<T>::AssignmentMatrixType vnl_hungarian_algorithm<T>::GetAssignmentMatrix() const {
  AssignmentMatrixType result(cost_.rows(), cost_.cols(), 0);
  for (std::size_t i = 0; i < assignment_.size(); ++i) {
    if (assignment_[i] != static_cast<unsigned>(-1)) result(i, assignment_[i]) = 1;
  }
  return result;
}

}  // inline namespace edgetrack_ports
