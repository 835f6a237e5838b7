// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_sparse_symmetric_eigensystem.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "vnl/algo/vnl_cholesky.h"
#include "vnl/algo/vnl_generalized_eigensystem.h"
#include "vnl/algo/vnl_symmetric_eigensystem.h"

inline namespace edgetrack_ports {

namespace {
vnl_matrix<double> dense(const vnl_sparse_matrix<double>& s) {
  vnl_matrix<double> d(s.rows(), s.cols(), 0.0);
  for (unsigned r = 0; r < s.rows(); ++r)
    for (const auto& e : s.get_row(r)) d(r, e.first) = e.second;
  return d;
}
}  // namespace

void vnl_sparse_symmetric_eigensystem::keep(const vnl_matrix<double>& V, const vnl_vector<double>& D, int nEV,
                                            bool smallest, bool magnitude, double sigma) {
  std::vector<unsigned> order(D.size());
  std::iota(order.begin(), order.end(), 0u);
  auto key = [&](unsigned i) { return magnitude || sigma != 0 ? std::fabs(D[i] - sigma) : D[i]; };
  std::stable_sort(order.begin(), order.end(),
                   [&](unsigned a, unsigned b) { return smallest ? key(a) < key(b) : key(a) > key(b); });
  nvalues = nEV;
  vectors.clear();
  values.clear();
  for (int k = 0; k < nEV; ++k) {
    values.push_back(D[order[k]]);
    vectors.push_back(V.get_column(order[k]));
  }
}

int vnl_sparse_symmetric_eigensystem::CalculateNPairs(vnl_sparse_matrix<double>& M, int n, bool smallest, long) {
  mat = &M;
  Bmat = nullptr;
  if (M.rows() != M.cols() || n < 1 || n > static_cast<int>(M.rows())) return 1;
  vnl_matrix<double> V;
  vnl_vector<double> D;
  vnl_symmetric_eigensystem_compute(dense(M), V, D);
  keep(V, D, n, smallest, false, 0.0);
  return 0;
}

int vnl_sparse_symmetric_eigensystem::CalculateNPairs(vnl_sparse_matrix<double>& A, vnl_sparse_matrix<double>& B,
                                                      int nEV, double, int, bool smallest, bool magnitude, int,
                                                      double sigma) {
  mat = &A;
  Bmat = &B;
  const unsigned n = A.rows();
  if (A.cols() != n || B.rows() != n || B.cols() != n || nEV < 1 || nEV > static_cast<int>(n)) return 1;
  const vnl_matrix<double> b = dense(B);
  if (vnl_cholesky_of<double>(b, vnl_cholesky_of<double>::quiet).rank_deficiency() != 0) return 2;
  const vnl_generalized_eigensystem gev(dense(A), b);
  keep(gev.V, gev.D.get_diagonal(), nEV, smallest, magnitude, sigma);
  return 0;
}

int vnl_sparse_symmetric_eigensystem::CalculateProduct(int n, int m, const double* p, double* q) {
  if (mat == nullptr || static_cast<unsigned>(n) != mat->cols()) return 1;
  vnl_vector<double> x(static_cast<unsigned>(n)), y;
  for (int j = 0; j < m; ++j) {
    x.copy_in(p + j * n);
    mat->mult(x, y);
    y.copy_out(q + j * n);
  }
  return 0;
}

int vnl_sparse_symmetric_eigensystem::SaveVectors(int n, int m, const double* q, int base) {
  if (base < 0) return 1;
  if (temp_store.size() <= static_cast<size_t>(base)) temp_store.resize(static_cast<size_t>(base) + 1);
  temp_store[static_cast<size_t>(base)].assign(q, q + static_cast<ptrdiff_t>(n) * m);
  return 0;
}

int vnl_sparse_symmetric_eigensystem::RestoreVectors(int n, int m, double* q, int base) {
  if (base < 0 || static_cast<size_t>(base) >= temp_store.size()) return 1;
  const std::vector<double>& saved = temp_store[static_cast<size_t>(base)];
  if (saved.size() != static_cast<size_t>(n) * static_cast<size_t>(m)) return 1;
  std::copy(saved.begin(), saved.end(), q);
  return 0;
}

}  // inline namespace edgetrack_ports
