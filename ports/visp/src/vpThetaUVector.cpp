// SPDX-License-Identifier: BSD-3-Clause
/// vpThetaUVector from a rotation matrix: theta = atan2(|skew part| / 2, (trace - 1) / 2); the axis
/// from the skew part divided by 2 sinc(theta), or, when 1 + cos(theta) <= 1e-4 (theta near pi,
/// where the skew part vanishes), from the diagonal with signs from the off-diagonal sums
/// (in fixed point, the small components from those sums: see axis_near_pi).
#include "visp3/core/vpThetaUVector.h"

#include <cmath>
#include <limits>
#include <type_traits>

#include "visp3/core/vpHomogeneousMatrix.h"
#include "visp3/core/vpMath.h"
#include "visp3/core/vpPoseVector.h"
#include "visp3/core/vpRotationMatrix.h"

inline namespace edgetrack_ports {

namespace {
const real kNearPi = real(0.0001);

real axis_component(real diagonal, real c) {
  using std::sqrt;
  return diagonal - c > std::numeric_limits<real>::epsilon() ? sqrt((diagonal - c) / (real(1) - c)) : real(0);
}

/// Flips b when sign(a) sign(b) disagrees with the sign of the symmetric off-diagonal sum.
void align_sign(real a, real& b, real sum) {
  if (vpMath::sign(a) * vpMath::sign(b) != vpMath::sign(sum)) b = -b;
}

/// |(a, b, c)|. Fixed point scales by the largest first: squares of differences of rotation
/// entries near 0 or pi (1e-4) would fall below the resolution (2^-23) and vanish.
real norm3(real a, real b, real c) {
  using std::abs;
  using std::sqrt;
  if constexpr (std::is_floating_point<real>::value) {
    return sqrt(a * a + b * b + c * c);
  } else {
    const real m = vpMath::maximum(abs(a), vpMath::maximum(abs(b), abs(c)));
    if (m == 0) return m;
    const real x = a / m, y = b / m, z = c / m;
    return m * sqrt(x * x + y * y + z * z);
  }
}

/// The axis near pi in fixed point: the largest component from the diagonal, as upstream, the
/// others from the symmetric off-diagonal sums R_kj + R_jk = 2 (1 - c) u_k u_j. Upstream takes
/// every component from the diagonal, through a square root that turns the resolution 2^-23 of
/// a component near 0 into an error of 3e-4; the sums keep it linear.
void axis_near_pi(const vpRotationMatrix& R, real c, real u[3]) {
  using std::sqrt;
  unsigned int k = 0;
  for (unsigned int n = 1; n < 3; ++n)
    if (R[n][n] > R[k][k]) k = n;
  const real d = R[k][k] - c;
  u[k] = d > 0 ? sqrt(d / (real(1) - c)) : real(0);
  // Upstream's sign for the largest component: that of the matching skew-symmetric part.
  const unsigned int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  if (R[k2][k1] - R[k1][k2] < 0) u[k] = -u[k];
  for (unsigned int n = 1; n < 3; ++n) {
    const unsigned int j = (k + n) % 3;
    u[j] = u[k] == 0 ? real(0) : (R[k][j] + R[j][k]) / ((real(1) - c) * u[k] * 2);
  }
}
}  // namespace

vpThetaUVector vpThetaUVector::buildFrom(const vpRotationMatrix& R) {
  using std::atan2;
  using std::sqrt;
  const real d10 = R[1][0] - R[0][1], d20 = R[2][0] - R[0][2], d21 = R[2][1] - R[1][2];
  const real s = norm3(d10, d20, d21) / 2;
  const real c = (R[0][0] + R[1][1] + R[2][2] - real(1)) / 2;
  const real theta = atan2(s, c);
  if (real(1) + c > kNearPi) {
    const real sinc = vpMath::sinc(s, theta);
    data_[0] = d21 / (sinc * 2);
    data_[1] = -d20 / (sinc * 2);
    data_[2] = d10 / (sinc * 2);
    return *this;
  }
  if constexpr (!std::is_floating_point<real>::value) {
    real u[3];
    axis_near_pi(R, c, u);
    for (unsigned int k = 0; k < 3; ++k) data_[k] = theta * u[k];
    return *this;
  }
  real x = axis_component(R[0][0], c), y = axis_component(R[1][1], c), z = axis_component(R[2][2], c);
  if (x > y && x > z) {
    if (d21 < 0) x = -x;
    align_sign(x, y, R[0][1] + R[1][0]);
    align_sign(x, z, R[0][2] + R[2][0]);
  } else if (y > z) {
    if (-d20 < 0) y = -y;
    align_sign(y, x, R[1][0] + R[0][1]);
    align_sign(y, z, R[1][2] + R[2][1]);
  } else {
    if (d10 < 0) z = -z;
    align_sign(z, x, R[2][0] + R[0][2]);
    align_sign(z, y, R[2][1] + R[1][2]);
  }
  data_[0] = theta * x;
  data_[1] = theta * y;
  data_[2] = theta * z;
  return *this;
}

vpThetaUVector vpThetaUVector::buildFrom(const vpHomogeneousMatrix& M) { return buildFrom(M.getRotationMatrix()); }

vpThetaUVector vpThetaUVector::buildFrom(const vpPoseVector& p) {
  buildFrom(p[3], p[4], p[5]);
  return *this;
}

vpThetaUVector vpThetaUVector::buildFrom(const vpColVector& tu) {
  buildFrom(tu[0], tu[1], tu[2]);
  return *this;
}

real vpThetaUVector::getTheta() const {
  using std::sqrt;
  return sqrt(data_[0] * data_[0] + data_[1] * data_[1] + data_[2] * data_[2]);
}

vpColVector vpThetaUVector::getU() const {
  vpColVector u(3);
  const real theta = getTheta();
  if (theta == 0) {
    u[2] = 1;
    return u;
  }
  for (unsigned int k = 0; k < 3; ++k) u[k] = data_[k] / theta;
  return u;
}

void vpThetaUVector::extract(real& theta, vpColVector& u) const {
  theta = getTheta();
  u = getU();
}

vpThetaUVector& vpThetaUVector::operator=(real x) {
  for (real& v : data_) v = x;
  return *this;
}

}  // inline namespace edgetrack_ports
