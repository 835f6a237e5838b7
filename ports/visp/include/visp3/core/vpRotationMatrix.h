// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpRotationMatrix.h: a 3x3 rotation matrix, on `real`, built from
/// theta u by Rodrigues' formula (R = cos t I + sinc t [tu]x + mcosc t (tu)(tu)^T).
/// Not ported: the Euler-angle and quaternion conversions, mean(), the comma initialiser.
#pragma once

#ifdef vpROTATIONMATRIX_H
#error "edgetrack's drop-in visp3/core/vpRotationMatrix.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "real/real.h"
#include "visp3/core/vpColVector.h"
#include "visp3/core/vpMatrix.h"
#include "visp3/core/vpTranslationVector.h"

inline namespace edgetrack_ports {

class vpHomogeneousMatrix;
class vpPoseVector;
class vpThetaUVector;

class vpRotationMatrix {
 public:
  /// The identity.
  vpRotationMatrix() { eye(); }
  explicit vpRotationMatrix(const vpHomogeneousMatrix& M) { buildFrom(M); }
  explicit vpRotationMatrix(const vpThetaUVector& tu) { buildFrom(tu); }
  explicit vpRotationMatrix(const vpPoseVector& p) { buildFrom(p); }
  /// From a 3x3 vpMatrix (not checked, unlike upstream, which throws when it is no rotation).
  explicit vpRotationMatrix(const vpMatrix& R) { *this = R; }
  vpRotationMatrix(real tux, real tuy, real tuz) { buildFrom(tux, tuy, tuz); }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpRotationMatrix(double tux, double tuy, double tuz) { buildFrom(real(tux), real(tuy), real(tuz)); }
#endif

  vpRotationMatrix buildFrom(const vpHomogeneousMatrix& M);
  vpRotationMatrix buildFrom(const vpThetaUVector& tu);
  vpRotationMatrix buildFrom(const vpPoseVector& p);
  vpRotationMatrix buildFrom(real tux, real tuy, real tuz);

  void eye();
  vpColVector getCol(unsigned int j) const;
  vpThetaUVector getThetaUVector();
  /// The transpose.
  vpRotationMatrix inverse() const { return t(); }
  void inverse(vpRotationMatrix& R) const { R = t(); }
  vpRotationMatrix t() const;
  /// R^T R within threshold of the identity.
  bool isARotationMatrix(real threshold = real(1e-6)) const;

  vpRotationMatrix& operator=(const vpMatrix& M);
  vpTranslationVector operator*(const vpTranslationVector& t) const;
  vpRotationMatrix operator*(const vpRotationMatrix& R) const;
  vpMatrix operator*(const vpMatrix& M) const;
  vpColVector operator*(const vpColVector& v) const;
  vpRotationMatrix operator*(real x) const;
  vpRotationMatrix& operator*=(real x);

  unsigned int getRows() const { return 3; }
  unsigned int getCols() const { return 3; }
  real* operator[](unsigned int r) { return data_[r]; }
  const real* operator[](unsigned int r) const { return data_[r]; }
  /// As a vpMatrix (upstream's class derives from the array type).
  operator vpMatrix() const;  // NOLINT(google-explicit-constructor)

 private:
  real data_[3][3];
};

}  // inline namespace edgetrack_ports
