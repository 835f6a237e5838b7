// SPDX-License-Identifier: BSD-3-Clause
/// LINE-2D's precomputed response maps in linearised memory: for each of the 8 orientations, the
/// similarity of a template feature of that orientation to the spread orientations at every
/// pixel, stored as T x T arrays, one per pixel offset (x mod T, y mod T), each holding that
/// offset's pixels on the T-pixel grid row by row. A feature then adds one contiguous run of one
/// array to the template's score at every grid position (template_matching.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgetrack/detector/gradient_orientations.h"

namespace edgetrack {

/// The most a feature can add: its own orientation found in its neighbourhood.
constexpr int kBestSimilarity = 4;

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
  const uint8_t* linear(int bin, int dx, int dy) const {
    return &memory_[(static_cast<size_t>(bin) * t_ * t_ + static_cast<size_t>(dy) * t_ + dx) * cells_];
  }

 private:
  int t_ = 0;
  int grid_width_ = 0;
  int grid_height_ = 0;
  size_t cells_ = 0;
  uint8_t table_[kOrientationBins][256] = {};
  bool table_ready_ = false;
  std::vector<uint8_t> memory_;
};

}  // namespace edgetrack
