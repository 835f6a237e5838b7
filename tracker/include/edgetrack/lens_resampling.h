// SPDX-License-Identifier: BSD-3-Clause
/// Rendering through a lens: draw the scene through a pinhole camera with a margin (wide enough
/// for everything the lens shows) at some scale, then take each sample of each pixel of the
/// distorted image where the lens's inverse puts it in that pinhole image, bilinearly. Used by
/// the test-image renderer and by `edgetrack synth`.
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/pinhole_camera.h"

namespace edgetrack {

class LensResampling {
 public:
  /// Where one sample reads the pinhole image: the top-left of four neighbours (-1: outside
  /// it, or beyond the lens's fold) and its offsets to them in 1 / kWeightOne.
  struct Sample {
    int32_t index = -1;
    uint16_t fx = 0, fy = 0;
  };
  static constexpr int kWeightOne = 256;

  /// `camera` with its lens; `samples` per pixel along each axis; the pinhole image has `scale`
  /// of its pixels per camera pixel along each axis.
  LensResampling(const PinholeCamera& camera, int samples, int scale);

  /// The camera to draw the pinhole image with (no lens, the margin around, `scale` times larger).
  const PinholeCamera& pinhole_camera() const { return pinhole_; }
  int samples() const { return samples_; }
  /// The samples^2 samples of pixel (x, y), row by row.
  const Sample* pixel(int x, int y) const {
    return &samples_of_[(static_cast<size_t>(y) * width_ + x) * static_cast<size_t>(samples_ * samples_)];
  }
  /// sum over the pixel's samples of `value` read bilinearly at each (`value(index)` the pinhole
  /// image's value at an index; `outside` for a sample that reads nothing), in 1 / kWeightOne^2.
  template <class Value>
  int64_t weighted_sum(int x, int y, const Value& value, int outside) const {
    const Sample* s = pixel(x, y);
    const int64_t one = kWeightOne;
    const int row = pinhole_.width;
    int64_t sum = 0;
    for (int k = 0; k < samples_ * samples_; ++k) {
      if (s[k].index < 0) {
        sum += int64_t(outside) * one * one;
        continue;
      }
      const int32_t i = s[k].index;
      const int64_t top = int64_t(value(i)) * (one - s[k].fx) + int64_t(value(i + 1)) * s[k].fx;
      const int64_t bottom = int64_t(value(i + row)) * (one - s[k].fx) + int64_t(value(i + row + 1)) * s[k].fx;
      sum += top * (one - s[k].fy) + bottom * s[k].fy;
    }
    return sum;
  }

 private:
  PinholeCamera pinhole_;
  int samples_ = 1;
  int width_ = 0;
  std::vector<Sample> samples_of_;
};

}  // namespace edgetrack
