// SPDX-License-Identifier: BSD-3-Clause
/// vpMeLine on synthetic frames: a straight dark/bright edge moving along its normal by 0.7 px
/// per frame. Sites find the edge to their 1 px search step, so the tracked line must stay within
/// that of the true edge (the equation's residual at points of the edge), have its direction and
/// rho as its distance to the origin; every kept site must lie on the edge, and too few sites
/// must raise vpTrackingException, as upstream.
#include <cmath>
#include <list>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpImage.h"
#include "visp3/core/vpImagePoint.h"
#include "visp3/core/vpTrackingException.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeLine.h"
#include "visp3/me/vpMeSite.h"

namespace {

constexpr unsigned int kRows = 120, kCols = 160;

struct Edge {
  double ci, cj;  // a point of the edge
  double ni, nj;  // unit normal, towards the bright side
  double distance(double i, double j) const { return (i - ci) * ni + (j - cj) * nj; }
};

/// The edge drawn with 4 x 4 supersampling (pixel (i, j) covers [i, i+1) x [j, j+1)).
vpImage<unsigned char> draw(const Edge& e) {
  vpImage<unsigned char> I(kRows, kCols);
  for (unsigned int i = 0; i < kRows; ++i)
    for (unsigned int j = 0; j < kCols; ++j) {
      const double centre = e.distance(i + 0.5, j + 0.5);
      int bright = centre > 0 ? 16 : 0;
      if (std::fabs(centre) < 1) {  // supersampled near the edge only
        bright = 0;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) bright += e.distance(i + (a + 0.5) / 4, j + (b + 0.5) / 4) > 0 ? 1 : 0;
      }
      I[i][j] = static_cast<unsigned char>(50 + (150 * bright) / 16);
    }
  return I;
}

/// Largest |distance| to the edge of the kept sites (the mask is centred on the site's pixel,
/// whose centre is half a pixel further on).
double worst_site(const vpMeLine& line, const Edge& e) {
  double worst = 0;
  for (const vpMeSite& s : line.getMeList()) {
    if (s.getState() != vpMeSite::NO_SUPPRESSION) continue;
    worst = std::fmax(worst, std::fabs(e.distance(s.get_i() + 0.5, s.get_j() + 0.5)));
  }
  return worst;
}

}  // namespace

static void test_me_line() {
  const double angle = 0.4;  // the edge's direction, radians from the i axis
  Edge e{60, 80, -std::sin(angle), std::cos(angle)};
  vpMe me;
  me.setRange(6);
  me.setSampleStep(6);
  vpMeLine line;
  line.setMe(&me);
  vpImage<unsigned char> I = draw(e);
  // Two clicks on the edge, 1.5 px off it.
  const vpImagePoint p1(e.ci - 35 * std::cos(angle) + 1.5 * e.ni, e.cj - 35 * std::sin(angle) + 1.5 * e.nj);
  const vpImagePoint p2(e.ci + 35 * std::cos(angle) + 1.5 * e.ni, e.cj + 35 * std::sin(angle) + 1.5 * e.nj);
  line.initTracking(I, p1, p2);

  double worst_residual = 0, worst_direction = 0, worst_rho = 0, worst_sites = 0;
  unsigned int fewest = 1000;
  for (int frame = 0; frame < 6; ++frame) {
    if (frame > 0) {
      e.ci += 0.7 * e.ni;
      e.cj += 0.7 * e.nj;
      I = draw(e);
      line.track(I);
    }
    const double a = static_cast<double>(line.getA()), b = static_cast<double>(line.getB());
    const double c = static_cast<double>(line.getC());
    for (double t = -40; t <= 40; t += 20) {
      // Points of the true edge; pixel centres sit half a pixel beyond the sites' (i, j).
      const double i = e.ci + t * std::cos(angle) - 0.5, j = e.cj + t * std::sin(angle) - 0.5;
      worst_residual = std::fmax(worst_residual, std::fabs(a * i + b * j + c));
    }
    worst_direction = std::fmax(worst_direction, 1 - std::fabs(a * e.ni + b * e.nj));
    worst_rho = std::fmax(worst_rho, std::fabs(std::fabs(static_cast<double>(line.getRho())) - std::fabs(c)));
    worst_sites = std::fmax(worst_sites, worst_site(line, e));
    fewest = std::min(fewest, line.numberOfSignal());
  }
  TEST("a^2 + b^2 = 1", std::fabs(std::hypot(static_cast<double>(line.getA()), static_cast<double>(line.getB())) - 1) <
                            1e-5, true);
  TEST_NEAR("the line passes within 1 px (the search step) of the true edge in every frame", worst_residual, 0, 1.0);
  TEST_NEAR("its normal is the edge's normal (1 - |cos| below 1e-4)", worst_direction, 0, 1e-4);
  TEST_NEAR("|rho| is the line's distance to the origin", worst_rho, 0, 1e-5);
  TEST_NEAR("every kept site is within 1.5 px of the edge", worst_sites, 0, 1.5);
  TEST("at least 10 sites kept in every frame", fewest >= 10, true);
  const double theta = static_cast<double>(line.getTheta());
  TEST("theta in [0, 2 pi)", theta >= 0 && theta < 2 * M_PI, true);
  vpImagePoint end1, end2;
  line.getExtremities(end1, end2);
  TEST("the extremities lie on the line",
       std::fabs(static_cast<double>(line.getA() * end1.get_i() + line.getB() * end1.get_j() + line.getC())) < 1.0,
       true);

  bool thrown = false;
  try {
    line.track(vpImage<unsigned char>(kRows, kCols, 100));  // the edge is gone
  } catch (const vpTrackingException&) {
    thrown = true;
  }
  TEST("a frame without the edge raises vpTrackingException", thrown, true);
}

TESTMAIN(test_me_line)
