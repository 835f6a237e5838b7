// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpHomogeneousMatrix.h: a rigid transformation aMb = [R t; 0 1],
/// on `real`. Not ported: the quaternion forms, std::vector conversions, file load/save,
/// vpPoint products, mean(), the comma initialiser.
#pragma once

#ifdef VPHOMOGENEOUSMATRIX_HH
#error "edgetrack's drop-in visp3/core/vpHomogeneousMatrix.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "real/real.h"
#include "visp3/core/vpColVector.h"
#include "visp3/core/vpRotationMatrix.h"
#include "visp3/core/vpThetaUVector.h"
#include "visp3/core/vpTranslationVector.h"

inline namespace edgetrack_ports {

class vpPoseVector;

class vpHomogeneousMatrix {
 public:
  /// The identity.
  vpHomogeneousMatrix() { eye(); }
  vpHomogeneousMatrix(const vpTranslationVector& t, const vpRotationMatrix& R) { buildFrom(t, R); }
  vpHomogeneousMatrix(const vpTranslationVector& t, const vpThetaUVector& tu) { buildFrom(t, tu); }
  explicit vpHomogeneousMatrix(const vpPoseVector& p) { buildFrom(p); }
  vpHomogeneousMatrix(real tx, real ty, real tz, real tux, real tuy, real tuz) { buildFrom(tx, ty, tz, tux, tuy, tuz); }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpHomogeneousMatrix(double tx, double ty, double tz, double tux, double tuy, double tuz) {
    buildFrom(real(tx), real(ty), real(tz), real(tux), real(tuy), real(tuz));
  }
#endif

  void buildFrom(const vpTranslationVector& t, const vpRotationMatrix& R);
  void buildFrom(const vpTranslationVector& t, const vpThetaUVector& tu);
  void buildFrom(const vpPoseVector& p);
  void buildFrom(real tx, real ty, real tz, real tux, real tuy, real tuz);

  void eye();
  vpColVector getCol(unsigned int j) const;
  vpRotationMatrix getRotationMatrix() const;
  vpThetaUVector getThetaUVector() const;
  vpTranslationVector getTranslationVector() const;
  /// [R^T, -R^T t; 0 1].
  vpHomogeneousMatrix inverse() const;
  void inverse(vpHomogeneousMatrix& Mi) const { Mi = inverse(); }
  bool isAnHomogeneousMatrix(real threshold = real(1e-6)) const;
  void insert(const vpRotationMatrix& R);
  void insert(const vpThetaUVector& tu);
  void insert(const vpTranslationVector& t);
  void extract(vpRotationMatrix& R) const { R = getRotationMatrix(); }
  void extract(vpThetaUVector& tu) const { tu = getThetaUVector(); }
  void extract(vpTranslationVector& t) const { t = getTranslationVector(); }

  vpHomogeneousMatrix operator*(const vpHomogeneousMatrix& M) const;
  vpHomogeneousMatrix& operator*=(const vpHomogeneousMatrix& M) { return *this = *this * M; }
  /// A 4-vector (homogeneous point or direction).
  vpColVector operator*(const vpColVector& v) const;
  /// R t_b + t: the point t_b of frame b in frame a.
  vpTranslationVector operator*(const vpTranslationVector& t) const;
  void print() const;

  unsigned int getRows() const { return 4; }
  unsigned int getCols() const { return 4; }
  real* operator[](unsigned int r) { return data_[r]; }
  const real* operator[](unsigned int r) const { return data_[r]; }

 private:
  real data_[4][4];
};

}  // inline namespace edgetrack_ports
