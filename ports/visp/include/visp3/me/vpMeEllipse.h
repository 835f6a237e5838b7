// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/me/vpMeEllipse.h: an ellipse (or an arc of it) tracked by moving edges,
/// on `real`. The ellipse is K0 u^2 + K1 v^2 + 2 K2 u v + 2 K3 u + 2 K4 v + K5 = 0, with centre
/// (uc, vc), normalised centred moments n20, n11, n02, semi-axes A >= B and orientation E.
///
///   vpMe me;  me.setRange(20);  me.setSampleStep(10);  // sample_step is in degrees here
///   vpMeEllipse ellipse;  ellipse.setMe(&me);
///   ellipse.initTracking(I, points);  // 5 or more vpImagePoint on the ellipse
///   ellipse.track(I);  ...  ellipse.get_ABE(), getCenter(), get_nij(), getMeList()
///
/// Per frame track() does upstream's steps: track the sites, fit the ellipse by least squares on
/// the algebraic equation weighted by Tukey's M-estimator on the geometric distance, drop
/// outliers (weight <= 0.2), sites outside the arc and sites closer than 0.6 sample steps,
/// plug holes and extend the ends, and resample when too few remain. It throws vpException
/// where upstream does. Not ported: display() and the click-based initTracking(I, trackArc).
/// ViSP 3.5's deprecated API (built in Debian's package) is here too, marked deprecated as
/// upstream: getA/B/E, getEquationParam, the raw and centred moments, and the initTracking forms
/// from a centre and axes or from arrays of points; the members it makes public stay protected.
#pragma once

#ifdef vpMeEllipse_HH
#error "edgetrack's drop-in visp3/me/vpMeEllipse.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <list>
#include <vector>

#include "real/real.h"
#include "visp3/core/vpColVector.h"
#include "visp3/core/vpImage.h"
#include "visp3/core/vpImagePoint.h"
#include "visp3/me/vpMeTracker.h"

