// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpPoseVector.h: a pose as (tx, ty, tz, theta ux, theta uy, theta uz),
/// on `real`. Not ported: quaternion extraction, file load/save, the formatted print().
#pragma once

#ifdef vpPOSEVECTOR_H
#error "edgetrack's drop-in visp3/core/vpPoseVector.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "real/real.h"
#include "visp3/core/vpRotationMatrix.h"
#include "visp3/core/vpThetaUVector.h"
#include "visp3/core/vpTranslationVector.h"

inline namespace edgetrack_ports {

class vpHomogeneousMatrix;

class vpPoseVector {
 public:
  vpPoseVector() = default;
  vpPoseVector(real tx, real ty, real tz, real tux, real tuy, real tuz) { set(tx, ty, tz, tux, tuy, tuz); }
  explicit vpPoseVector(const vpHomogeneousMatrix& M) { buildFrom(M); }
  vpPoseVector(const vpTranslationVector& t, const vpThetaUVector& tu) { buildFrom(t, tu); }
  vpPoseVector(const vpTranslationVector& t, const vpRotationMatrix& R) { buildFrom(t, R); }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpPoseVector(double tx, double ty, double tz, double tux, double tuy, double tuz) {
    set(real(tx), real(ty), real(tz), real(tux), real(tuy), real(tuz));
  }
#endif

  vpPoseVector buildFrom(real tx, real ty, real tz, real tux, real tuy, real tuz);
  vpPoseVector buildFrom(const vpHomogeneousMatrix& M);
  vpPoseVector buildFrom(const vpTranslationVector& t, const vpThetaUVector& tu);
  vpPoseVector buildFrom(const vpTranslationVector& t, const vpRotationMatrix& R);
  void set(real tx, real ty, real tz, real tux, real tuy, real tuz);

  void extract(vpRotationMatrix& R) const { R = getRotationMatrix(); }
  void extract(vpThetaUVector& tu) const { tu = getThetaUVector(); }
  void extract(vpTranslationVector& t) const { t = getTranslationVector(); }
  vpRotationMatrix getRotationMatrix() const { return vpRotationMatrix(getThetaUVector()); }
  vpThetaUVector getThetaUVector() const { return vpThetaUVector(data_[3], data_[4], data_[5]); }
  vpTranslationVector getTranslationVector() const { return vpTranslationVector(data_[0], data_[1], data_[2]); }

  unsigned int getRows() const { return 6; }
  unsigned int size() const { return 6; }
  real& operator[](unsigned int i) { return data_[i]; }
  const real& operator[](unsigned int i) const { return data_[i]; }
  void print() const;

 private:
  real data_[6] = {0, 0, 0, 0, 0, 0};
};

}  // inline namespace edgetrack_ports
