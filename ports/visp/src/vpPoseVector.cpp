// SPDX-License-Identifier: BSD-3-Clause
/// vpPoseVector: (t, theta u) to and from the other pose representations.
#include "visp3/core/vpPoseVector.h"

#include <cstdio>

#include "visp3/core/vpHomogeneousMatrix.h"

inline namespace edgetrack_ports {

void vpPoseVector::set(real tx, real ty, real tz, real tux, real tuy, real tuz) {
  data_[0] = tx;
  data_[1] = ty;
  data_[2] = tz;
  data_[3] = tux;
  data_[4] = tuy;
  data_[5] = tuz;
}

vpPoseVector vpPoseVector::buildFrom(real tx, real ty, real tz, real tux, real tuy, real tuz) {
  set(tx, ty, tz, tux, tuy, tuz);
  return *this;
}

vpPoseVector vpPoseVector::buildFrom(const vpHomogeneousMatrix& M) {
  return buildFrom(M.getTranslationVector(), M.getThetaUVector());
}

vpPoseVector vpPoseVector::buildFrom(const vpTranslationVector& t, const vpThetaUVector& tu) {
  set(t[0], t[1], t[2], tu[0], tu[1], tu[2]);
  return *this;
}

vpPoseVector vpPoseVector::buildFrom(const vpTranslationVector& t, const vpRotationMatrix& R) {
  return buildFrom(t, vpThetaUVector(R));
}

void vpPoseVector::print() const {
  for (unsigned int k = 0; k < 6; ++k) std::printf("%g\n", static_cast<double>(data_[k]));
}

}  // inline namespace edgetrack_ports