inline namespace edgetrack_ports {

class vpMeEllipse : public vpMeTracker {
 public:
  vpMeEllipse();
  vpMeEllipse(const vpMeEllipse&) = default;
  vpMeEllipse& operator=(const vpMeEllipse&) = default;
  ~vpMeEllipse() override = default;

  /// n20, n11, n02.
  vpColVector get_nij() const;
  /// A, B, E (E in [-pi/2, pi/2], the angle of the major axis with the u axis).
  vpColVector get_ABE() const;
  real getArea() const { return m00; }
  vpImagePoint getCenter() const { return iPc; }
  unsigned int getExpectedDensity() const { return m_expectedDensity; }
  /// Sites kept by the last fit (upstream's m_numberOfGoodPoints).
  unsigned int getNumberOfGoodPoints() const { return m_numberOfGoodPoints; }
  vpImagePoint getFirstEndpoint() const { return iP1; }
  vpImagePoint getSecondEndpoint() const { return iP2; }
  real getHighestAngle() const { return m_alphamax; }
  real getSmallestAngle() const { return m_alphamin; }

  /// The ellipse through the points (least squares), sampled, snapped and tracked once. With
  /// trackArc, the first and last points bound the arc (clockwise).
  void initTracking(const vpImage<unsigned char>& I, const std::vector<vpImagePoint>& iP, bool trackArc = false);
  /// From param = (uc, vc, n20, n11, n02); an arc from pt1 to pt2 when both are given.
  void initTracking(const vpImage<unsigned char>& I, const vpColVector& param, vpImagePoint* pt1 = nullptr,
                    const vpImagePoint* pt2 = nullptr);
  void printParameters() const;
  void setEndpoints(const vpImagePoint& pt1, const vpImagePoint& pt2) {
    iP1 = pt1;
    iP2 = pt2;
  }
  void setThresholdRobust(real threshold) {
    thresholdWeight = threshold < 0 ? real(0) : (threshold > 1 ? real(1) : threshold);
  }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  void setThresholdRobust(double threshold) { setThresholdRobust(real(threshold)); }
#endif
  void track(const vpImage<unsigned char>& I);

  [[deprecated("use get_ABE()")]] real getA() const { return a; }
  [[deprecated("use get_ABE()")]] real getB() const { return b; }
  [[deprecated("use get_ABE()")]] real getE() const { return e; }
  [[deprecated("use get_ABE()")]] void getEquationParam(real& A, real& B, real& E) const {
    A = a;
    B = b;
    E = e;
  }
  /// The area and the raw (m10 ... m02) and centred (mu20, mu11, mu02) moments of the ellipse.
  [[deprecated("use getArea()")]] real get_m00() const { return m00; }
  [[deprecated("use getCenter() and getArea()")]] real get_m10() const { return m10; }
  [[deprecated("use getCenter() and getArea()")]] real get_m01() const { return m01; }
  [[deprecated("use get_nij() and getArea()")]] real get_m11() const { return m11; }
  [[deprecated("use get_nij() and getArea()")]] real get_m20() const { return m20; }
  [[deprecated("use get_nij() and getArea()")]] real get_m02() const { return m02; }
  [[deprecated("use get_nij() and getArea()")]] real get_mu11() const { return mu11; }
  [[deprecated("use get_nij() and getArea()")]] real get_mu02() const { return mu02; }
  [[deprecated("use get_nij() and getArea()")]] real get_mu20() const { return mu20; }
  /// The arc from alpha1 to alpha2 (radians) of the ellipse of centre, semi-axes and angle given.
  [[deprecated("use initTracking(I, param, pt1, pt2)")]] void initTracking(const vpImage<unsigned char>& I,
                                                                           const vpImagePoint& center_p, real a_p,
                                                                           real b_p, real e_p, real low_alpha,
                                                                           real high_alpha);
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  [[deprecated("use get_ABE()")]] void getEquationParam(double& A, double& B, double& E) const {
    A = static_cast<double>(a);
    B = static_cast<double>(b);
    E = static_cast<double>(e);
  }
  [[deprecated("use initTracking(I, param, pt1, pt2)")]] void initTracking(const vpImage<unsigned char>& I,
                                                                           const vpImagePoint& center_p, double a_p,
                                                                           double b_p, double e_p, double low_alpha,
                                                                           double high_alpha) {
    initArcTracking(I, center_p, real(a_p), real(b_p), real(e_p), real(low_alpha), real(high_alpha));
  }
#endif
  [[deprecated("use initTracking(I, points)")]] void initTracking(const vpImage<unsigned char>& I, unsigned int n,
                                                                  vpImagePoint* iP);
  [[deprecated("use initTracking(I, points)")]] void initTracking(const vpImage<unsigned char>& I, unsigned int n,
                                                                  unsigned* i, unsigned* j);

 protected:
  vpColVector K;
  vpImagePoint iPc;
  real a = 0, b = 0, e = 0;
  vpImagePoint iP1, iP2;
  real alpha1 = 0, alpha2 = real(2 * M_PI);
  real ce = 0, se = 0;
  std::list<real> angle;
  real m00 = 0;
  real mu11 = 0, mu20 = 0, mu02 = 0;
  real m10 = 0, m01 = 0;
  real m11 = 0, m02 = 0, m20 = 0;
  real thresholdWeight = real(0.2);
  real m_alphamin = 0, m_alphamax = 0;
  real m_uc = 0, m_vc = 0;
  real m_n20 = 0, m_n11 = 0, m_n02 = 0;
  unsigned int m_expectedDensity = 0;
  unsigned int m_numberOfGoodPoints = 0;
  bool m_trackArc = false;
  real m_arcEpsilon = real(1e-6);

  void computeAbeFromNij();
  real computeAngleOnEllipse(const vpImagePoint& pt) const;
  void computeKiFromNij();
  void computeNijFromAbe();
  void computePointOnEllipse(real ang, vpImagePoint& iP);
  real computeTheta(const vpImagePoint& iP) const;
  real computeTheta(real u, real v) const;
  /// Centre, moments, A, B, E from K, and K scaled so that K0 = n02.
  void getParameters();
  void leastSquare(const vpImage<unsigned char>& I, const std::vector<vpImagePoint>& iP);
  void leastSquareRobust(const vpImage<unsigned char>& I);
  unsigned int plugHoles(const vpImage<unsigned char>& I);
  void sample(const vpImage<unsigned char>& I, bool doNotTrack = false) override;
  void updateTheta();

 private:
  /// The body of the deprecated arc overloads: the double one calls it rather than the deprecated
  /// real one, which would warn wherever this header is included.
  void initArcTracking(const vpImage<unsigned char>& I, const vpImagePoint& center_p, real a_p, real b_p, real e_p,
                       real low_alpha, real high_alpha);
  /// K from a unit null vector of the system in coordinates normalised by (um, vm).
  void denormalise(const vpColVector& kernel, real um, real vm);
  /// A site on the ellipse at angle ang, snapped within +-2 pixels; false when lost or outside.
  bool addSite(const vpImage<unsigned char>& I, real ang, vpMeSite& site, real& site_angle);
  void setArcFromEndpoints();
  /// The deprecated moments from the area, the centre and n_ij.
  void computeMoments();
  /// The arc from first to last when tracking an arc and both are given, else the whole
  /// ellipse; then the sites are sampled and tracked once.
  void startTracking(const vpImage<unsigned char>& I, const vpImagePoint* first, const vpImagePoint* last);
};

}  // inline namespace edgetrack_ports
