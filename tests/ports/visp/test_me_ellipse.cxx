// SPDX-License-Identifier: BSD-3-Clause
/// vpMeEllipse on synthetic frames: a bright filled ellipse (semi-axes 45 and 28 px, major axis
/// at 0.35 rad) moving 1 px per frame. Initialised from five points of the true ellipse 1 px
/// outside it, the tracker must give the centre, A, B and E, every kept site must lie on the
/// outline, and the area and moments must follow from A, B, E. An arc of it (trackArc) must keep
/// its sites within the arc.
#include <cmath>
#include <vector>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpColVector.h"
#include "visp3/core/vpImage.h"
#include "visp3/core/vpImagePoint.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeEllipse.h"
#include "visp3/me/vpMeSite.h"

namespace {

constexpr unsigned int kRows = 150, kCols = 200;
constexpr double kA = 45, kB = 28, kE = 0.35;

/// Squared radius of (u, v) in the ellipse's own axes, scaled so that the outline is at 1.
double radius2(double u, double v, double uc, double vc) {
  const double du = u - uc, dv = v - vc;
  const double x = (du * std::cos(kE) + dv * std::sin(kE)) / kA, y = (-du * std::sin(kE) + dv * std::cos(kE)) / kB;
  return x * x + y * y;
}

/// 4 x 4 supersampling near the outline only (pixel (i, j) covers [i, i+1) x [j, j+1)).
vpImage<unsigned char> draw(double uc, double vc) {
  vpImage<unsigned char> I(kRows, kCols);
  for (unsigned int i = 0; i < kRows; ++i)
    for (unsigned int j = 0; j < kCols; ++j) {
      const double centre = radius2(j + 0.5, i + 0.5, uc, vc);
      int inside = centre < 1 ? 16 : 0;
      if (std::fabs(centre - 1) < 0.15) {
        inside = 0;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) inside += radius2(j + (b + 0.5) / 4, i + (a + 0.5) / 4, uc, vc) < 1 ? 1 : 0;
      }
      I[i][j] = static_cast<unsigned char>(40 + (160 * inside) / 16);
    }
  return I;
}

vpImagePoint on_outline(double t, double uc, double vc, double grow) {
  const double x = (kA + grow) * std::cos(t), y = (kB + grow) * std::sin(t);
  return vpImagePoint(vc + x * std::sin(kE) + y * std::cos(kE), uc + x * std::cos(kE) - y * std::sin(kE));
}

/// An arc: five points from t = 0.3 to 3.9 rad; the sites must stay within the arc's angles.
void test_arc() {
  const double uc = 95, vc = 72;
  vpMe me;
  me.setRange(6);
  me.setSampleStep(10);
  vpMeEllipse arc;
  arc.setMe(&me);
  const vpImage<unsigned char> I = draw(uc, vc);
  std::vector<vpImagePoint> points;
  for (double t : {0.3, 1.2, 2.1, 3.0, 3.9}) points.push_back(on_outline(t, uc, vc, 1.0));
  arc.initTracking(I, points, true);
  const double span = static_cast<double>(arc.getHighestAngle() - arc.getSmallestAngle());
  TEST_EQUAL("arc of 3.6 rad: 20 sites expected", arc.getExpectedDensity(), 20u);
  TEST("the sites span most of the arc and no more", span > 3.0 && span <= 3.6 + 1e-3, true);
  const vpColVector abe = arc.get_ABE();
  TEST_NEAR("the arc gives the ellipse's A within the 1 px search step", abe[0], kA, 1.0);
  TEST_NEAR("the arc gives the ellipse's B within the 1 px search step", abe[1], kB, 1.0);
  const vpImagePoint end = arc.getFirstEndpoint();
  TEST_NEAR("the first endpoint lies on the outline",
            (std::sqrt(radius2(static_cast<double>(end.get_j()) + 0.5, static_cast<double>(end.get_i()) + 0.5, uc, vc)) - 1) * kB,
            0, 1.5);
  TEST_NEAR("the first endpoint is near the first point", vpImagePoint::distance(end, points.front()), 0, 5.0);
}

}  // namespace

