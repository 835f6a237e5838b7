// SPDX-License-Identifier: BSD-3-Clause
/// vpMeLine: upstream's line tracking steps (see the header), on `real`.
#include "visp3/me/vpMeLine.h"

#include <cmath>
#include <cstdlib>
#include <type_traits>

#include "visp3/core/vpColVector.h"
#include "visp3/core/vpMath.h"
#include "visp3/core/vpRobust.h"
#include "visp3/core/vpTrackingException.h"

inline namespace edgetrack_ports {

namespace {

const real kPi = real(M_PI);
const real kHalfPi = real(M_PI / 2);

real fold_to_pi(real x) {
  while (x > kPi) x -= kPi;
  while (x < -kPi) x += kPi;
  return x;
}

/// The normal angle of the segment (i1, j1) -> (i2, j2).
real segment_normal(int i1, int j1, int i2, int j2) {
  using std::atan2;
  return fold_to_pi(atan2(real(i1 - i2), real(j1 - j2)) - kHalfPi);
}

/// Orthogonal projection of (i, j) onto a i + b j + c = 0, solved for the larger coefficient.
void project(real a, real b, real c, real i, real j, real& ip, real& jp) {
  using std::abs;
  const real norm2 = a * a + b * b;
  if (abs(a) > abs(b)) {
    jp = (a * a * j - a * b * i - c * b) / norm2;
    ip = (-c - b * jp) / a;
  } else {
    ip = (b * b * i - a * b * j - c * a) / norm2;
    jp = (-c - a * ip) / b;
  }
}

/// Upstream stores the clicked extremities through float; fixed point keeps its own precision
/// (and runs no floating-point code).
real through_float(real x) {
  if constexpr (std::is_floating_point<real>::value) return static_cast<real>(static_cast<float>(x));
  return x;
}

void check_me(const vpMe* me) {
  if (me == nullptr) throw vpTrackingException(vpTrackingException::initializationError, "Moving edges not initialized");
  if (me->getSampleStep() == 0) throw vpTrackingException(vpTrackingException::fatalError, "sample step = 0");
}

}  // namespace

void vpMeLine::sample(const vpImage<unsigned char>& I, bool /*doNotTrack*/) {
  using std::sqrt;
  check_me(me);
  const int rows = static_cast<int>(I.getHeight()), cols = static_cast<int>(I.getWidth());
  const real di = PExt[0].ifloat - PExt[1].ifloat, dj = PExt[0].jfloat - PExt[1].jfloat;
  const real length = sqrt(di * di + dj * dj);
  if (length == 0)
    throw vpTrackingException(vpTrackingException::fatalError, "points too close of each other to define a line");
  const real n_sample = length / me->getSampleStep();
  const real step_i = di / n_sample, step_j = dj / n_sample;
  real is = PExt[1].ifloat, js = PExt[1].jfloat;
  list.clear();
  for (int k = 0; k <= vpMath::round(n_sample); ++k) {
    if (!outOfImage(vpMath::round(is), vpMath::round(js), 0, rows, cols)) {
      vpMeSite pix;
      pix.init(real(static_cast<int>(is)), real(static_cast<int>(js)), delta, real(0), sign);
      pix.setDisplay(selectDisplay);
      list.push_back(pix);
    }
    is += step_i;
    js += step_j;
  }
}

namespace {
/// Minimises sum w_k^2 (u_k x0 + x1 - b_k)^2: upstream's pseudo-inverse of diag(w) A applied to
/// diag(w) B, solved on data centred at the weighted mean, which is the same solution and keeps
/// its precision in fixed point (u is a pixel coordinate, hundreds, beside the column of ones).
void weighted_line_fit(const vpColVector& u, const vpColVector& rhs, const vpColVector& w, real& x0, real& x1) {
  const unsigned int n = u.getRows();
  real sw = 0, su = 0, sb = 0;
  for (unsigned int k = 0; k < n; ++k) {
    const real w2 = w[k] * w[k];
    sw += w2;
    su += w2 * u[k];
    sb += w2 * rhs[k];
  }
  if (sw == 0) {
    x0 = x1 = 0;
    return;
  }
  const real mean_u = su / sw, mean_b = sb / sw;
  real suu = 0, sub = 0;
  for (unsigned int k = 0; k < n; ++k) {
    const real w2 = w[k] * w[k], du = u[k] - mean_u;
    suu += w2 * du * du;
    sub += w2 * du * (rhs[k] - mean_b);
  }
  x0 = suu == 0 ? real(0) : sub / suu;  // all u equal: the minimum-norm slope, as a pseudo-inverse gives
  x1 = mean_b - x0 * mean_u;
}
}  // namespace

void vpMeLine::fitLine(bool j_on_i, real& x0, real& x1) {
  using std::abs;
  const unsigned int n = numberOfSignal();
  vpColVector u(n), rhs(n), w(n, real(1)), residue(n);
  unsigned int k = 0;
  for (const vpMeSite& s : list) {
    if (s.getState() != vpMeSite::NO_SUPPRESSION) continue;
    u[k] = j_on_i ? s.ifloat : s.jfloat;
    rhs[k] = j_on_i ? -s.jfloat : -s.ifloat;
    ++k;
  }
  vpRobust robust;
  robust.setMinMedianAbsoluteDeviation(real(2));
  real previous0 = 0, previous1 = 0, distance = 100;
  x0 = 0;
  x1 = 0;
  for (unsigned int iter = 0; iter < 4 && distance > real(0.05); ++iter) {
    weighted_line_fit(u, rhs, w, x0, x1);
    for (unsigned int r = 0; r < n; ++r) residue[r] = rhs[r] - (u[r] * x0 + x1);
    robust.MEstimator(vpRobust::TUKEY, residue, w);
    distance = abs(x0 - previous0) + abs(x1 - previous1);
    previous0 = x0;
    previous1 = x1;
  }
  k = 0;
  for (vpMeSite& s : list) {
    if (s.getState() != vpMeSite::NO_SUPPRESSION) continue;
    if (w[k] < real(0.2)) s.setState(vpMeSite::M_ESTIMATOR);
    ++k;
  }
}

void vpMeLine::leastSquare() {
  using std::abs;
  using std::atan2;
  using std::sqrt;
  if (list.size() <= 2 || numberOfSignal() <= 2)
    throw vpTrackingException(vpTrackingException::notEnoughPointError, "not enough point");
  real x0, x1;
  if (abs(b) >= real(0.9)) {  // closer to vertical in (i, j): j as a function of i
    fitLine(true, x0, x1);
    a = x0;
    b = 1;
  } else {
    fitLine(false, x0, x1);
    a = 1;
    b = x0;
  }
  c = x1;
  const real norm = sqrt(a * a + b * b);
  a /= norm;
  b /= norm;
  c /= norm;
  delta = fold_to_pi(atan2(a, b));
}

void vpMeLine::initTracking(const vpImage<unsigned char>& I, const vpImagePoint& ip1, const vpImagePoint& ip2) {
  using std::atan2;
  using std::cos;
  using std::sin;
  const int i1 = vpMath::round(ip1.get_i()), i2 = vpMath::round(ip2.get_i());
  const int j1 = vpMath::round(ip1.get_j()), j2 = vpMath::round(ip2.get_j());
  PExt[0].ifloat = through_float(ip1.get_i());
  PExt[0].jfloat = through_float(ip1.get_j());
  PExt[1].ifloat = through_float(ip2.get_i());
  PExt[1].jfloat = through_float(ip2.get_j());
  const real direction = atan2(real(i1 - i2), real(j1 - j2));
  a = cos(direction);
  b = sin(direction);
  delta = segment_normal(i1, j1, i2, j2);
  delta_1 = delta;
  sample(I);
  vpMeTracker::initTracking(I);
  track(I);
}

void vpMeLine::suppressPoints() {
  list.remove_if([](const vpMeSite& s) { return s.getState() != vpMeSite::NO_SUPPRESSION; });
}

void vpMeLine::setExtremities() {
  using std::abs;
  real imin = real(1000000), jmin = real(1000000), imax = -1, jmax = -1;
  // The sites of smallest and largest row (or column), starting from the extremes found so far.
  const auto scan = [&](bool by_column) {
    for (const vpMeSite& s : list) {
      const real key = by_column ? s.jfloat : s.ifloat;
      if (key < (by_column ? jmin : imin)) {
        imin = s.ifloat;
        jmin = s.jfloat;
      }
      if (key > (by_column ? jmax : imax)) {
        imax = s.ifloat;
        jmax = s.jfloat;
      }
    }
  };
  scan(false);
  if (abs(imin - imax) < 25) scan(true);  // rather horizontal: the extremities by column
  PExt[0].ifloat = imin;
  PExt[0].jfloat = jmin;
  PExt[1].ifloat = imax;
  PExt[1].jfloat = jmax;
}

void vpMeLine::seekExtremities(const vpImage<unsigned char>& I) {
  using std::sqrt;
  check_me(me);
  const int rows = static_cast<int>(I.getHeight()), cols = static_cast<int>(I.getWidth());
  const real di_all = PExt[0].ifloat - PExt[1].ifloat, dj_all = PExt[0].jfloat - PExt[1].jfloat;
  const real length = sqrt(di_all * di_all + dj_all * dj_all);
  const real step = me->getSampleStep();
  const real di = di_all / length * step, dj = dj_all / length * step;
  // Three samples beyond each end, each snapped within +-1 pixel (upstream sets range 1).
  for (int end = 0; end < 2; ++end) {
    const real dir = end == 0 ? real(1) : real(-1);
    vpMeSite P;
    P.init(real(static_cast<int>(PExt[end].ifloat)), real(static_cast<int>(PExt[end].jfloat)), delta_1, real(0), sign);
    P.setDisplay(selectDisplay);
    for (int k = 0; k < 3; ++k) {
      P.ifloat = P.ifloat + dir * di;
      P.i = static_cast<int>(P.ifloat);
      P.jfloat = P.jfloat + dir * dj;
      P.j = static_cast<int>(P.jfloat);
      if (outOfImage(P.i, P.j, 5, rows, cols)) continue;
      P.track(I, me, false, 1);
      if (P.getState() == vpMeSite::NO_SUPPRESSION) list.push_back(P);
    }
  }
}

void vpMeLine::reSample(const vpImage<unsigned char>& I) {
  using std::sqrt;
  check_me(me);
  real i1, j1, i2, j2;
  project(a, b, c, PExt[0].ifloat, PExt[0].jfloat, i1, j1);
  project(a, b, c, PExt[1].ifloat, PExt[1].jfloat, i2, j2);
  PExt[0].ifloat = i1;
  PExt[0].jfloat = j1;
  PExt[1].ifloat = i2;
  PExt[1].jfloat = j2;
  const real length = sqrt((i1 - i2) * (i1 - i2) + (j1 - j2) * (j1 - j2));
  const real expected = length / me->getSampleStep();
  if (real(static_cast<int>(numberOfSignal())) < real(0.9) * expected) {
    const real delta_new = delta;
    delta = delta_1;
    sample(I);
    delta = delta_new;
    vpMeTracker::initTracking(I);
  }
}

void vpMeLine::updateDelta() {
  using std::abs;
  real tangent = delta + kHalfPi;
  while (tangent < 0) tangent += kPi;
  while (tangent > kPi) tangent -= kPi;
  int degrees = vpMath::round(tangent * real(180 / M_PI));
  if (degrees == 180 || degrees == -180) degrees = 0;
  angle = real(degrees);
  if (abs(angle - angle_1) > 90) sign = -sign;
  angle_1 = angle;
  for (vpMeSite& s : list) {
    s.alpha = delta;
    s.mask_sign = sign;
  }
  delta_1 = delta;
}

void vpMeLine::track(const vpImage<unsigned char>& I) {
  vpMeTracker::track(I);
  suppressPoints();
  setExtremities();
  leastSquare();
  seekExtremities(I);
  setExtremities();
  leastSquare();
  suppressPoints();
  setExtremities();
  reSample(I);
  updateDelta();
  computeRhoTheta(I);
}

namespace {
/// The two pixels `incr` away from (i, j) on either side, along (cos theta, sin theta).
void side_pixels(real theta, int i, int j, int incr, int& i1, int& i2, int& j1, int& j2) {
  using std::cos;
  using std::sin;
  const real ci = cos(theta) * incr, sj = sin(theta) * incr;
  i1 = static_cast<int>(i + ci);
  j1 = static_cast<int>(j + sj);
  i2 = static_cast<int>(i - ci);
  j2 = static_cast<int>(j - sj);
}
}  // namespace

void vpMeLine::computeRhoTheta(const vpImage<unsigned char>& I) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::floor;
  using std::sin;
  rho = abs(c);
  theta = atan2(b, a);
  while (theta >= kPi) theta -= kPi;
  while (theta < 0) theta += kPi;
  if (!_useIntensityForRho) return;

  const int i = vpMath::round((PExt[0].ifloat + PExt[1].ifloat) / 2);
  const int j = vpMath::round((PExt[0].jfloat + PExt[1].jfloat) / 2);
  const int width = static_cast<int>(I.getWidth()), height = static_cast<int>(I.getHeight());
  int incr = 10;
  int i1, i2, j1, j2;
  side_pixels(theta, i, j, incr, i1, i2, j1, j2);
  if (i1 < 0 || i1 >= height || i2 < 0 || i2 >= height || j1 < 0 || j1 >= width || j2 < 0 || j2 >= width) {
    const real rho_lim = vpMath::minimum(abs(real(i) / cos(theta)), abs(real(j) / sin(theta)));
    const real co_rho_lim = vpMath::minimum(abs(real(height - i) / cos(theta)), abs(real(width - j) / sin(theta)));
    incr = static_cast<int>(floor(vpMath::minimum(rho_lim, co_rho_lim)));
    if (incr < 1) throw vpTrackingException(vpTrackingException::fatalError, "increment is too small");
    side_pixels(theta, i, j, incr, i1, i2, j1, j2);
  }
  unsigned char v1 = 0, v2 = 0;
  for (bool end = false; !end;) {
    end = true;
    v1 = I[static_cast<unsigned int>(i1)][static_cast<unsigned int>(j1)];
    v2 = I[static_cast<unsigned int>(i2)][static_cast<unsigned int>(j2)];
    if (v1 == v2) {
      --incr;
      end = false;
      if (incr == 1)
        throw vpException(vpException::fatalError,
                          "In vpMeLine cannot determine rho sign, since there is no gray level difference between "
                          "both sides of the line");
    }
    side_pixels(theta, i, j, incr, i1, i2, j1, j2);
  }
  if (theta >= 0 && theta <= kHalfPi) {
    if (v2 < v1) {
      theta += kPi;
      rho = -rho;
    }
  } else {
    const real jinter = -c / b;
    if (v2 < v1) {
      theta += kPi;
      if (jinter > 0) rho = -rho;
    } else if (jinter < 0) {
      rho = -rho;
    }
  }
}

void vpMeLine::getExtremities(vpImagePoint& ip1, vpImagePoint& ip2) const {
  ip1.set_ij(PExt[0].ifloat, PExt[0].jfloat);
  ip2.set_ij(PExt[1].ifloat, PExt[1].jfloat);
}

bool vpMeLine::intersection(const vpMeLine& line1, const vpMeLine& line2, vpImagePoint& ip) {
  const real a1 = line1.a, b1 = line1.b, c1 = line1.c;
  const real a2 = line2.a, b2 = line2.b, c2 = line2.c;
  real i = 0, j = 0;
  if (a1 > real(0.1)) {
    const real denom = -(a2 / a1) * b1 + b2;
    if (denom == 0) return false;
    j = ((a2 / a1) * c1 - c2) / denom;
    i = (-b1 * j - c1) / a1;
  } else {
    const real denom = -(b2 / b1) * a1 + a2;
    if (denom == 0) return false;
    i = ((b2 / b1) * c1 - c2) / denom;
    j = (-a1 * i - c1) / b1;
  }
  ip.set_ij(i, j);
  return true;
}

}  // inline namespace edgetrack_ports
