// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpImagePoint.h: a sub-pixel image position, row i (= v) and column
/// j (= u), on `real`. Drawing and the vpRect helpers are not ported.
#pragma once

#ifdef vpImagePoint_H
#error "edgetrack's drop-in visp3/core/vpImagePoint.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>
#include <ostream>

#include "real/real.h"

inline namespace edgetrack_ports {

class vpImagePoint {
 public:
  vpImagePoint() = default;
  vpImagePoint(real ii, real jj) : i(ii), j(jj) {}
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  vpImagePoint(double ii, double jj) : i(real(ii)), j(real(jj)) {}
  vpImagePoint(int ii, int jj) : i(ii), j(jj) {}
  void set_i(double ii) { i = real(ii); }
  void set_j(double jj) { j = real(jj); }
  void set_u(double u) { j = real(u); }
  void set_v(double v) { i = real(v); }
  void set_ij(double ii, double jj) { set_ij(real(ii), real(jj)); }
  void set_uv(double u, double v) { set_uv(real(u), real(v)); }
#endif

  void set_i(real ii) { i = ii; }
  void set_j(real jj) { j = jj; }
  void set_ij(real ii, real jj) {
    i = ii;
    j = jj;
  }
  void set_u(real u) { j = u; }
  void set_v(real v) { i = v; }
  void set_uv(real u, real v) {
    i = v;
    j = u;
  }
  real get_i() const { return i; }
  real get_j() const { return j; }
  real get_u() const { return j; }
  real get_v() const { return i; }

  vpImagePoint& operator+=(const vpImagePoint& ip) {
    i += ip.i;
    j += ip.j;
    return *this;
  }
  vpImagePoint& operator-=(const vpImagePoint& ip) {
    i -= ip.i;
    j -= ip.j;
    return *this;
  }
  vpImagePoint& operator*=(real s) {
    i *= s;
    j *= s;
    return *this;
  }
  vpImagePoint& operator/=(real s) {
    i /= s;
    j /= s;
    return *this;
  }

  static real distance(const vpImagePoint& a, const vpImagePoint& b) {
    using std::sqrt;
    return sqrt(sqrDistance(a, b));
  }
  static real sqrDistance(const vpImagePoint& a, const vpImagePoint& b) {
    const real di = a.i - b.i, dj = a.j - b.j;
    return di * di + dj * dj;
  }

 private:
  real i = 0, j = 0;
};

inline bool operator==(const vpImagePoint& a, const vpImagePoint& b) {
  return a.get_i() == b.get_i() && a.get_j() == b.get_j();
}
inline bool operator!=(const vpImagePoint& a, const vpImagePoint& b) { return !(a == b); }
inline vpImagePoint operator+(const vpImagePoint& a, const vpImagePoint& b) {
  return vpImagePoint(a.get_i() + b.get_i(), a.get_j() + b.get_j());
}
inline vpImagePoint operator+(const vpImagePoint& a, int offset) {
  return vpImagePoint(a.get_i() + offset, a.get_j() + offset);
}
inline vpImagePoint operator-(const vpImagePoint& a, const vpImagePoint& b) {
  return vpImagePoint(a.get_i() - b.get_i(), a.get_j() - b.get_j());
}
inline vpImagePoint operator-(const vpImagePoint& a, int offset) {
  return vpImagePoint(a.get_i() - offset, a.get_j() - offset);
}
inline vpImagePoint operator*(const vpImagePoint& a, real s) { return vpImagePoint(a.get_i() * s, a.get_j() * s); }
inline vpImagePoint operator/(const vpImagePoint& a, real s) { return vpImagePoint(a.get_i() / s, a.get_j() / s); }
/// Prints "i, j", as upstream.
inline std::ostream& operator<<(std::ostream& os, const vpImagePoint& ip) {
  return os << static_cast<double>(ip.get_i()) << ", " << static_cast<double>(ip.get_j());
}

}  // inline namespace edgetrack_ports
