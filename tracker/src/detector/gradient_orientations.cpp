// SPDX-License-Identifier: BSD-3-Clause
/// Quantised gradient orientations, their spreading and the grey image's downscaling.
#include "edgetrack/detector/gradient_orientations.h"

#include <algorithm>

namespace edgetrack {

namespace {

// tan(11.25), tan(33.75), tan(56.25) and tan(78.75) degrees in 1/256: the bin boundaries, each
// 11.25 degrees from a bin's centre.
constexpr int32_t kBoundaryTanQ8[4] = {51, 171, 383, 1287};  // 0.199 0.668 1.496 5.027 (exact 0.199 0.668 1.497 5.027)

/// The bin of a direction in the first quadrant (x >= 0, y >= 0): 0 (along x) to 4 (along y).
int quadrant_bin(int32_t x, int32_t y) {
  int bin = 0;
  while (bin < 4 && y * 256 >= kBoundaryTanQ8[bin] * x) ++bin;
  return bin;
}

}  // namespace

int orientation_bin(int32_t gx, int32_t gy) {
  if (gy < 0 || (gy == 0 && gx < 0)) {  // modulo 180 degrees: turn into the upper half-plane
    gx = -gx;
    gy = -gy;
  }
  if (gx >= 0) return quadrant_bin(gx, gy);
  return (kOrientationBins - quadrant_bin(-gx, gy)) % kOrientationBins;  // mirrored about the y axis: 180 - angle
}

void quantise_orientations(const uint8_t* grey, int width, int height, const OrientationParams& params,
                           std::vector<uint8_t>& scratch, OrientationImage& out) {
  out.width = width;
  out.height = height;
  out.bits.assign(static_cast<size_t>(width) * height, 0);
  // Pass 1: the bin + 1 of every strong pixel, 0 for weak ones and the border.
  scratch.assign(static_cast<size_t>(width) * height, 0);
  const int32_t min_squared = int32_t(params.min_magnitude) * params.min_magnitude;
  for (int y = 1; y + 1 < height; ++y) {
    const uint8_t* up = grey + static_cast<size_t>(y - 1) * width;
    const uint8_t* row = up + width;
    const uint8_t* down = row + width;
    uint8_t* bins = &scratch[static_cast<size_t>(y) * width];
    for (int x = 1; x + 1 < width; ++x) {
      const int32_t gx = (up[x + 1] + 2 * row[x + 1] + down[x + 1]) - (up[x - 1] + 2 * row[x - 1] + down[x - 1]);
      const int32_t gy = (down[x - 1] + 2 * down[x] + down[x + 1]) - (up[x - 1] + 2 * up[x] + up[x + 1]);
      if (gx * gx + gy * gy >= min_squared) bins[x] = static_cast<uint8_t>(orientation_bin(gx, gy) + 1);
    }
  }
  // Pass 2: the most frequent bin of the 3x3 neighbourhood, when enough pixels agree on it.
  for (int y = 2; y + 2 < height; ++y) {
    for (int x = 2; x + 2 < width; ++x) {
      if (scratch[static_cast<size_t>(y) * width + x] == 0) continue;
      int counts[kOrientationBins + 1] = {0};
      for (int dy = -1; dy <= 1; ++dy) {
        const uint8_t* bins = &scratch[static_cast<size_t>(y + dy) * width + x - 1];
        ++counts[bins[0]];
        ++counts[bins[1]];
        ++counts[bins[2]];
      }
      int best = 1;
      for (int b = 2; b <= kOrientationBins; ++b)
        if (counts[b] > counts[best]) best = b;
      if (counts[best] >= params.min_agreeing)
        out.bits[static_cast<size_t>(y) * width + x] = static_cast<uint8_t>(1u << (best - 1));
    }
  }
}

void spread_orientations(const OrientationImage& in, int t, std::vector<uint8_t>& rows, OrientationImage& out) {
  const int w = in.width, h = in.height;
  out.width = w;
  out.height = h;
  out.bits.assign(static_cast<size_t>(w) * h, 0);
  // Rows first (OR of t pixels to the right), then columns of those (t rows below).
  rows.resize(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    const uint8_t* src = &in.bits[static_cast<size_t>(y) * w];
    uint8_t* dst = &rows[static_cast<size_t>(y) * w];
    for (int x = 0; x < w; ++x) {
      uint8_t v = 0;
      for (int dx = 0; dx < t && x + dx < w; ++dx) v |= src[x + dx];
      dst[x] = v;
    }
  }
  for (int y = 0; y < h; ++y) {
    uint8_t* dst = &out.bits[static_cast<size_t>(y) * w];
    for (int dy = 0; dy < t && y + dy < h; ++dy) {
      const uint8_t* src = &rows[static_cast<size_t>(y + dy) * w];
      for (int x = 0; x < w; ++x) dst[x] |= src[x];
    }
  }
}

void downscale_grey(const uint8_t* grey, int width, int height, int factor, std::vector<uint8_t>& out) {
  const int w = width / factor, h = height / factor, area = factor * factor;
  out.assign(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      int sum = 0;
      for (int dy = 0; dy < factor; ++dy) {
        const uint8_t* src = grey + static_cast<size_t>(y * factor + dy) * width + x * factor;
        for (int dx = 0; dx < factor; ++dx) sum += src[dx];
      }
      out[static_cast<size_t>(y) * w + x] = static_cast<uint8_t>((sum + area / 2) / area);
    }
  }
}

}  // namespace edgetrack
