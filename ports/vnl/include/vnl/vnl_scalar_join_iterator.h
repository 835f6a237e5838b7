// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_scalar_join_iterator.h: the relational join of two matrices on
/// one column each. The iterator visits every pair (row1, row2) with
/// relation1(row1, column1) == relation2(row2, column2), in ascending order of that value
/// (for equal values, row2 varies fastest, as upstream's sort-merge). Neither matrix may
/// change or go away while an iterator over it lives.
#pragma once

#ifdef vnl_scalar_join_iterator_h_
#error "edgetrack's drop-in vnl/vnl_scalar_join_iterator.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>
#include <ostream>
#include <vector>

#include "vnl/vnl_matrix.h"

inline namespace edgetrack_ports {

/// A pointer to one element of the join column and the row it came from.
template <class T>
class vnl_scalar_join_iterator_indexed_pair {
 public:
  const T* object = nullptr;
  int original_index = 0;

  vnl_scalar_join_iterator_indexed_pair() = default;
  vnl_scalar_join_iterator_indexed_pair(const T* object_, int original_index_)
      : object(object_), original_index(original_index_) {}
  /// Compare the pointed-to values.
  bool operator==(const vnl_scalar_join_iterator_indexed_pair<T>& that) const { return *that.object == *object; }
  bool operator<(const vnl_scalar_join_iterator_indexed_pair<T>& that) const { return *object < *that.object; }
};

template <class T>
std::ostream& operator<<(std::ostream& s, const vnl_scalar_join_iterator_indexed_pair<T>& p) {
  return s << p.original_index << ' ' << *p.object << '\n';
}

template <class T>
class vnl_scalar_join_iterator {
 public:
  vnl_scalar_join_iterator(const vnl_matrix<T>& relation1, unsigned column1, const vnl_matrix<T>& relation2,
                           unsigned column2)
      : n1(relation1.rows()),
        n2(relation2.rows()),
        I1(sorted_column(relation1, column1)),
        I2(sorted_column(relation2, column2)) {
    seek_match();
  }

  explicit operator bool() const { return !done(); }
  bool operator!() const { return done(); }
  vnl_scalar_join_iterator<T>& operator++() {
    next();
    return *this;
  }

  /// No further matching pair.
  bool done() const { return index1 == I1.size() || index2 == I2.size(); }
  /// Moves to the next matching pair.
  void next() {
    ++index2;
    if (index2 < I2.size() && *I2[index2].object == *I1[index1].object) return;
    // The run of equal values in relation2 is over: the next row of relation1 restarts it.
    const std::size_t run_start = run_start_of(index2);
    ++index1;
    if (index1 < I1.size() && run_start < I2.size() && *I1[index1].object == *I2[run_start].object) {
      index2 = run_start;
      return;
    }
    seek_match();
  }
  /// The rows of relation1 and relation2 of the current pair.
  unsigned row1() const { return static_cast<unsigned>(I1[index1].original_index); }
  unsigned row2() const { return static_cast<unsigned>(I2[index2].original_index); }

 protected:
  unsigned n1;
  unsigned n2;
  std::vector<vnl_scalar_join_iterator_indexed_pair<T>> I1;
  std::vector<vnl_scalar_join_iterator_indexed_pair<T>> I2;
  std::size_t index1 = 0;
  std::size_t index2 = 0;

 private:
  using pair_list = std::vector<vnl_scalar_join_iterator_indexed_pair<T>>;

  static pair_list sorted_column(const vnl_matrix<T>& relation, unsigned column) {
    pair_list pairs;
    pairs.reserve(relation.rows());
    for (unsigned i = 0; i < relation.rows(); ++i) pairs.emplace_back(&relation(i, column), static_cast<int>(i));
    std::stable_sort(pairs.begin(), pairs.end());
    return pairs;
  }
  /// The first position of relation2's run of values equal to the one before `end`.
  std::size_t run_start_of(std::size_t end) const {
    std::size_t start = end - 1;
    while (start > 0 && *I2[start - 1].object == *I2[end - 1].object) --start;
    return start;
  }
  /// Advances the smaller side until both point at equal values, or one side ends.
  void seek_match() {
    while (!done()) {
      const T& a = *I1[index1].object;
      const T& b = *I2[index2].object;
      if (a == b) return;
      if (b < a) {
        ++index2;
      } else {
        ++index1;
      }
    }
  }
};

}  // inline namespace edgetrack_ports
