// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/me/vpMeLine.h: a straight edge tracked by moving edges, as the line
/// a i + b j + c = 0 (a^2 + b^2 = 1) and its (rho, theta), on `real`.
///
///   vpMe me;  me.setRange(15);  me.setThreshold(15000);
///   vpMeLine line;  line.setMe(&me);
///   line.initTracking(I, vpImagePoint(96, 191), vpImagePoint(122, 211));
///   line.track(I);  ...  line.getRho(), line.getTheta(), line.getMeList()
///
/// Per frame track() does upstream's steps: track the sites, drop the lost ones, fit the line
/// by Tukey-weighted least squares (weight < 0.2: M_ESTIMATOR), look 3 sample steps beyond
/// each end for more sites, fit again, resample when under 90% of the expected sites, and turn
/// the sites' normals to the new line. It throws vpTrackingException where upstream does (two
/// sites or fewer). Not ported: display(). Differences: docs/ME.md.
#pragma once

#ifdef vpMeLine_HH
#error "edgetrack's drop-in visp3/me/vpMeLine.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <list>

#include "real/real.h"
#include "visp3/core/vpImage.h"
#include "visp3/core/vpImagePoint.h"
#include "visp3/me/vpMeSite.h"
#include "visp3/me/vpMeTracker.h"

inline namespace edgetrack_ports {

class vpMeLine : public vpMeTracker {
 public:
  vpMeLine() = default;
  vpMeLine(const vpMeLine&) = default;
  vpMeLine& operator=(const vpMeLine&) = default;
  ~vpMeLine() override = default;

  void track(const vpImage<unsigned char>& I);
  /// Sites every sample_step pixels from the second extremity to the first, normal delta.
  void sample(const vpImage<unsigned char>& image, bool doNotTrack = false) override;
  void reSample(const vpImage<unsigned char>& I);
  void leastSquare();
  void updateDelta();
  void setExtremities();
  void seekExtremities(const vpImage<unsigned char>& I);
  void suppressPoints();
  /// The line through ip1 and ip2 (rounded to pixels for its angle), sampled, snapped and tracked once.
  void initTracking(const vpImage<unsigned char>& I, const vpImagePoint& ip1, const vpImagePoint& ip2);
  /// rho = |c| and theta = atan2(b, a) in [0, pi), then signed by the grey levels on either side.
  void computeRhoTheta(const vpImage<unsigned char>& I);
  real getRho() const { return rho; }
  real getTheta() const { return theta; }
  void getExtremities(vpImagePoint& ip1, vpImagePoint& ip2) const;
  void getEquationParam(real& A, real& B, real& C) const {
    A = a;
    B = b;
    C = c;
  }
  real getA() const { return a; }
  real getB() const { return b; }
  real getC() const { return c; }
  static bool intersection(const vpMeLine& line1, const vpMeLine& line2, vpImagePoint& ip);
  void computeRhoSignFromIntensity(bool useIntensityForRho) { _useIntensityForRho = useIntensityForRho; }

 protected:
  vpMeSite PExt[2];
  real rho = 0, theta = 0;
  real delta = 0, delta_1 = 0;
  real angle = 0, angle_1 = 90;
  int sign = 1;
  bool _useIntensityForRho = true;
  real a = 0, b = 0, c = 0;

 private:
  /// Tukey-weighted least squares over the kept sites of u x0 + x1 = -w, with (u, w) = (i, j)
  /// or (j, i); marks sites of weight below 0.2 M_ESTIMATOR.
  void fitLine(bool j_on_i, real& x0, real& x1);
};

}  // inline namespace edgetrack_ports
