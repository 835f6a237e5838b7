// SPDX-License-Identifier: BSD-3-Clause
/// vpMe: defaults, and the oriented masks. Each weight is 100 times the signed area balance of
/// one pixel cut by the mask's edge line: round(100 * (A+ - A-)), A+ being the part of the pixel
/// on the positive side of the line through the mask centre at angle theta. This is the value
/// upstream reaches through segment clipping; here the pixel square is clipped by the half-plane
/// and its area taken with the shoelace formula. Set-up only, in double.
#include "visp3/me/vpMe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "vcl/vcl_cmath.h"

inline namespace edgetrack_ports {

namespace {

/// Area of the part of the unit square centred at (x, y) where n_x * X + n_y * Y > 0.
double positive_area(double x, double y, double n_x, double n_y) {
  const double corners[4][2] = {{x - 0.5, y - 0.5}, {x + 0.5, y - 0.5}, {x + 0.5, y + 0.5}, {x - 0.5, y + 0.5}};
  double poly[8][2];
  int count = 0;
  for (int k = 0; k < 4; ++k) {
    const double* p = corners[k];
    const double* q = corners[(k + 1) % 4];
    const double fp = n_x * p[0] + n_y * p[1];
    const double fq = n_x * q[0] + n_y * q[1];
    if (fp >= 0) {
      poly[count][0] = p[0];
      poly[count][1] = p[1];
      ++count;
    }
    if ((fp >= 0) != (fq >= 0)) {
      const double t = fp / (fp - fq);
      poly[count][0] = p[0] + t * (q[0] - p[0]);
      poly[count][1] = p[1] + t * (q[1] - p[1]);
      ++count;
    }
  }
  double twice_area = 0;
  for (int k = 0; k < count; ++k) {
    const double* p = poly[k];
    const double* q = poly[(k + 1) % count];
    twice_area += p[0] * q[1] - q[0] * p[1];
  }
  return std::fabs(twice_area) / 2;
}

}  // namespace

vpMe::vpMe()
    : threshold(1500),
      mu1(real(0.5)),
      mu2(real(0.5)),
      min_samplestep(4),
      anglestep(1),
      mask_sign(0),
      range(4),
      sample_step(10),
      ntotal_sample(0),
      points_to_track(500),
      mask_size(5),
      n_mask(180),
      strip(2) {
  initMask();
}

std::string vpMe::settingsText() const {
  // Upstream's report on std::cout; printf's %g is the stream's default format for doubles.
  char text[768];
  std::snprintf(text, sizeof text,
                "\nMoving edges settings \n\n"
                " Size of the convolution masks....%ux%u pixels\n"
                " Number of masks..................%u        \n"
                " Query range +/- J................%u pixels  \n"
                " Likelihood test ratio............%g\n"
                " Contrast tolerance +/-...........%g%% and %g%%     \n"
                " Sample step......................%g pixels\n"
                " Strip............................%d pixels  \n"
                " Min_Samplestep...................%g pixels  \n",
                mask_size, mask_size, n_mask, range, static_cast<double>(threshold), static_cast<double>(mu1) * 100,
                static_cast<double>(mu2) * 100, static_cast<double>(sample_step), strip,
                static_cast<double>(min_samplestep));
  return text;
}

void vpMe::print() { std::fputs(settingsText().c_str(), stdout); }

void vpMe::initMask() {
  const unsigned int step = n_mask == 0 ? 1 : (180 / n_mask > 0 ? 180 / n_mask : 1);
  const unsigned int n = mask_size;
  masks_.assign(static_cast<std::size_t>(n_mask) * n * n, 0);
  const double half = n / 2.0;
  for (unsigned int k = 0; k < n_mask; ++k) {
    const double theta = M_PI / 180 * (k * step);
    // Positive side of the edge line through the centre with direction (cos, sin):
    // cos * Y - sin * X > 0, X along columns, Y along rows.
    const double n_x = -std::sin(theta), n_y = std::cos(theta);
    int16_t* mask = masks_.data() + static_cast<std::size_t>(k) * n * n;
    for (unsigned int a = 0; a < n; ++a) {
      const double y = -half + 0.5 + a;
      for (unsigned int b = 0; b < n; ++b) {
        const double x = -half + 0.5 + b;
        const double balance = 2 * positive_area(x, y, n_x, n_y) - 1;
        mask[a * n + b] = static_cast<int16_t>(std::lround(100 * balance));
      }
    }
  }
  padded_masks_.clear();
  if (kPaddedRow >= n) {
    padded_masks_.assign(static_cast<std::size_t>(n_mask) * n * kPaddedRow, 0);
    for (std::size_t row = 0; row < static_cast<std::size_t>(n_mask) * n; ++row)
      std::copy(masks_.begin() + row * n, masks_.begin() + (row + 1) * n, padded_masks_.begin() + row * kPaddedRow);
  }
  masks_antisymmetric_ = true;
  const std::size_t cells = static_cast<std::size_t>(n) * n;
  for (std::size_t m = 0; m < masks_.size() && masks_antisymmetric_; ++m) {
    const std::size_t first = m - m % cells, partner = first + cells - 1 - m % cells;
    masks_antisymmetric_ = masks_[m] == -masks_[partner];
  }
}

void vpMe::setMaskNumber(const unsigned int& n) {
  n_mask = n;
  anglestep = n_mask == 0 ? 1 : (180 / n_mask > 0 ? 180 / n_mask : 1);
  initMask();
}

void vpMe::setMaskSize(const unsigned int& s) {
  mask_size = s;
  initMask();
}

unsigned int vpMe::maskIndex(const real& alpha) const {
  using std::round;
  static constexpr real kPi = real(M_PI);
  static constexpr real kHalfPi = real(M_PI_2);
  static constexpr real kDegreesPerRadian = real(180 / M_PI);
  // The mask is indexed by the tangent angle, alpha + pi/2, folded into [0, pi].
  real theta = alpha + kHalfPi;
  while (theta < 0) theta += kPi;
  while (theta > kPi) theta -= kPi;
  int degrees = static_cast<int>(round(theta * kDegreesPerRadian));
  if (degrees == 180) degrees = 0;
  // One mask per degree (upstream's default) needs no division: ARMv5TE has no divide instruction.
  const unsigned int index =
      anglestep > 1 ? static_cast<unsigned int>(degrees) / anglestep : static_cast<unsigned int>(degrees);
  return index < n_mask ? index : n_mask - 1;
}

}  // inline namespace edgetrack_ports
