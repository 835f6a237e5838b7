// SPDX-License-Identifier: BSD-3-Clause
/// Frame I/O through OpenCV on the host: any image format, video files, cameras, PNG and video output.
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "host_io.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

RgbImage from_bgr(const cv::Mat& bgr) {
  cv::Mat rgb;
  if (bgr.channels() == 1)
    cv::cvtColor(bgr, rgb, cv::COLOR_GRAY2RGB);
  else if (bgr.channels() == 4)
    cv::cvtColor(bgr, rgb, cv::COLOR_BGRA2RGB);
  else
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  if (rgb.depth() != CV_8U) rgb.convertTo(rgb, CV_8U, rgb.depth() == CV_16U ? 1.0 / 257 : 1.0);
  RgbImage image = make_image(rgb.cols, rgb.rows);
  for (int y = 0; y < rgb.rows; ++y) std::copy(rgb.ptr<uint8_t>(y), rgb.ptr<uint8_t>(y) + rgb.cols * 3, image.pixel(0, y));
  return image;
}

cv::Mat to_bgr(const RgbImage& image) {
  cv::Mat rgb(image.height, image.width, CV_8UC3, const_cast<uint8_t*>(image.rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

class CaptureInput : public VideoInput {
 public:
  explicit CaptureInput(cv::VideoCapture capture) : capture_(std::move(capture)) {}
  bool read(RgbImage& frame) override {
    cv::Mat bgr;
    if (!capture_.read(bgr) || bgr.empty()) return false;
    frame = from_bgr(bgr);
    return true;
  }

 private:
  cv::VideoCapture capture_;
};

class WriterOutput : public VideoOutput {
 public:
  explicit WriterOutput(cv::VideoWriter writer) : writer_(std::move(writer)) {}
  bool write(const RgbImage& frame) override {
    writer_.write(to_bgr(frame));
    return true;
  }

 private:
  cv::VideoWriter writer_;
};

}  // namespace

bool host_io_available() { return true; }

Result<RgbImage> read_image_any(const std::string& path) {
  cv::Mat bgr;
  try {
    bgr = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    return Error{path, 0, std::string("unreadable image: ") + e.what()};
  }
  if (bgr.empty()) return Error{path, 0, "unreadable image (not a format OpenCV reads)"};
  return from_bgr(bgr);
}

Result<bool> write_image(const std::string& path, const RgbImage& image) {
  const std::string ext = extension_of(path);
  if (ext == "ppm" || ext == "pnm") return write_ppm(path, image);
  bool ok = false;
  try {
    ok = cv::imwrite(path, to_bgr(image));
  } catch (const cv::Exception& e) {
    return Error{path, 0, std::string("cannot write the image: ") + e.what()};
  }
  if (!ok) return Error{path, 0, "cannot write the image"};
  return true;
}

Result<std::unique_ptr<VideoInput>> open_video_file(const std::string& path) {
  cv::VideoCapture capture(path);
  if (!capture.isOpened()) return Error{path, 0, "unreadable video (OpenCV cannot open it)"};
  return std::unique_ptr<VideoInput>(new CaptureInput(std::move(capture)));
}

Result<std::unique_ptr<VideoInput>> open_camera_device(int device) {
  cv::VideoCapture capture(device);
  if (!capture.isOpened()) return Error{"camera " + std::to_string(device), 0, "no such camera, or it cannot be opened"};
  return std::unique_ptr<VideoInput>(new CaptureInput(std::move(capture)));
}

Result<std::unique_ptr<VideoOutput>> open_video_output(const std::string& path, int width, int height, double fps) {
  cv::VideoWriter writer(path, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps, cv::Size(width, height));
  if (!writer.isOpened()) return Error{path, 0, "cannot open the video for writing"};
  return std::unique_ptr<VideoOutput>(new WriterOutput(std::move(writer)));
}

}  // namespace edgetrack_app
