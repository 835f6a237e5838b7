// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpColVector.h: a column vector of `real` (upstream: double), the
/// subset the moving edges and the pose classes use. Storage is one std::vector; resize keeps
/// its capacity, so a vector reused from frame to frame does not reallocate.
#pragma once

#ifdef _vpColVector_h_
#error "edgetrack's drop-in visp3/core/vpColVector.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>
#include <cstddef>
#include <vector>

#include "real/real.h"

inline namespace edgetrack_ports {

class vpColVector {
 public:
  vpColVector() = default;
  explicit vpColVector(unsigned int n) : data_(n, real(0)) {}
  vpColVector(unsigned int n, real value) : data_(n, value) {}
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpColVector(unsigned int n, double value) : data_(n, real(value)) {}
  vpColVector& operator=(double value) { return *this = real(value); }
#endif

  unsigned int getRows() const { return static_cast<unsigned int>(data_.size()); }
  unsigned int getCols() const { return 1; }
  unsigned int size() const { return getRows(); }
  /// New size; the elements are zero when flagNullify is true, else the kept ones keep their values.
  void resize(unsigned int n, bool flagNullify = true) {
    if (flagNullify) {
      data_.assign(n, real(0));
    } else {
      data_.resize(n, real(0));
    }
  }

  real& operator[](unsigned int n) { return data_[n]; }
  const real& operator[](unsigned int n) const { return data_[n]; }

  /// Every element set to `value`.
  vpColVector& operator=(real value) {
    for (real& x : data_) x = value;
    return *this;
  }

  vpColVector operator+(const vpColVector& v) const;
  vpColVector operator-(const vpColVector& v) const;
  vpColVector operator-() const;
  vpColVector operator*(real s) const;
  vpColVector operator/(real s) const;
  vpColVector& operator+=(const vpColVector& v);
  vpColVector& operator-=(const vpColVector& v);
  vpColVector& operator*=(real s);
  vpColVector& operator/=(real s);

  real sum() const;
  real sumSquare() const;
  real frobeniusNorm() const {
    using std::sqrt;
    return sqrt(sumSquare());
  }
  real euclideanNorm() const { return frobeniusNorm(); }
  static real dotProd(const vpColVector& a, const vpColVector& b);

  real* data() { return data_.data(); }
  const real* data() const { return data_.data(); }

 private:
  std::vector<real> data_;
};

inline vpColVector operator*(real s, const vpColVector& v) { return v * s; }

}  // inline namespace edgetrack_ports
