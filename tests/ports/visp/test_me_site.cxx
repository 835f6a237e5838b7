// SPDX-License-Identifier: BSD-3-Clause
/// vpMeSite::track on synthetic step edges: the site moves along its normal onto the edge for
/// several angles and offsets, keeps it with the contrast test, and is suppressed with upstream's
/// state codes when the contrast changes too much (CONSTRAST) or the edge is gone (THRESHOLD).
#include <cmath>

#include "real/real.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeSite.h"

namespace {

constexpr int kSize = 48;
constexpr double kCentre = 23.5;  // the edge line passes through (kCentre, kCentre)

/// A step edge through the centre with normal angle alpha: `bright` where the signed distance
/// (i - c) sin(alpha) + (j - c) cos(alpha) of the pixel centre is positive, `dark` elsewhere.
vpImage<unsigned char> step_image(double alpha, unsigned char dark, unsigned char bright) {
  vpImage<unsigned char> I(kSize, kSize);
  for (int i = 0; i < kSize; ++i)
    for (int j = 0; j < kSize; ++j) {
      const double d = (i - kCentre) * std::sin(alpha) + (j - kCentre) * std::cos(alpha);
      I[i][j] = d > 0 ? bright : dark;
    }
  return I;
}

/// Signed distance of the site's pixel (where the mask was centred) to the edge line, along the normal.
double distance_to_edge(const vpMeSite& s, double alpha) {
  return (s.get_i() - kCentre) * std::sin(alpha) + (s.get_j() - kCentre) * std::cos(alpha);
}

void test_found_on_edge() {
  const vpMe me;  // range 4, mask 5, threshold 1500
  const double angles_deg[] = {0, 30, 45, 60, 90, 120, 135, 160, -30, -90};
  bool all_found = true, all_kept = true, along_normal = true, steady = true, truncated = true;
  double worst = 0;
  for (double deg : angles_deg) {
    const double alpha = deg * M_PI / 180;
    const vpImage<unsigned char> I = step_image(alpha, 40, 200);
    for (int offset = -3; offset <= 3; ++offset) {
      vpMeSite s;
      const double i0 = kCentre + offset * std::sin(alpha) + 0.25, j0 = kCentre + offset * std::cos(alpha) - 0.25;
      s.init(real(i0), real(j0), real(alpha));
      s.track(I, &me, false);
      const double d = distance_to_edge(s, alpha);
      all_found = all_found && s.getState() == vpMeSite::NO_SUPPRESSION;
      worst = std::fabs(d) > worst ? std::fabs(d) : worst;
      // The pixel is the truncated sub-pixel position, as upstream's (int) cast.
      truncated = truncated && s.get_i() == static_cast<int>(static_cast<double>(s.get_ifloat())) &&
                  s.get_j() == static_cast<int>(static_cast<double>(s.get_jfloat()));
      // The site moves by a whole number of steps along its normal: its offset across the normal stays.
      const double across = (static_cast<double>(s.get_ifloat()) - i0) * std::cos(alpha) -
                            (static_cast<double>(s.get_jfloat()) - j0) * std::sin(alpha);
      along_normal = along_normal && std::fabs(across) < 1e-4;
      // Second frame, same image, with the contrast test: the site stays put and stays kept.
      const double i1 = static_cast<double>(s.get_ifloat()), j1 = static_cast<double>(s.get_jfloat());
      const double reference = static_cast<double>(s.convlt);
      s.track(I, &me, true);
      all_kept = all_kept && s.getState() == vpMeSite::NO_SUPPRESSION;
      steady = steady && std::fabs(static_cast<double>(s.get_ifloat()) - i1) < 1.01 &&
               std::fabs(static_cast<double>(s.get_jfloat()) - j1) < 1.01 &&
               std::fabs(static_cast<double>(s.convlt) - reference) <= 0.5 * std::fabs(reference);
    }
  }
  TEST("a step edge within range is found (NO_SUPPRESSION) for every angle and offset", all_found, true);
  TEST_NEAR("found sites' pixels lie within 1 px of the edge line along the normal", worst, 0, 1.0);
  TEST("the site's pixel is its sub-pixel position truncated", truncated, true);
  TEST("the search moves the site only along its normal", along_normal, true);
  TEST("tracking again with the contrast test keeps the site on the edge", all_kept && steady, true);
}

void test_axis_aligned_position() {
  // Normal along the columns (alpha 0): the edge lies between columns 23 and 24; the 5x5 mask
  // responds fully at columns 23 and 24, and the search (k from -range) meets 23 first from the left.
  const vpMe me;
  const vpImage<unsigned char> I = step_image(0, 40, 200);
  vpMeSite s;
  s.init(real(20.0), real(21.0), real(0.0));
  s.track(I, &me, false);
  TEST("alpha 0, start 2.5 px left: kept", s.getState() == vpMeSite::NO_SUPPRESSION, true);
  TEST_EQUAL("alpha 0, start 2.5 px left: column 23", s.get_j(), 23);
  TEST_EQUAL("alpha 0: row unchanged", s.get_i(), 20);
  TEST_NEAR("response is 160 levels times the 10 weights of 100 (sign of the mask)",
            std::fabs(static_cast<double>(s.convlt)), 160.0 * 100 * 10, 0);
  TEST_EQUAL("previous position recorded in j_1", s.j_1, 21);

  s.init(real(20.0), real(27.0), real(0.0));
  s.track(I, &me, false);
  TEST_EQUAL("alpha 0, start 3.5 px right: column 23 (first of the tie)", s.get_j(), 23);

  // Out of range: the nearest candidate is 5 px from the edge, beyond range 4 + half mask.
  s.init(real(20.0), real(31.0), real(0.0));
  s.track(I, &me, false);
  TEST("edge beyond range + half mask: THRESHOLD", s.getState() == vpMeSite::THRESHOLD, true);
  TEST_EQUAL("a suppressed site stays where it was", s.get_j(), 31);
}

/// A ramp across the columns: 20 + slope (j - 10), clamped to [0, 255]; the alpha-0 mask gives
/// the same response, -3000 slope, at every candidate near column 23.
vpImage<unsigned char> ramp_image(int slope) {
  vpImage<unsigned char> I(kSize, kSize);
  for (int i = 0; i < kSize; ++i)
    for (int j = 0; j < kSize; ++j) {
      const int v = 20 + slope * (j - 10);
      I[i][j] = static_cast<unsigned char>(v < 0 ? 0 : (v > 255 ? 255 : v));
    }
  return I;
}

void test_suppression() {
  const vpMe me;
  // Reference: a 20-level step (100 to 120) with normal alpha 0, response -20000.
  vpMeSite first;
  first.init(real(20.0), real(22.0), real(0.0));
  first.track(step_image(0, 100, 120), &me, false);
  TEST("reference site found", first.getState() == vpMeSite::NO_SUPPRESSION, true);
  TEST_NEAR("reference response -20000", static_cast<double>(first.convlt), -20000, 0);

  // Every candidate on a ramp responds -3000 slope: the ratio to the reference is 0.15 slope.
  vpMeSite low = first, high = first, within = first;
  low.track(ramp_image(2), &me, true);        // ratio 0.3 < 1 - mu1
  high.track(ramp_image(11), &me, true);      // ratio 1.65 > 1 + mu2
  within.track(ramp_image(8), &me, true);     // ratio 1.2
  TEST("contrast ratio 0.3 at every candidate: CONSTRAST", low.getState() == vpMeSite::CONSTRAST, true);
  TEST("contrast ratio 1.65 at every candidate: CONSTRAST", high.getState() == vpMeSite::CONSTRAST, true);
  TEST("contrast ratio 1.2: kept", within.getState() == vpMeSite::NO_SUPPRESSION, true);
  TEST_NEAR("kept: the reference becomes the new response", static_cast<double>(within.convlt), -24000, 0);
  TEST_NEAR("suppressed: the reference contrast is kept", static_cast<double>(low.convlt), -20000, 0);
  TEST_EQUAL("suppressed: the site stays where it was", low.get_j(), first.get_j());

  // As upstream, the state reports the last candidate that passed the likelihood test: a weak
  // step with flat surroundings ends on a zero response (ratio 0), which upstream calls THRESHOLD.
  vpMeSite weak_step = first;
  weak_step.track(step_image(0, 100, 103), &me, true);
  TEST("weak step, flat at the end of the range: THRESHOLD (upstream's rule)",
       weak_step.getState() == vpMeSite::THRESHOLD, true);

  // Reversed polarity: conv = -convlt, likelihood |conv + convlt| = 0: THRESHOLD.
  vpMeSite reversed = first;
  reversed.track(step_image(0, 120, 100), &me, true);
  TEST("reversed polarity: THRESHOLD", reversed.getState() == vpMeSite::THRESHOLD, true);

  // A flat image: every response is 0, contrast ratio 0: THRESHOLD, with or without the test.
  const vpImage<unsigned char> flat(kSize, kSize, 128);
  vpMeSite gone = first;
  gone.track(flat, &me, true);
  TEST("edge gone, contrast test: THRESHOLD", gone.getState() == vpMeSite::THRESHOLD, true);
  vpMeSite gone2 = first;
  gone2.track(flat, &me, false);
  TEST("edge gone, no contrast test: THRESHOLD", gone2.getState() == vpMeSite::THRESHOLD, true);

  // The likelihood threshold without the contrast test: |2 conv| must exceed it.
  vpMe strict;
  strict.setThreshold(2 * 32 * 100 * 10);  // |2 conv| of a 32-level step at best: not above
  vpMeSite faint;
  faint.init(real(20.0), real(21.0), real(0.0));
  faint.track(step_image(0, 100, 132), &strict, false);
  TEST("|2 conv| equal to the threshold: THRESHOLD", faint.getState() == vpMeSite::THRESHOLD, true);
  strict.setThreshold(2 * 32 * 100 * 10 - 1);
  faint.track(step_image(0, 100, 132), &strict, false);
  TEST("|2 conv| just above the threshold: kept", faint.getState() == vpMeSite::NO_SUPPRESSION, true);
}

void test_follows_moving_edge() {
  // Normal along the columns; the edge moves 3 px right per frame, tracked with range 7 and the
  // contrast test: the site follows by exactly 3 columns each frame.
  vpMe me;
  me.setRange(7);
  vpMeSite s;
  s.init(real(20.0), real(18.0), real(0.0));
  s.track(step_image(0, 40, 200), &me, false);
  const int start = s.get_j();
  bool follows = s.getState() == vpMeSite::NO_SUPPRESSION;
  for (int frame = 1; frame <= 4; ++frame) {
    vpImage<unsigned char> I(kSize, kSize);
    for (int i = 0; i < kSize; ++i)
      for (int j = 0; j < kSize; ++j) I[i][j] = j - 3 * frame > kCentre ? 200 : 40;
    s.track(I, &me, true);
    follows = follows && s.getState() == vpMeSite::NO_SUPPRESSION && s.get_j() == start + 3 * frame &&
              s.get_i() == 20;
  }
  TEST("a site follows an edge moving 3 px per frame for 4 frames", follows, true);
}

void test_border_and_init_from_image() {
  const vpMe me;
  const vpImage<unsigned char> I = step_image(0, 40, 200);
  vpMeSite s;
  s.initFromImage(I, &me, real(1.0), real(23.0), real(0.0));
  TEST("initFromImage within the border strip: TOO_NEAR", s.getState() == vpMeSite::TOO_NEAR, true);
  s.initFromImage(I, &me, real(20.0), real(23.0), real(0.0));
  TEST("initFromImage on the edge: kept", s.getState() == vpMeSite::NO_SUPPRESSION, true);
  TEST_NEAR("initFromImage takes the mask response as the reference", std::fabs(static_cast<double>(s.convlt)),
            160.0 * 100 * 10, 0);
  vpMeSite t;
  t.init(real(20.0), real(23.0), real(0.0));
  TEST_NEAR("convolution() gives the same response", static_cast<double>(t.convolution(I, &me)),
            static_cast<double>(s.convlt), 0);

  int top = 0, left = 0, bottom = 0, right = 0;
  s.getSearchBox(&me, top, left, bottom, right);
  TEST("search box of alpha 0 spans range + half mask across, the mask down",
       top == 18 && bottom == 23 && left == 23 - 4 - 2 && right == 23 + 4 + 3, true);
}

}  // namespace

static void test_me_site() {
  test_found_on_edge();
  test_axis_aligned_position();
  test_suppression();
  test_follows_moving_edge();
  test_border_and_init_from_image();
}

TESTMAIN(test_me_site)
