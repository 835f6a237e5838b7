// SPDX-License-Identifier: BSD-3-Clause
/// What a camera does to the light it collected before a frame reaches the tracker, for
/// `edgetrack synth`: exposure and gain that change over the sequence (auto-exposure turning to
/// a window, a gain step) and JPEG compression (many pipelines hand over JPEG frames).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "edgetrack/result.h"
#include "image_io.h"

namespace edgetrack_app {

/// The brightness factor of each frame (exposure time times gain, relative to the render):
/// key frames with their factors, linear in between, constant before the first key and after
/// the last. Keys on consecutive frames make a sudden step (0:1,29:1,30:1.4: 40 % brighter from
/// frame 30 on).
class ExposureSchedule {
 public:
  /// "FRAME:FACTOR[,FRAME:FACTOR...]", frames increasing, factors in (0, kMaxFactor].
  static edgetrack::Result<ExposureSchedule> parse(const std::string& text);
  static constexpr double kMaxFactor = 16;

  double factor(int frame) const;
  bool empty() const { return keys_.empty(); }

 private:
  std::vector<std::pair<int, double>> keys_;
};

/// Every channel of every pixel times `factor`, rounded, clipped at 255 as a sensor saturates.
void apply_exposure(RgbImage& image, double factor);

/// The image as a JPEG of `quality` (1..100, OpenCV's imencode: baseline, 4:2:0 chroma) decodes.
edgetrack::Result<RgbImage> jpeg_round_trip(const RgbImage& image, int quality);

}  // namespace edgetrack_app
