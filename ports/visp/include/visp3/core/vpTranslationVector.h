// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpTranslationVector.h: a 3D translation (tx, ty, tz), on `real`.
/// Not ported: the comma initialiser, mean() and the row-vector products.
#pragma once

#ifdef vpTRANSLATIONVECTOR_H
#error "edgetrack's drop-in visp3/core/vpTranslationVector.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "real/real.h"
#include "visp3/core/vpColVector.h"
#include "visp3/core/vpMatrix.h"

inline namespace edgetrack_ports {

class vpHomogeneousMatrix;
class vpPoseVector;

class vpTranslationVector {
 public:
  vpTranslationVector() = default;
  vpTranslationVector(real tx, real ty, real tz) { set(tx, ty, tz); }
  explicit vpTranslationVector(const vpHomogeneousMatrix& M) { buildFrom(M); }
  explicit vpTranslationVector(const vpPoseVector& p) { buildFrom(p); }
  /// The first three elements of v.
  explicit vpTranslationVector(const vpColVector& v) { buildFrom(v); }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpTranslationVector(double tx, double ty, double tz) { set(real(tx), real(ty), real(tz)); }
  void set(double tx, double ty, double tz) { set(real(tx), real(ty), real(tz)); }
#endif

  vpTranslationVector buildFrom(real tx, real ty, real tz);
  vpTranslationVector buildFrom(const vpHomogeneousMatrix& M);
  vpTranslationVector buildFrom(const vpPoseVector& p);
  vpTranslationVector buildFrom(const vpColVector& v);
  void set(real tx, real ty, real tz) {
    data_[0] = tx;
    data_[1] = ty;
    data_[2] = tz;
  }

  unsigned int getRows() const { return 3; }
  unsigned int getCols() const { return 1; }
  unsigned int size() const { return 3; }
  real& operator[](unsigned int n) { return data_[n]; }
  const real& operator[](unsigned int n) const { return data_[n]; }

  vpTranslationVector operator+(const vpTranslationVector& t) const;
  vpTranslationVector operator-(const vpTranslationVector& t) const;
  vpTranslationVector operator-() const;
  vpTranslationVector operator*(real x) const;
  vpTranslationVector operator/(real x) const;
  vpTranslationVector& operator*=(real x);
  vpTranslationVector& operator/=(real x);
  vpTranslationVector& operator=(real x);

  real sumSquare() const { return data_[0] * data_[0] + data_[1] * data_[1] + data_[2] * data_[2]; }
  real frobeniusNorm() const;
  real euclideanNorm() const { return frobeniusNorm(); }
  /// The skew-symmetric matrix [t]x, with [t]x v = t x v.
  vpMatrix skew() const { return skew(*this); }
  static vpMatrix skew(const vpTranslationVector& t);
  static vpTranslationVector cross(const vpTranslationVector& a, const vpTranslationVector& b);
  /// As a vpColVector (upstream's class derives from the array type).
  operator vpColVector() const;  // NOLINT(google-explicit-constructor)

 private:
  real data_[3] = {0, 0, 0};
};

}  // inline namespace edgetrack_ports
