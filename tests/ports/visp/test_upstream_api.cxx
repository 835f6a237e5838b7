// SPDX-License-Identifier: BSD-3-Clause
/// The ViSP 3.5 declarations that tests/bench/visp_coverage/signatures.py found missing in
/// ports/visp and that a moving-edge program meets, called with upstream's signatures and
/// checked against upstream's behaviour: vpMe::print, vpMeSite::getQueryList, vpException's
/// printf-style constructors, vpImage's fill, sum, mean, destroy and image-point access.
#include <cmath>
#include <cstring>
#include <string>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpException.h"
#include "visp3/core/vpImage.h"
#include "visp3/core/vpImagePoint.h"
#include "visp3/core/vpTrackingException.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeSite.h"

namespace {

bool contains(const std::string& text, const char* line) { return text.find(line) != std::string::npos; }

void test_me_print() {
  vpMe me;
  me.setRange(7);
  me.setMu1(0.25);
  const std::string text = me.settingsText();
  TEST("settings title", contains(text, "\nMoving edges settings \n\n"), true);
  TEST("mask size", contains(text, " Size of the convolution masks....5x5 pixels\n"), true);
  TEST("number of masks", contains(text, " Number of masks..................180        \n"), true);
  TEST("range as set", contains(text, " Query range +/- J................7 pixels  \n"), true);
  TEST("threshold", contains(text, " Likelihood test ratio............1500\n"), true);
  TEST("contrast tolerances in percent", contains(text, " Contrast tolerance +/-...........25% and 50%     \n"), true);
  TEST("sample step", contains(text, " Sample step......................10 pixels\n"), true);
  TEST("strip", contains(text, " Strip............................2 pixels  \n"), true);
  TEST("minimum sample step", contains(text, " Min_Samplestep...................4 pixels  \n"), true);
  me.print();  // the same text on stdout
}

void test_me_site_query_list() {
  vpMeSite site;
  const double alpha = 0.5;
  site.init(20.25, 30.5, alpha, 400.0, -1);
  site.setDisplay(vpMeSite::RANGE);
  const vpImage<unsigned char> I(64, 64);
  const int range = 3;
  vpMeSite* list = site.getQueryList(I, range);
  bool positions = true, pixels = true, copied = true;
  for (int k = -range; k <= range; ++k) {
    const vpMeSite& c = list[k + range];
    const double i = 20.25 + k * std::sin(alpha), j = 30.5 + k * std::cos(alpha);
    // sin and cos of `real` times k: a few of S47.16's 1.5e-5 ulps; candidates are 0.48 px apart.
    const double tolerance = 1e-3;
    positions = positions && std::fabs(static_cast<double>(c.get_ifloat()) - i) < tolerance &&
                std::fabs(static_cast<double>(c.get_jfloat()) - j) < tolerance;
    // The pixel is the truncation of the position, as upstream's init(i, j, alpha, convlt, sign).
    pixels = pixels && c.get_i() == static_cast<int>(c.get_ifloat()) && c.get_j() == static_cast<int>(c.get_jfloat());
    copied = copied && c.getAlpha() == site.getAlpha() && c.convlt == site.convlt && c.getSign() == -1 &&
             c.getState() == vpMeSite::NO_SUPPRESSION && c.getWeight() == real(1);
  }
  TEST("2 range + 1 candidates along the normal", positions, true);
  TEST("candidate pixels truncated", pixels, true);
  TEST("alpha, convlt and sign copied", copied, true);
  TEST("the middle candidate is the site", list[range].get_i() == 20 && list[range].get_j() == 30, true);
  delete[] list;
}

void test_exception_formats() {
  const vpException formatted(vpException::badValue, "%d sites, %s", 12, "too few");
  TEST("printf-style message", std::string(formatted.getMessage()), std::string("12 sites, too few"));
  TEST("its code", formatted.getCode(), static_cast<int>(vpException::badValue));
  const vpException bare(vpException::fatalError);
  TEST("code only: empty message", std::string(bare.getMessage()), std::string());
  const vpTrackingException tracking(vpTrackingException::notEnoughPointError, "%u of %u", 3u, 5u);
  TEST("tracking exception formats too", std::string(tracking.getMessage()), std::string("3 of 5"));
  TEST("tracking code kept", tracking.getCode(), static_cast<int>(vpTrackingException::notEnoughPointError));
  const vpTrackingException tracking_bare(vpTrackingException::fatalError);
  TEST("tracking code only", std::string(tracking_bare.what()), std::string());
}

void test_image_statistics_and_points() {
  vpImage<unsigned char> I(2, 3);
  I = 7;  // upstream's operator=(const Type&): every pixel
  TEST("fill", I[1][2] == 7 && I[0][0] == 7, true);
  TEST("number of pixels", I.getNumberOfPixel(), 6u);
  I[0][1] = 10;
  TEST("sum in double", I.getSum(), 45.0);
  TEST("mean truncated to the pixel type", static_cast<int>(I.getMeanValue()), 7);  // 45 / 6 = 7.5
  const vpImagePoint ip(1.75, 2.5);
  I(ip, 200);
  TEST("write at the truncated point", static_cast<int>(I[1][2]), 200);
  TEST("read at the truncated point", static_cast<int>(I(vpImagePoint(0.9, 1.9))), 10);
  vpImage<double> D(2, 2, 0.5);
  TEST("mean of doubles", D.getMeanValue(), 0.5);
  I.destroy();
  TEST("destroy frees the pixels", I.bitmap == nullptr && I.getSize() == 0u, true);
  const vpImage<unsigned char> empty;
  TEST("sum and mean of an empty image are 0", empty.getSum() == 0.0 && empty.getMeanValue() == 0, true);
}

}  // namespace

static void test_upstream_api() {
  test_me_print();
  test_me_site_query_list();
  test_exception_formats();
  test_image_statistics_and_points();
}

TESTMAIN(test_upstream_api)
