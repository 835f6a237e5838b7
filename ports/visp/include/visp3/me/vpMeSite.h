// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/me/vpMeSite.h: one moving-edge site (position, normal angle alpha,
/// reference contrast convlt) and its search along the normal, with upstream's state codes.
///
/// How the tracker uses it, once per control point per frame:
///   vpMeSite s;
///   s.init(i, j, alpha);          // sub-pixel position (row i, column j), normal angle in radians
///   s.track(I, &me, false);       // first frame: strongest edge within +-range, sets convlt
///   ... next frame, same object (or init(i, j, alpha) again, convlt is kept):
///   s.track(I, &me);              // also requires the contrast to stay within [1-mu1, 1+mu2]
///   if (s.getState() == vpMeSite::NO_SUPPRESSION) use s.get_ifloat(), s.get_jfloat();
/// initFromImage() is the alternative to the first track(): it takes convlt from the image at
/// the given position itself, without searching. getSearchBox() gives the pixels track() reads.
/// Display code is not ported: setDisplay() only records the choice.
///
/// Differences from upstream (docs/ME.md): scalars are `real`; no heap allocation per track()
/// (track() does not go through getQueryList()); sine, cosine and mask index once per track();
/// convolution, likelihood and contrast tests are integer comparisons (exact, see track()); the
/// mask index is kept for the next convolution() with the same alpha.
#pragma once

#ifdef vpMeSite_H
#error "edgetrack's drop-in visp3/me/vpMeSite.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>

#include "real/real.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/mask_response.h"

