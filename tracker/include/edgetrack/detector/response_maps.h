// SPDX-License-Identifier: BSD-3-Clause
/// LINE-2D's precomputed response maps in linearised memory: for each of the 8 orientations, the
/// similarity of a template feature of that orientation to the spread orientations at every
/// pixel, stored as T x T arrays, one per pixel offset (x mod T, y mod T), each holding that
/// offset's pixels on the T-pixel grid row by row. A feature then adds one contiguous run of one
/// array to the template's score at every grid position (template_matching.h). Each array is
/// also kept shifted by 1, 2 and 3 bytes, so that a run starting anywhere is read as aligned
/// 32-bit words: four positions' bytes added by one 32-bit add (the sums stay under 256, as a
/// template has at most 63 features of at most 4), which a 32-bit core without SIMD needs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgetrack/detector/gradient_orientations.h"

namespace edgetrack {

/// The most a feature can add: its own orientation found in its neighbourhood.
constexpr int kBestSimilarity = 4;
/// Words readable past the end of a run (ResponseMaps::words), so that matching can add runs in
/// blocks of this many words without a shorter last block.
constexpr size_t kRunPadWords = 8;

/// The similarity of a feature of orientation `bin` to a spread byte: 4 when the byte has that
/// bin, 1 when it has a neighbouring bin (22.5 degrees off, cos 0.92) only, 0 otherwise; the
/// step from 4 to 1 keeps a 22.5-degree mismatch from scoring as a match.
int similarity(int bin, uint8_t spread);

class ResponseMaps {
 public:
  /// Fills the maps from `spread` (spread over t x t) for the grid of step t; the grid covers
  /// (width / t) x (height / t) positions. Buffers are kept between calls.
  void compute(const OrientationImage& spread, int t);

  int step() const { return t_; }
  int grid_width() const { return grid_width_; }
  int grid_height() const { return grid_height_; }
  /// The linearised responses of orientation `bin` at the pixels (dx + t i, dy + t j), 0 <= dx,
  /// dy < t, index j * grid_width() + i.
  const uint8_t* linear(int bin, int dx, int dy) const { return bytes(array_index(bin, dx, dy), 0); }
  /// The same run from index `start` on as aligned words: byte j of the words (in memory order)
  /// is linear(bin, dx, dy)[start + j]; readable for (cells - start + 3) / 4 + kRunPadWords words.
  const uint32_t* words(int bin, int dx, int dy, size_t start) const {
    const size_t shift = start % 4;
    return &memory_[(array_index(bin, dx, dy) * 4 + shift) * (stride_ / 4) + (start - shift) / 4];
  }

 private:
  size_t array_index(int bin, int dx, int dy) const {
    return static_cast<size_t>(bin) * t_ * t_ + static_cast<size_t>(dy) * t_ + dx;
  }
  const uint8_t* bytes(size_t array, size_t shift) const {
    return reinterpret_cast<const uint8_t*>(&memory_[(array * 4 + shift) * (stride_ / 4)]);
  }
  int t_ = 0;
  int grid_width_ = 0;
  int grid_height_ = 0;
  size_t cells_ = 0;
  size_t stride_ = 0;  ///< bytes per shifted copy: cells_ rounded up to words, plus the padding
  uint8_t table_[kOrientationBins][256] = {};
  bool table_ready_ = false;
  std::vector<uint32_t> memory_;  ///< per array, its 4 shifted copies (words: aligned for 32-bit loads)
};

}  // namespace edgetrack
