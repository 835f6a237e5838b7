// SPDX-License-Identifier: BSD-3-Clause
/// Helpers for the vnl_algo tests: a tolerance per scalar and small deterministic matrices.
#pragma once

#include <cmath>
#include <limits>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_random.h"
#include "../vnl_test_types.h"

/// A decomposition's tolerance: `scale` ulps of T (double: ~1e-13, float and S40.23: ~1e-4).
template <class T>
double decomposition_tol(double scale = 1024) {
  return ulps<T>(scale) + 1e-14;
}

/// An m x n matrix of uniform values in [-1, 1) from a fixed seed.
template <class T>
vnl_matrix<T> random_matrix(unsigned m, unsigned n, unsigned long seed) {
  vnl_random rng(seed);
  vnl_matrix<T> a(m, n);
  for (T& x : a) x = T(rng.drand64(-1.0, 1.0));
  return a;
}

/// |a - b|_F as a double.
template <class T>
double distance(const vnl_matrix<T>& a, const vnl_matrix<T>& b) {
  return static_cast<double>((a - b).frobenius_norm());
}

/// |a^T a - I|_F.
template <class T>
double orthonormality_error(const vnl_matrix<T>& a) {
  vnl_matrix<T> id(a.cols(), a.cols());
  id.set_identity();
  return distance(a.transpose() * a, id);
}