/// ViSP 3.5's deprecated API, as a program written for Debian's package calls it: the getters
/// agree with get_ABE and the moments with the area, centre and n_ij, and the old initTracking
/// forms track the same ellipse.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
void test_deprecated_api() {
  const double uc = 95, vc = 72;
  vpMe me;
  me.setRange(6);
  me.setSampleStep(10);
  const vpImage<unsigned char> I = draw(uc, vc);
  vpImagePoint points[5];
  unsigned rows[5], cols[5];
  int k = 0;
  for (double t : {0.3, 1.5, 2.7, 3.9, 5.1}) {
    points[k] = on_outline(t, uc, vc, 1.0);
    rows[k] = static_cast<unsigned>(std::lround(static_cast<double>(points[k].get_i())));
    cols[k] = static_cast<unsigned>(std::lround(static_cast<double>(points[k].get_j())));
    ++k;
  }
  vpMeEllipse from_array;
  from_array.setMe(&me);
  from_array.initTracking(I, 5, points);
  const vpColVector abe = from_array.get_ABE(), nij = from_array.get_nij();
  TEST("getA, getB, getE are get_ABE's",
       from_array.getA() == abe[0] && from_array.getB() == abe[1] && from_array.getE() == abe[2], true);
  real A = 0, B = 0, E = 0;
  from_array.getEquationParam(A, B, E);
  TEST("getEquationParam gives A, B, E", A == abe[0] && B == abe[1] && E == abe[2], true);
  const double m00 = static_cast<double>(from_array.get_m00());
  const double u = static_cast<double>(from_array.getCenter().get_u());
  TEST("get_m00 is the area", from_array.get_m00() == from_array.getArea(), true);
  // To one part in 1e6 (the products are formed in `real`).
  const double mu20 = static_cast<double>(nij[0]) * m00, m20 = mu20 + u * m00 * u;
  TEST_NEAR("m10 = uc m00", from_array.get_m10(), u * m00, 1e-6 * u * m00);
  TEST_NEAR("mu20 = n20 m00", from_array.get_mu20(), mu20, 1e-6 * mu20);
  TEST_NEAR("m20 = mu20 + m10 uc", from_array.get_m20(), m20, 1e-6 * m20);
  vpMeEllipse from_ij;
  from_ij.setMe(&me);
  from_ij.initTracking(I, 5, rows, cols);
  TEST_NEAR("initTracking from i, j arrays tracks the same ellipse", from_ij.get_ABE()[0], abe[0], 1.0);
  vpMeEllipse from_axes;
  from_axes.setMe(&me);
  from_axes.initTracking(I, vpImagePoint(vc - 0.5, uc - 0.5), real(kA), real(kB), real(kE), real(0), real(M_PI));
  TEST_NEAR("initTracking from centre and axes: the arc's A", from_axes.get_ABE()[0], kA, 1.0);
  TEST("and only the half arc is sampled", from_axes.getExpectedDensity(), 18u);
}
#pragma GCC diagnostic pop

static void test_me_ellipse() {
  test_arc();
  test_deprecated_api();
  double uc = 95, vc = 72;
  vpMe me;
  me.setRange(6);
  me.setSampleStep(10);  // degrees
  vpMeEllipse ellipse;
  ellipse.setMe(&me);
  vpImage<unsigned char> I = draw(uc, vc);
  std::vector<vpImagePoint> points;
  for (double t : {0.3, 1.5, 2.7, 3.9, 5.1}) points.push_back(on_outline(t, uc, vc, 1.0));
  ellipse.initTracking(I, points);
  TEST_EQUAL("36 sites expected for a 10 degree step", ellipse.getExpectedDensity(), 36u);

  // Sites and the fitted centre refer to pixel (i, j) = the mask centre; the drawn outline is
  // half a pixel further, so compare against (uc - 0.5, vc - 0.5).
  double worst_centre = 0, worst_axes = 0, worst_e = 0, worst_site = 0;
  unsigned int fewest = 1000;
  for (int frame = 0; frame < 5; ++frame) {
    if (frame > 0) {
      uc += 1.0;
      vc += 0.5;
      I = draw(uc, vc);
      ellipse.track(I);
    }
    const vpImagePoint centre = ellipse.getCenter();
    const vpColVector abe = ellipse.get_ABE();
    worst_centre = std::fmax(worst_centre, std::hypot(static_cast<double>(centre.get_u()) - (uc - 0.5),
                                                      static_cast<double>(centre.get_v()) - (vc - 0.5)));
    worst_axes = std::fmax(worst_axes, std::fmax(std::fabs(static_cast<double>(abe[0]) - kA),
                                                 std::fabs(static_cast<double>(abe[1]) - kB)));
    worst_e = std::fmax(worst_e, std::fabs(static_cast<double>(abe[2]) - kE));
    for (const vpMeSite& s : ellipse.getMeList()) {
      const double r = std::sqrt(radius2(s.get_j() + 0.5, s.get_i() + 0.5, uc, vc));
      worst_site = std::fmax(worst_site, std::fabs(r - 1) * kB);  // about pixels, at worst
    }
    fewest = std::min(fewest, ellipse.getNumberOfGoodPoints());
  }
  TEST_NEAR("centre within 1 px (the sites' search step) in every frame", worst_centre, 0, 1.0);
  TEST_NEAR("A and B within 0.5 px", worst_axes, 0, 0.5);
  TEST_NEAR("E within 0.02 rad", worst_e, 0, 0.02);
  TEST_NEAR("every site within 1.5 px of the outline", worst_site, 0, 1.5);
  TEST("at least 30 of the 36 sites kept in every frame", fewest >= 30, true);

  const vpColVector abe = ellipse.get_ABE(), nij = ellipse.get_nij();
  const double a = static_cast<double>(abe[0]), b = static_cast<double>(abe[1]), e = static_cast<double>(abe[2]);
  TEST_NEAR("area = pi A B", ellipse.getArea(), M_PI * a * b, 1e-3 * a * b);
  TEST_NEAR("n20 = (A^2 cos^2 E + B^2 sin^2 E) / 4", nij[0],
            (a * a * std::cos(e) * std::cos(e) + b * b * std::sin(e) * std::sin(e)) / 4, 1e-3 * a * a);
  TEST_NEAR("n11 = sin E cos E (A^2 - B^2) / 4", nij[1], std::sin(e) * std::cos(e) * (a * a - b * b) / 4, 1e-3 * a * a);
  TEST("an ellipse, not an arc: alpha spans more than 300 degrees",
       static_cast<double>(ellipse.getHighestAngle() - ellipse.getSmallestAngle()) > 300 * M_PI / 180, true);
}

TESTMAIN(test_me_ellipse)
