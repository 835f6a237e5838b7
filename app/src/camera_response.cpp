// SPDX-License-Identifier: BSD-3-Clause
#include "camera_response.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace edgetrack_app {

edgetrack::Result<ExposureSchedule> ExposureSchedule::parse(const std::string& text) {
  ExposureSchedule schedule;
  size_t at = 0;
  while (at <= text.size()) {
    const size_t comma = std::min(text.find(',', at), text.size());
    const std::string key = text.substr(at, comma - at);
    int frame = 0, used = 0;
    double factor = 0;
    if (std::sscanf(key.c_str(), "%d:%lf%n", &frame, &factor, &used) != 2 || used != static_cast<int>(key.size()))
      return edgetrack::Error{"", 0, "--exposure '" + text + "': expected FRAME:FACTOR[,FRAME:FACTOR...], not '" + key + "'"};
    if (frame < 0 || (!schedule.keys_.empty() && frame <= schedule.keys_.back().first))
      return edgetrack::Error{"", 0, "--exposure '" + text + "': frames must be 0 or more and increasing"};
    if (!(factor > 0 && factor <= kMaxFactor))
      return edgetrack::Error{"", 0, "--exposure '" + text + "': factors must be in (0, 16]"};
    schedule.keys_.emplace_back(frame, factor);
    at = comma + 1;
  }
  return schedule;
}

double ExposureSchedule::factor(int frame) const {
  if (keys_.empty()) return 1;
  if (frame <= keys_.front().first) return keys_.front().second;
  for (size_t i = 1; i < keys_.size(); ++i)
    if (frame <= keys_[i].first) {
      const auto& [f0, k0] = keys_[i - 1];
      const auto& [f1, k1] = keys_[i];
      return k0 + (k1 - k0) * (frame - f0) / (f1 - f0);
    }
  return keys_.back().second;
}

void apply_exposure(RgbImage& image, double factor) {
  for (uint8_t& v : image.rgb) v = static_cast<uint8_t>(std::min(255L, std::lround(v * factor)));
}

edgetrack::Result<RgbImage> jpeg_round_trip(const RgbImage& image, int quality) {
  cv::Mat rgb(image.height, image.width, CV_8UC3, const_cast<uint8_t*>(image.rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);  // JPEG's luma weights assume OpenCV's BGR order
  std::vector<uint8_t> encoded;
  if (!cv::imencode(".jpg", bgr, encoded, {cv::IMWRITE_JPEG_QUALITY, quality}))
    return edgetrack::Error{"", 0, "OpenCV could not encode a JPEG frame"};
  const cv::Mat decoded = cv::imdecode(encoded, cv::IMREAD_COLOR);
  if (decoded.empty() || decoded.cols != image.width || decoded.rows != image.height)
    return edgetrack::Error{"", 0, "OpenCV could not decode its own JPEG frame"};
  RgbImage out = make_image(image.width, image.height);
  cv::Mat out_rgb(out.height, out.width, CV_8UC3, out.rgb.data());
  cv::cvtColor(decoded, out_rgb, cv::COLOR_BGR2RGB);
  return out;
}

}  // namespace edgetrack_app
