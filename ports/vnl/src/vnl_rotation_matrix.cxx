// SPDX-License-Identifier: BSD-3-Clause
// Upstream's double overloads of vnl_rotation_matrix, all through the one Rodrigues formula.
#include "vnl/vnl_rotation_matrix.h"

#include <cassert>

#include "vnl/vnl_rotation_matrix.hxx"

inline namespace edgetrack_ports {

namespace {
vnl_matrix_fixed<double, 3, 3> rotation_of(const double axis[3]) {
  return vnl_rotation_matrix(vnl_vector_fixed<double, 3>(axis));
}
}  // namespace

bool vnl_rotation_matrix(const double axis[3], double* R0, double* R1, double* R2) {
  const vnl_matrix_fixed<double, 3, 3> R = rotation_of(axis);
  double* rows[3] = {R0, R1, R2};
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) rows[i][j] = R(i, j);
  return true;
}

bool vnl_rotation_matrix(const double axis[3], double** R) { return vnl_rotation_matrix(axis, R[0], R[1], R[2]); }

bool vnl_rotation_matrix(const double axis[3], double R[3][3]) {
  return vnl_rotation_matrix(axis, R[0], R[1], R[2]);
}

bool vnl_rotation_matrix(const vnl_vector_fixed<double, 3>& axis, vnl_matrix_fixed<double, 3, 3>& R) {
  R = vnl_rotation_matrix(axis);
  return true;
}

bool vnl_rotation_matrix(const vnl_vector<double>& axis, vnl_matrix<double>& R) {
  R = vnl_rotation_matrix(axis);
  return true;
}

vnl_matrix<double> vnl_rotation_matrix(const vnl_vector<double>& axis) {
  assert(axis.size() == 3);
  return rotation_of(axis.data_block()).as_matrix();
}

}  // inline namespace edgetrack_ports