inline namespace edgetrack_ports {

class vpMeSite {
 public:
  typedef enum { NONE, RANGE, RESULT, RANGE_RESULT } vpMeSiteDisplayType;

  /// Why a site is kept or dropped; the values are upstream's.
  typedef enum {
    NO_SUPPRESSION = 0,  ///< kept
    CONSTRAST = 1,       ///< candidates passed the likelihood threshold but not the contrast test
    THRESHOLD = 2,       ///< no candidate passed the likelihood threshold
    M_ESTIMATOR = 3,     ///< rejected later by the robust pose estimation
    TOO_NEAR = 4,        ///< too near the image border (set by initFromImage)
    UNKNOW = 5           ///< reserved
  } vpMeSiteState;

  int i = 0, j = 0;
  int i_1 = 0, j_1 = 0;
  real ifloat = 0, jfloat = 0;
  unsigned char v = 0;
  int mask_sign = 1;
  /// Angle of the normal to the edge at the site, radians (upstream calls it the tangent's).
  real alpha = 0;
  /// Convolution at the site in the previous image: the reference contrast.
  real convlt = 0;
  real normGradient = 0;
  real weight = 1;

  vpMeSite() = default;
  vpMeSite(real ip, real jp);

  /// Back to the state of a default site, except that weight becomes -1 (as upstream).
  void init();
  /// Moves the site to (ip, jp) rounded, with normal alpha; keeps convlt and the state.
  void init(real ip, real jp, real alphap);
  /// As above with i, j truncated and the reference contrast given.
  void init(real ip, real jp, real alphap, real convltp);
  void init(real ip, real jp, real alphap, real convltp, int sign);
  /// New: init(ip, jp, alphap), then convlt = the mask response at (ip, jp) in I, and the state
  /// NO_SUPPRESSION, or TOO_NEAR (convlt 0) when the mask would reach the border strip.
  void initFromImage(const vpImage<unsigned char>& I, const vpMe* me, real ip, real jp, real alphap);
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  // Set-up conversions from upstream's double arguments for the fixed-point builds.
  vpMeSite(double ip, double jp) : vpMeSite(real(ip), real(jp)) {}
  void init(double ip, double jp, double alphap) { init(real(ip), real(jp), real(alphap)); }
  void init(double ip, double jp, double alphap, double convltp) {
    init(real(ip), real(jp), real(alphap), real(convltp));
  }
  void init(double ip, double jp, double alphap, double convltp, int sign) {
    init(real(ip), real(jp), real(alphap), real(convltp), sign);
  }
#endif

  /// Mask response at (i, j): mask_sign * sum of weight * pixel, for the mask of alpha. If the
  /// mask would reach the border strip, returns 0 and sets i = j = 0, as upstream does.
  real convolution(const vpImage<unsigned char>& I, const vpMe* me);
  /// New: the response of this site's mask (alpha's mask, the site's sign) at any pixel of I,
  /// for callers reading many pixels of one site; convolution() at (i, j) is response(I, me).at(i, j).
  MaskResponse response(const vpImage<unsigned char>& I, const vpMe* me);

  /// Searches the 2 range + 1 candidates ifloat + k sin(alpha), jfloat + k cos(alpha), k in
  /// [-range, range] (pixel = truncation). With test_contraste, a candidate qualifies when its
  /// likelihood |conv + convlt| exceeds the threshold and conv / convlt lies in (1 - mu1, 1 + mu2);
  /// the one with conv closest to convlt wins (the first on ties). Without, the largest |2 conv|
  /// above the threshold wins. The winner becomes the site (state NO_SUPPRESSION, weight 1,
  /// convlt = its conv); otherwise the site stays and its state says why (CONSTRAST, THRESHOLD).
  void track(const vpImage<unsigned char>& I, const vpMe* me, bool test_contraste = true);
  /// New: the same search over +-search_range instead of me's range. The trackers use it where
  /// upstream temporarily changes the shared vpMe's range (initial and extremity searches).
  void track(const vpImage<unsigned char>& I, const vpMe* me, bool test_contraste, unsigned int search_range);

  /// Upstream's candidate list: a new[] array of the 2 range + 1 sites at ifloat + k sin(alpha),
  /// jfloat + k cos(alpha), k from -range to range, each init(..., alpha, convlt, mask_sign)
  /// (pixel = truncation) with this site's display choice; the caller delete[]s it. I is not
  /// read (upstream only draws on it).
  vpMeSite* getQueryList(const vpImage<unsigned char>& I, const int range);

  /// Pixels track() will read: rows [top, bottom), columns [left, right), not clipped.
  void getSearchBox(const vpMe* me, int& top, int& left, int& bottom, int& right) const;

  void setAlpha(const real& a) { alpha = a; }
  real getAlpha() const { return alpha; }
  void setDisplay(vpMeSiteDisplayType select) { selectDisplay = select; }
  int get_i() const { return i; }
  int get_j() const { return j; }
  real get_ifloat() const { return ifloat; }
  real get_jfloat() const { return jfloat; }
  void setState(const vpMeSiteState& flag) { state = flag; }
  vpMeSiteState getState() const { return state; }
  int getSign() const { return mask_sign; }
  void setWeight(const real& w) { weight = w; }
  real getWeight() const { return weight; }

  int operator!=(const vpMeSite& m) const { return m.i != i || m.j != j; }

  static real distance(const vpMeSite& s1, const vpMeSite& s2) {
    using std::sqrt;
    return sqrt(sqrDistance(s1, s2));
  }
  static real sqrDistance(const vpMeSite& s1, const vpMeSite& s2) {
    const real di = s1.ifloat - s2.ifloat, dj = s1.jfloat - s2.jfloat;
    return di * di + dj * dj;
  }

 private:
  /// me's mask index for alpha, kept for the next convolution() with the same alpha and masks
  /// (a caller reading several pixels of one site computes it once).
  unsigned int maskIndexFor(const vpMe* me);

  vpMeSiteDisplayType selectDisplay = NONE;
  vpMeSiteState state = NO_SUPPRESSION;
  const vpMe* mask_me_ = nullptr;
  real mask_alpha_ = 0;
  unsigned int mask_number_ = 0, mask_angle_step_ = 0, mask_index_ = 0;
};

}  // inline namespace edgetrack_ports
