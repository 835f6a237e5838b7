// SPDX-License-Identifier: BSD-3-Clause
/// The rigid transformation classes on a grid of rotations, written against ViSP 3.5's API only
/// and built twice (against Debian's ViSP and against ports/visp); transforms_compare.sh compares
/// the two outputs. For each theta u on the grid (including angles near 0 and near pi) it prints
/// R(theta u), theta u back from R, the homogeneous matrix with a translation, its inverse, the
/// transformed point and the pose vector back from the matrix, one number per line.
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/core/vpRotationMatrix.h>
#include <visp3/core/vpThetaUVector.h>
#include <visp3/core/vpTranslationVector.h>

#include <cmath>
#include <cstdio>

namespace {

template <class Matrix>
void print_rows(const char* what, const Matrix& M, unsigned int rows, unsigned int cols) {
  for (unsigned int r = 0; r < rows; ++r)
    for (unsigned int c = 0; c < cols; ++c) std::printf("%s %u %u %.12f\n", what, r, c, static_cast<double>(M[r][c]));
}

template <class Vector>
void print_vector(const char* what, const Vector& v, unsigned int n) {
  for (unsigned int k = 0; k < n; ++k) std::printf("%s %u %.12f\n", what, k, static_cast<double>(v[k]));
}

}  // namespace

int main() {
  const double axes[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.6, -0.8, 0}, {0.48, 0.6, -0.64}, {-0.36, 0.48, 0.8}};
  const double angles[] = {0, 1e-5, 0.3, 1.0, 2.0, 3.0, 3.1415, M_PI - 1e-6};
  for (const auto& u : axes) {
    for (double theta : angles) {
      const vpThetaUVector tu(theta * u[0], theta * u[1], theta * u[2]);
      const vpRotationMatrix R(tu);
      print_rows("R", R, 3, 3);
      print_vector("tu", vpThetaUVector(R), 3);
      const vpHomogeneousMatrix M(vpTranslationVector(0.1, -0.25, 0.6), tu);
      print_rows("Minv", M.inverse(), 4, 4);
      print_vector("Mp", M * vpTranslationVector(0.3, 0.2, -0.1), 3);
      print_vector("pose", vpPoseVector(M), 6);
    }
  }
  return 0;
}
