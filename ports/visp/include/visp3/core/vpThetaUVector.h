// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpThetaUVector.h: a rotation as theta u (angle times unit axis),
/// on `real`. Not ported: the Euler-angle and quaternion conversions.
#pragma once

#ifdef vpTHETAUVECTOR_H
#error "edgetrack's drop-in visp3/core/vpThetaUVector.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "real/real.h"
#include "visp3/core/vpColVector.h"

inline namespace edgetrack_ports {

class vpHomogeneousMatrix;
class vpPoseVector;
class vpRotationMatrix;

class vpThetaUVector {
 public:
  vpThetaUVector() = default;
  vpThetaUVector(real tux, real tuy, real tuz) { buildFrom(tux, tuy, tuz); }
  explicit vpThetaUVector(const vpRotationMatrix& R) { buildFrom(R); }
  explicit vpThetaUVector(const vpHomogeneousMatrix& M) { buildFrom(M); }
  explicit vpThetaUVector(const vpPoseVector& p) { buildFrom(p); }
  explicit vpThetaUVector(const vpColVector& tu) { buildFrom(tu); }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpThetaUVector(double tux, double tuy, double tuz) { buildFrom(real(tux), real(tuy), real(tuz)); }
#endif

  void buildFrom(real tux, real tuy, real tuz) {
    data_[0] = tux;
    data_[1] = tuy;
    data_[2] = tuz;
  }
  /// theta in [0, pi]; near pi the axis comes from R's diagonal, as upstream.
  vpThetaUVector buildFrom(const vpRotationMatrix& R);
  vpThetaUVector buildFrom(const vpHomogeneousMatrix& M);
  vpThetaUVector buildFrom(const vpPoseVector& p);
  vpThetaUVector buildFrom(const vpColVector& tu);

  /// theta and the unit axis u (u = (0, 0, 1) for theta = 0, as upstream).
  void extract(real& theta, vpColVector& u) const;
  real getTheta() const;
  vpColVector getU() const;

  unsigned int getRows() const { return 3; }
  unsigned int size() const { return 3; }
  real& operator[](unsigned int n) { return data_[n]; }
  const real& operator[](unsigned int n) const { return data_[n]; }
  vpThetaUVector& operator=(real x);

 private:
  real data_[3] = {0, 0, 0};
};

}  // inline namespace edgetrack_ports
