// SPDX-License-Identifier: BSD-3-Clause
/// The response maps, computed straight into linearised memory through one lookup per pixel.
#include "edgetrack/detector/response_maps.h"

#include <cstring>

namespace edgetrack {

int similarity(int bin, uint8_t spread) {
  if (spread & (1u << bin)) return kBestSimilarity;
  const int left = (bin + kOrientationBins - 1) % kOrientationBins, right = (bin + 1) % kOrientationBins;
  if (spread & ((1u << left) | (1u << right))) return 1;
  return 0;
}

void ResponseMaps::compute(const OrientationImage& spread, int t) {
  if (!table_ready_) {
    for (int bin = 0; bin < kOrientationBins; ++bin)
      for (int s = 0; s < 256; ++s) table_[bin][s] = static_cast<uint8_t>(similarity(bin, static_cast<uint8_t>(s)));
    table_ready_ = true;
  }
  const bool same_grid = t == t_ && spread.width / t == grid_width_ && spread.height / t == grid_height_;
  t_ = t;
  grid_width_ = spread.width / t;
  grid_height_ = spread.height / t;
  cells_ = static_cast<size_t>(grid_width_) * grid_height_;
  stride_ = (cells_ + 3) / 4 * 4 + 4 * (kRunPadWords + 1);
  // Every byte below a copy's cells is written below; the ones past them (the padding, a shifted
  // copy's last bytes) stay the zeros of the first fill while the grid stays the same.
  const size_t words = static_cast<size_t>(kOrientationBins) * t * t * 4 * (stride_ / 4);
  if (!same_grid || memory_.size() != words) memory_.assign(words, 0);
  for (int bin = 0; bin < kOrientationBins; ++bin) {
    const uint8_t* table = table_[bin];
    for (int dy = 0; dy < t; ++dy) {
      for (int dx = 0; dx < t; ++dx) {
        const size_t array = array_index(bin, dx, dy);
        uint8_t* out = const_cast<uint8_t*>(bytes(array, 0));
        for (int j = 0; j < grid_height_; ++j) {
          const uint8_t* row = &spread.bits[static_cast<size_t>(dy + t * j) * spread.width + dx];
          for (int i = 0; i < grid_width_; ++i) *out++ = table[row[t * i]];
        }
        const uint8_t* first = bytes(array, 0);
        for (size_t shift = 1; shift < 4 && shift < cells_; ++shift)
          std::memcpy(const_cast<uint8_t*>(bytes(array, shift)), first + shift, cells_ - shift);
      }
    }
  }
}

}  // namespace edgetrack
