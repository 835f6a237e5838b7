// SPDX-License-Identifier: BSD-3-Clause
/// vpMeEllipse: upstream's ellipse tracking steps (see the header), on `real`. The equation is
/// fitted in coordinates normalised by half the image size, (u - um) / um and (v - vm) / vm, as
/// upstream, which keeps the 6-column system well scaled (and within fixed point's range).
#include "visp3/me/vpMeEllipse.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <type_traits>

#include "visp3/core/vpException.h"
#include "visp3/core/vpMath.h"
#include "visp3/core/vpMatrix.h"
#include "visp3/core/vpRobust.h"

inline namespace edgetrack_ports {

namespace {

const real kPi = real(M_PI);
const real kTwoPi = real(2 * M_PI);
/// An arc of a whole number of steps (360 / 10 degrees) gives a quotient a few units of the last
/// place below that number in fixed point, where floor() would lose a site; double is exact.
const real kWholeStepSlack = std::is_floating_point<real>::value ? real(0) : real(1e-4);

/// new_ang moved by 2 pi towards ang when they are more than pi apart.
real unwrap_near(real new_ang, real ang) {
  if (new_ang - ang > kPi) return new_ang - kTwoPi;
  if (ang - new_ang > kPi) return new_ang + kTwoPi;
  return new_ang;
}

/// One row of the conic system for the normalised point (u, v).
void conic_row(real u, real v, real* row) {
  row[0] = u * u;
  row[1] = v * v;
  row[2] = u * v * 2;
  row[3] = u * 2;
  row[4] = v * 2;
  row[5] = 1;
}

/// The sample step in degrees, as radians (upstream replaces a zero step by 10 degrees).
real angle_step(const vpMe* me) {
  const real step = me->getSampleStep();
  return vpMath::rad(step == 0 ? real(10) : step);
}

vpColVector column3(real x, real y, real z) {
  vpColVector v(3);
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

}  // namespace

vpMeEllipse::vpMeEllipse() : K(6) {}

vpColVector vpMeEllipse::get_nij() const { return column3(m_n20, m_n11, m_n02); }

vpColVector vpMeEllipse::get_ABE() const { return column3(a, b, e); }

real vpMeEllipse::computeTheta(const vpImagePoint& iP) const { return computeTheta(iP.get_u(), iP.get_v()); }

real vpMeEllipse::computeTheta(real u, real v) const {
  using std::atan2;
  const real A = K[0] * u + K[2] * v + K[3];
  const real B = K[1] * v + K[2] * u + K[4];
  real theta = atan2(B, A);  // the normal's angle with the u axis, folded into [0, pi]
  if (theta < 0) theta += kPi;
  return theta;
}

void vpMeEllipse::updateTheta() {
  for (vpMeSite& s : list) s.alpha = computeTheta(s.jfloat, s.ifloat);
}

void vpMeEllipse::computePointOnEllipse(real ang, vpImagePoint& iP) {
  using std::cos;
  using std::sin;
  const real u = a * cos(ang), v = b * sin(ang);
  iP.set_uv(m_uc + ce * u - se * v, m_vc + se * u + ce * v);
}

real vpMeEllipse::computeAngleOnEllipse(const vpImagePoint& pt) const {
  using std::atan2;
  const real du = pt.get_u() - m_uc, dv = pt.get_v() - m_vc;
  const real co = (du * ce + dv * se) / a;
  const real si = (-du * se + dv * ce) / b;
  return atan2(si, co);
}

void vpMeEllipse::computeAbeFromNij() {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  real num = m_n20 - m_n02;
  real d = num * num + m_n11 * m_n11 * 4;
  if (d <= std::numeric_limits<real>::epsilon()) {  // a circle: E undefined
    e = 0;
    ce = 1;
    se = 0;
    a = b = sqrt(m_n20) * 2;
  } else {
    e = atan2(m_n11 * 2, num) / 2;
    ce = cos(e);
    se = sin(e);
    d = sqrt(d);
    num = m_n20 + m_n02;
    a = sqrt((num + d) * 2);
    b = sqrt((num - d) * 2);
  }
}

void vpMeEllipse::computeKiFromNij() {
  K[0] = m_n02;
  K[1] = m_n20;
  K[2] = -m_n11;
  K[3] = m_n11 * m_vc - m_n02 * m_uc;
  K[4] = m_n11 * m_uc - m_n20 * m_vc;
  K[5] = m_n02 * m_uc * m_uc + m_n20 * m_vc * m_vc - m_n11 * m_uc * m_vc * 2 +
         (m_n11 * m_n11 - m_n20 * m_n02) * 4;
}

void vpMeEllipse::computeNijFromAbe() {
  m_n20 = (a * a * ce * ce + b * b * se * se) / 4;
  m_n11 = se * ce * (a * a - b * b) / 4;
  m_n02 = (a * a * se * se + b * b * ce * ce) / 4;
}

void vpMeEllipse::getParameters() {
  const real num = K[0] * K[1] - K[2] * K[2];
  if (num <= 0) throw vpException(vpException::fatalError, "The points do not belong to an ellipse!");
  m_uc = (K[2] * K[4] - K[1] * K[3]) / num;
  m_vc = (K[2] * K[3] - K[0] * K[4]) / num;
  iPc.set_uv(m_uc, m_vc);
  real d = (K[0] * m_uc * m_uc + K[1] * m_vc * m_vc + K[2] * m_uc * m_vc * 2 - K[5]) / (num * 4);
  m_n20 = K[1] * d;
  m_n11 = -K[2] * d;
  m_n02 = K[0] * d;
  computeAbeFromNij();
  d = m_n02 / K[0];
  for (unsigned int k = 0; k < 6; ++k) K[k] *= d;
}

void vpMeEllipse::printParameters() const {
  std::cout << "K :";
  for (unsigned int k = 0; k < 6; ++k) std::cout << " " << static_cast<double>(K[k]);
  std::cout << "\nxc = " << static_cast<double>(m_uc) << ", yc = " << static_cast<double>(m_vc)
            << "\nn20 = " << static_cast<double>(m_n20) << ", n11 = " << static_cast<double>(m_n11)
            << ", n02 = " << static_cast<double>(m_n02) << "\nA = " << static_cast<double>(a)
            << ", B = " << static_cast<double>(b) << ", E (dg) " << static_cast<double>(vpMath::deg(e)) << std::endl;
}

void vpMeEllipse::sample(const vpImage<unsigned char>& I, bool doNotTrack) {
  using std::floor;
  if (me == nullptr) throw vpException(vpException::fatalError, "Moving edges on ellipse not initialized");
  list.clear();
  angle.clear();
  const int rows = static_cast<int>(I.getHeight()), cols = static_cast<int>(I.getWidth());
  const real incr = angle_step(me);
  m_expectedDensity = static_cast<unsigned int>(floor((alpha2 - alpha1) / incr + kWholeStepSlack));
  // Centred in [alpha1, alpha2]: the remainder split between both ends.
  real ang = alpha1 + ((alpha2 - alpha1) - real(static_cast<int>(m_expectedDensity)) * incr) / 2;
  for (unsigned int k = 0; k < m_expectedDensity; ++k) {
    vpImagePoint iP;
    computePointOnEllipse(ang, iP);
    if (!outOfImage(vpMath::round(iP.get_i()), vpMath::round(iP.get_j()), 0, rows, cols)) {
      vpMeSite pix;
      pix.init(iP.get_i(), iP.get_j(), computeTheta(iP));
      pix.setDisplay(selectDisplay);
      pix.setState(vpMeSite::NO_SUPPRESSION);
      list.push_back(pix);
      angle.push_back(ang);
    }
    ang += incr;
  }
  if (!doNotTrack) vpMeTracker::initTracking(I);
}

bool vpMeEllipse::addSite(const vpImage<unsigned char>& I, real ang, vpMeSite& site, real& site_angle) {
  const int rows = static_cast<int>(I.getHeight()), cols = static_cast<int>(I.getWidth());
  vpImagePoint iP;
  computePointOnEllipse(ang, iP);
  if (outOfImage(vpMath::round(iP.get_i()), vpMath::round(iP.get_j()), 0, rows, cols)) return false;
  site = vpMeSite();
  site.init(iP.get_i(), iP.get_j(), computeTheta(iP));
  site.setDisplay(selectDisplay);
  site.setState(vpMeSite::NO_SUPPRESSION);
  site.track(I, me, false, 2);  // upstream: range 2 (its mu1 = mu2 = 0.5 play no part without the contrast test)
  if (site.getState() != vpMeSite::NO_SUPPRESSION) return false;
  iP.set_ij(site.ifloat, site.jfloat);
  site_angle = unwrap_near(computeAngleOnEllipse(iP), ang);
  return true;
}

unsigned int vpMeEllipse::plugHoles(const vpImage<unsigned char>& I) {
  using std::floor;
  if (me == nullptr) throw vpException(vpException::fatalError, "Moving edges on ellipse tracking not initialized");
  unsigned int added = 0;
  const real incr = angle_step(me);
  vpMeSite site;
  real site_angle = 0;
  // A site in the middle of each gap wider than 1.6 steps between consecutive sites.
  if (!list.empty()) {
    auto angle_it = angle.begin();
    auto site_it = list.begin();
    real ang = *angle_it;
    for (++angle_it, ++site_it; site_it != list.end(); ++angle_it, ++site_it) {
      const real next = *angle_it;
      if (next - ang > incr * real(1.6) && addSite(I, (next + ang) / 2, site, site_angle)) {
        ++added;
        list.insert(site_it, site);
        angle.insert(angle_it, site_angle);
      }
      ang = next;
    }
  }
  // Then steps beyond each end, towards alpha1 and alpha2.
  const real before = floor((m_alphamin - alpha1) / incr);
  const unsigned int n_before = before > 0 ? static_cast<unsigned int>(before) : 0u;
  real ang = m_alphamin - incr;
  for (unsigned int k = 0; k < n_before; ++k, ang -= incr) {
    if (!addSite(I, ang, site, site_angle)) continue;
    ++added;
    list.push_front(site);
    angle.push_front(site_angle);
  }
  const real after = floor((alpha2 - m_alphamax) / incr);
  const unsigned int n_after = after > 0 ? static_cast<unsigned int>(after) : 0u;
  ang = m_alphamax + incr;
  for (unsigned int k = 0; k < n_after; ++k, ang += incr) {
    if (!addSite(I, ang, site, site_angle)) continue;
    ++added;
    list.push_back(site);
    angle.push_back(site_angle);
  }
  return added;
}

void vpMeEllipse::denormalise(const vpColVector& kernel, real um, real vm) {
  for (unsigned int k = 0; k < 6; ++k) K[k] = kernel[k] * (um * vm);
  K[0] /= um * um;
  K[1] /= vm * vm;
  K[2] /= um * vm;
  K[3] = K[3] / um - K[0] * um - K[2] * vm;
  K[4] = K[4] / vm - K[1] * vm - K[2] * um;
  K[5] = K[5] - K[0] * um * um - K[1] * vm * vm - K[2] * um * vm * 2 - K[3] * um * 2 - K[4] * vm * 2;
}

void vpMeEllipse::leastSquare(const vpImage<unsigned char>& I, const std::vector<vpImagePoint>& iP) {
  const real um = real(static_cast<int>(I.getWidth())) / 2, vm = real(static_cast<int>(I.getHeight())) / 2;
  const unsigned int n = static_cast<unsigned int>(iP.size());
  vpMatrix A(n, 6);
  for (unsigned int k = 0; k < n; ++k) conic_row((iP[k].get_u() - um) / um, (iP[k].get_v() - vm) / vm, A[k]);
  vpMatrix KerA;
  if (A.nullSpace(KerA, 1) > 1)
    throw vpException(vpException::fatalError, "Linear system for computing the ellipse equation ill conditionned");
  denormalise(KerA.getCol(0), um, vm);
  getParameters();
}

void vpMeEllipse::leastSquareRobust(const vpImage<unsigned char>& I) {
  const unsigned int nos = numberOfSignal();
  const real um = real(static_cast<int>(I.getWidth())) / 2, vm = real(static_cast<int>(I.getHeight())) / 2;
  vpMatrix A(nos, 6);
  vpColVector xp(nos), yp(nos);
  unsigned int k = 0;
  for (const vpMeSite& s : list) {
    if (s.getState() != vpMeSite::NO_SUPPRESSION) continue;
    conic_row((s.jfloat - um) / um, (s.ifloat - vm) / vm, A[k]);
    xp[k] = s.jfloat;
    yp[k] = s.ifloat;
    ++k;
  }
  if (k < 5) throw vpException(vpException::dimensionError, "Not enough moving edges to track the ellipse");

  vpRobust robust;
  robust.setMinMedianAbsoluteDeviation(real(1));  // image noise, pixels of geometric distance
  vpColVector w(k, real(1)), Kprev(6), residue(k);
  vpMatrix DA(k, 6), KerDA;
  real var = 1;
  for (unsigned int iter = 0; iter < 4 && var > real(0.001); ++iter) {
    for (unsigned int r = 0; r < k; ++r)
      for (unsigned int c = 0; c < 6; ++c) DA[r][c] = w[r] * A[r][c];
    if (DA.nullSpace(KerDA, 1) > 1)
      throw vpException(vpException::fatalError, "Linear system for computing the ellipse equation ill conditionned");
    const vpColVector kernel = KerDA.getCol(0);  // unit norm
    var = (kernel - Kprev).frobeniusNorm();
    Kprev = kernel;
    denormalise(kernel, um, vm);
    getParameters();
    for (unsigned int r = 0; r < k; ++r) {
      vpImagePoint measured, on_ellipse;
      measured.set_uv(xp[r], yp[r]);
      computePointOnEllipse(computeAngleOnEllipse(measured), on_ellipse);
      residue[r] = vpImagePoint::distance(measured, on_ellipse);
    }
    robust.MEstimator(vpRobust::TUKEY, residue, w);
  }

  // Keep the inliers inside [alpha1, alpha2] at least 0.6 steps after the previous kept one.
  const real incr = angle_step(me);
  real previous = -kPi * 4;
  k = 0;
  m_numberOfGoodPoints = 0;
  auto angle_it = angle.begin();
  for (auto site_it = list.begin(); site_it != list.end();) {
    bool keep = false;
    if (site_it->getState() == vpMeSite::NO_SUPPRESSION) {
      if (w[k] > thresholdWeight) {
        vpImagePoint iP;
        iP.set_ij(site_it->ifloat, site_it->jfloat);
        const real new_ang = unwrap_near(computeAngleOnEllipse(iP), *angle_it);
        if (new_ang >= alpha1 && new_ang <= alpha2 && new_ang - previous >= incr * real(0.6)) {
          *angle_it = previous = new_ang;
          keep = true;
        }
      }
      ++k;
    }
    if (keep) {
      ++m_numberOfGoodPoints;
      ++site_it;
      ++angle_it;
    } else {
      site_it = list.erase(site_it);
      angle_it = angle.erase(angle_it);
    }
  }
  if (!angle.empty()) {
    m_alphamin = angle.front();
    m_alphamax = angle.back();
  }
}

void vpMeEllipse::setArcFromEndpoints() {
  alpha1 = computeAngleOnEllipse(iP1);
  alpha2 = computeAngleOnEllipse(iP2);
  using std::abs;
  if (alpha2 <= alpha1 || abs(alpha2 - alpha1) < m_arcEpsilon) alpha2 += kTwoPi;
}

void vpMeEllipse::startTracking(const vpImage<unsigned char>& I, const vpImagePoint* first, const vpImagePoint* last) {
  if (m_trackArc && first != nullptr && last != nullptr) {
    iP1 = *first;
    iP2 = *last;
    setArcFromEndpoints();
  } else {
    alpha1 = 0;
    alpha2 = kTwoPi;
    computePointOnEllipse(alpha1, iP1);
    iP2 = iP1;
  }
  sample(I);
  track(I);
}

void vpMeEllipse::initTracking(const vpImage<unsigned char>& I, const std::vector<vpImagePoint>& iP, bool trackArc) {
  m_trackArc = trackArc;
  leastSquare(I, iP);
  startTracking(I, &iP.front(), &iP.back());
}

void vpMeEllipse::initTracking(const vpImage<unsigned char>& I, const vpColVector& param, vpImagePoint* pt1,
                               const vpImagePoint* pt2) {
  if (pt1 != nullptr && pt2 != nullptr) m_trackArc = true;
  m_uc = param[0];
  m_vc = param[1];
  m_n20 = param[2];
  m_n11 = param[3];
  m_n02 = param[4];
  computeAbeFromNij();
  computeKiFromNij();
  iPc.set_uv(m_uc, m_vc);
  startTracking(I, pt1, pt2);
}

void vpMeEllipse::track(const vpImage<unsigned char>& I) {
  vpMeTracker::track(I);
  if (m_trackArc) setArcFromEndpoints();
  leastSquareRobust(I);
  if (m_numberOfGoodPoints < m_expectedDensity && plugHoles(I) > 0) leastSquareRobust(I);
  const auto too_few = [this] {
    return 3 * m_numberOfGoodPoints < m_expectedDensity || m_numberOfGoodPoints <= 5 ||
           m_alphamax - m_alphamin < vpMath::rad(real(120));
  };
  if (too_few()) {
    sample(I);
    vpMeTracker::track(I);
    leastSquareRobust(I);
    if (too_few()) throw vpException(vpException::dimensionError, "Impossible to track the ellipse");
  }
  updateTheta();
  m00 = kPi * a * b;
  computePointOnEllipse(alpha1, iP1);
  computePointOnEllipse(alpha2, iP2);
  computeMoments();
}

void vpMeEllipse::computeMoments() {
  m10 = m_uc * m00;
  m01 = m_vc * m00;
  mu20 = m_n20 * m00;
  mu11 = m_n11 * m00;
  mu02 = m_n02 * m00;
  m20 = mu20 + m10 * m_uc;
  m11 = mu11 + m10 * m_vc;
  m02 = mu02 + m01 * m_vc;
}

void vpMeEllipse::initTracking(const vpImage<unsigned char>& I, const vpImagePoint& center_p, real a_p, real b_p,
                               real e_p, real low_alpha, real high_alpha) {
  initArcTracking(I, center_p, a_p, b_p, e_p, low_alpha, high_alpha);
}

void vpMeEllipse::initArcTracking(const vpImage<unsigned char>& I, const vpImagePoint& center_p, real a_p, real b_p,
                                  real e_p, real low_alpha, real high_alpha) {
  using std::cos;
  using std::sin;
  m_trackArc = true;
  m_uc = center_p.get_u();
  m_vc = center_p.get_v();
  a = a_p;
  b = b_p;
  e = e_p;
  ce = cos(e);
  se = sin(e);
  computeNijFromAbe();
  computeKiFromNij();
  alpha1 = low_alpha;
  alpha2 = high_alpha < low_alpha ? high_alpha + kTwoPi : high_alpha;
  computePointOnEllipse(alpha1, iP1);
  computePointOnEllipse(alpha2, iP2);
  iPc = center_p;
  sample(I);
  track(I);
}

void vpMeEllipse::initTracking(const vpImage<unsigned char>& I, unsigned int n, vpImagePoint* iP) {
  initTracking(I, std::vector<vpImagePoint>(iP, iP + n));
}

void vpMeEllipse::initTracking(const vpImage<unsigned char>& I, unsigned int n, unsigned* i, unsigned* j) {
  std::vector<vpImagePoint> points(n);
  for (unsigned int k = 0; k < n; ++k) points[k].set_ij(real(static_cast<int>(i[k])), real(static_cast<int>(j[k])));
  initTracking(I, points);
}

}  // inline namespace edgetrack_ports
