// SPDX-License-Identifier: BSD-3-Clause
/// vpMeSite: the search along the normal. Per track(): one sine, one cosine and one mask index;
/// per candidate: a truncation, a border test and an integer mask_size^2 convolution; the
/// likelihood and contrast tests compare that integer with bounds computed once per site.
#include "visp3/me/vpMeSite.h"

#include <cmath>
#include <type_traits>

inline namespace edgetrack_ports {

namespace {

/// The integers n with n > x are those with n > floor_int(x); clamped far beyond any response.
int floor_int(real x) {
  using std::floor;
  static constexpr int kLimit = 1 << 30;
  if (x > real(kLimit)) return kLimit;
  if (x < real(-kLimit)) return -kLimit;
  return static_cast<int>(floor(x));
}

/// The integers n with n < x are those with n < ceil_int(x).
int ceil_int(real x) {
  using std::ceil;
  static constexpr int kLimit = 1 << 30;
  if (x > real(kLimit)) return kLimit;
  if (x < real(-kLimit)) return -kLimit;
  return static_cast<int>(ceil(x));
}

int round_int(real x) {
  using std::round;
  return static_cast<int>(round(x));
}

}  // namespace

vpMeSite::vpMeSite(real ip, real jp) : i(round_int(ip)), j(round_int(jp)), ifloat(ip), jfloat(jp) {}

void vpMeSite::init() {
  *this = vpMeSite();
  weight = -1;
}

void vpMeSite::init(real ip, real jp, real alphap) {
  selectDisplay = NONE;
  ifloat = ip;
  i = round_int(ip);
  jfloat = jp;
  j = round_int(jp);
  alpha = alphap;
  mask_sign = 1;
  v = 0;
  i_1 = 0;
  j_1 = 0;
}

void vpMeSite::init(real ip, real jp, real alphap, real convltp) { init(ip, jp, alphap, convltp, 1); }

void vpMeSite::init(real ip, real jp, real alphap, real convltp, int sign) {
  selectDisplay = NONE;
  ifloat = ip;
  i = static_cast<int>(ip);
  jfloat = jp;
  j = static_cast<int>(jp);
  alpha = alphap;
  convlt = convltp;
  mask_sign = sign;
  v = 0;
  i_1 = 0;
  j_1 = 0;
}

vpMeSite* vpMeSite::getQueryList(const vpImage<unsigned char>&, const int range) {
  using std::cos;
  using std::sin;
  const real s = sin(alpha), c = cos(alpha);
  vpMeSite* candidates = new vpMeSite[2 * static_cast<unsigned int>(range) + 1];
  for (int k = -range; k <= range; ++k) {
    vpMeSite& candidate = candidates[k + range];
    candidate.init(ifloat + k * s, jfloat + k * c, alpha, convlt, mask_sign);
    candidate.setDisplay(selectDisplay);
  }
  return candidates;
}

void vpMeSite::initFromImage(const vpImage<unsigned char>& I, const vpMe* me, real ip, real jp, real alphap) {
  init(ip, jp, alphap);
  const MaskResponse mask = response(I, me);
  if (mask.outside(i, j)) {
    convlt = 0;
    state = TOO_NEAR;
    return;
  }
  convlt = mask.at(i, j);
  state = NO_SUPPRESSION;
}

unsigned int vpMeSite::maskIndexFor(const vpMe* me) {
  if (me != mask_me_ || !(alpha == mask_alpha_) || me->getMaskNumber() != mask_number_ ||
      me->getAngleStep() != mask_angle_step_) {
    mask_me_ = me;
    mask_alpha_ = alpha;
    mask_number_ = me->getMaskNumber();
    mask_angle_step_ = me->getAngleStep();
    mask_index_ = me->maskIndex(alpha);
  }
  return mask_index_;
}

MaskResponse vpMeSite::response(const vpImage<unsigned char>& I, const vpMe* me) {
  return MaskResponse(I, *me, maskIndexFor(me), mask_sign);
}

real vpMeSite::convolution(const vpImage<unsigned char>& I, const vpMe* me) {
  const MaskResponse mask = response(I, me);
  if (mask.outside(i, j)) {
    i = 0;
    j = 0;
    return 0;
  }
  return mask.at(i, j);
}

void vpMeSite::getSearchBox(const vpMe* me, int& top, int& left, int& bottom, int& right) const {
  using std::cos;
  using std::sin;
  const real s = sin(alpha), c = cos(alpha);
  const int range = static_cast<int>(me->getRange());
  const int size = static_cast<int>(me->getMaskSize());
  const int half = (size - 1) >> 1;
  const int i_a = static_cast<int>(ifloat - range * s), i_b = static_cast<int>(ifloat + range * s);
  const int j_a = static_cast<int>(jfloat - range * c), j_b = static_cast<int>(jfloat + range * c);
  top = (i_a < i_b ? i_a : i_b) - half;
  bottom = (i_a < i_b ? i_b : i_a) - half + size;
  left = (j_a < j_b ? j_a : j_b) - half;
  right = (j_a < j_b ? j_b : j_a) - half + size;
}

void vpMeSite::track(const vpImage<unsigned char>& I, const vpMe* me, bool test_contraste) {
  track(I, me, test_contraste, me->getRange());
}

void vpMeSite::track(const vpImage<unsigned char>& I, const vpMe* me, bool test_contraste,
                     unsigned int search_range) {
  using std::cos;
  using std::sin;
  const int range = static_cast<int>(search_range);
  const MaskResponse mask = response(I, me);
  const real s = sin(alpha), c = cos(alpha);

  // Likelihood |conv + convlt| > threshold, for integer conv: conv > above or conv < below.
  const real threshold = me->getThreshold();
  int above, below;
  // Contrast conv / convlt in (1 - mu1, 1 + mu2): lo < conv < hi; empty when convlt is 0.
  int lo = 0, hi = 0;
  if (test_contraste) {
    above = floor_int(threshold - convlt);
    below = ceil_int(-threshold - convlt);
    const real c_min = real(1) - me->getMu1(), c_max = real(1) + me->getMu2();
    if (convlt > 0) {
      lo = floor_int(c_min * convlt);
      hi = ceil_int(c_max * convlt);
    } else if (convlt < 0) {
      lo = floor_int(c_max * convlt);
      hi = ceil_int(c_min * convlt);
    }
  } else {
    // |2 conv| > threshold.
    above = floor_int(threshold);
    below = 0;
  }

  int best = -1, best_conv = 0, best_i = 0, best_j = 0;
  real best_distance = 0, best_ifloat = 0, best_jfloat = 0;
  int best_likelihood = 0;
  bool last_passing_nonzero = false;

  real ii = 0, jj = 0;
  if constexpr (!std::is_floating_point<real>::value) {
    // Fixed point: stepping by s and c adds exactly what ifloat + k s would give.
    ii = ifloat - range * s;
    jj = jfloat - range * c;
  }
  for (int n = 0; n <= 2 * range; ++n) {
    if constexpr (std::is_floating_point<real>::value) {
      const int k = n - range;
      ii = ifloat + k * s;
      jj = jfloat + k * c;
    } else if (n > 0) {
      ii += s;
      jj += c;
    }
    int ci = static_cast<int>(ii), cj = static_cast<int>(jj);
    int conv = 0;
    if (mask.outside(ci, cj)) {
      ci = 0;  // upstream's convolution() moves an out-of-image candidate to (0, 0)
      cj = 0;
    } else {
      conv = mask.at(ci, cj);
    }

    bool take = false;
    if (test_contraste) {
      if (conv > above || conv < below) {
        last_passing_nonzero = conv != 0;
        if (conv > lo && conv < hi) {
          using std::abs;
          const real distance = abs(convlt - conv);
          if (best < 0 || distance < best_distance) {
            best_distance = distance;
            take = true;
          }
        }
      }
    } else {
      const int likelihood = conv < 0 ? -2 * conv : 2 * conv;
      if (likelihood > best_likelihood && likelihood > above) {
        best_likelihood = likelihood;
        take = true;
      }
    }
    if (take) {
      best = n;
      best_conv = conv;
      best_i = ci;
      best_j = cj;
      best_ifloat = ii;
      best_jfloat = jj;
    }
  }

  i_1 = i;
  j_1 = j;
  if (best >= 0) {
    ifloat = best_ifloat;
    jfloat = best_jfloat;
    i = best_i;
    j = best_j;
    v = 0;
    convlt = best_conv;
    normGradient = real(best_conv) * real(best_conv);
    weight = 1;
    state = NO_SUPPRESSION;
  } else {
    normGradient = 0;
    state = last_passing_nonzero ? CONSTRAST : THRESHOLD;
  }
}

}  // inline namespace edgetrack_ports
