// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_matops.h"

#include <cassert>
#include <cmath>

inline namespace edgetrack_ports {

namespace {
vnl_matrix<double> column(const vnl_vector<double>& v) {
  vnl_matrix<double> m(v.size(), 1);
  m.set_column(0, v);
  return m;
}

template <class To, class From>
vnl_matrix<To> convert(const vnl_matrix<From>& m) {
  vnl_matrix<To> result(m.rows(), m.cols());
  for (std::size_t i = 0; i < m.size(); ++i) result.data_block()[i] = static_cast<To>(m.data_block()[i]);
  return result;
}

template <class To, class From>
vnl_vector<To> convert(const vnl_vector<From>& v) {
  vnl_vector<To> result(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) result[i] = static_cast<To>(v[i]);
  return result;
}
}  // namespace

double vnl_matops::homg_diff(const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  const vnl_matrix<double> a = A / A.frobenius_norm(), b = B / B.frobenius_norm();
  return std::fmin((a - b).frobenius_norm(), (a + b).frobenius_norm());
}

vnl_matrix<double> vnl_matops::cat(const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  assert(A.rows() == B.rows());
  vnl_matrix<double> result(A.rows(), A.cols() + B.cols());
  result.update(A, 0, 0);
  result.update(B, 0, A.cols());
  return result;
}

vnl_matrix<double> vnl_matops::cat(const vnl_matrix<double>& A, const vnl_vector<double>& B) { return cat(A, column(B)); }
vnl_matrix<double> vnl_matops::cat(const vnl_vector<double>& A, const vnl_matrix<double>& B) { return cat(column(A), B); }

vnl_matrix<double> vnl_matops::vcat(const vnl_matrix<double>& A, const vnl_matrix<double>& B) {
  assert(A.cols() == B.cols());
  vnl_matrix<double> result(A.rows() + B.rows(), A.cols());
  result.update(A, 0, 0);
  result.update(B, A.rows(), 0);
  return result;
}

vnl_matrix<double> vnl_matops::f2d(const vnl_matrix<float>& m) { return convert<double>(m); }
vnl_vector<double> vnl_matops::f2d(const vnl_vector<float>& v) { return convert<double>(v); }
vnl_matrix<float> vnl_matops::d2f(const vnl_matrix<double>& m) { return convert<float>(m); }
vnl_vector<float> vnl_matops::d2f(const vnl_vector<double>& v) { return convert<float>(v); }

}  // inline namespace edgetrack_ports
