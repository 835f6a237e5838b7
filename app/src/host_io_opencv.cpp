// SPDX-License-Identifier: BSD-3-Clause
/// Frame I/O through OpenCV on the host: any image format, video files, cameras, PNG and video output.
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

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

/// The frames a video file holds, -1 when it cannot be read. FFmpeg names on stderr what it
/// finds wrong in the file; the caller's one line says it instead.
long long frames_in(const std::string& path) {
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  const int null = open("/dev/null", O_WRONLY);
  if (saved >= 0 && null >= 0) dup2(null, STDERR_FILENO);
  cv::VideoCapture video(path, cv::CAP_FFMPEG);
  const long long frames = video.isOpened() ? static_cast<long long>(video.get(cv::CAP_PROP_FRAME_COUNT)) : -1;
  video.release();
  if (saved >= 0 && null >= 0) dup2(saved, STDERR_FILENO);
  if (null >= 0) close(null);
  if (saved >= 0) close(saved);
  return frames;
}

class WriterOutput : public VideoOutput {
 public:
  WriterOutput(cv::VideoWriter writer, std::string partial, std::string path)
      : writer_(std::move(writer)), partial_(std::move(partial)), path_(std::move(path)) {}
  bool write(const RgbImage& frame) override {
    writer_.write(to_bgr(frame));
    ++frames_;
    return writer_.isOpened();
  }
  Result<bool> close() override {
    writer_.release();
    // cv::VideoWriter::write reports no failure: the file, read back, must hold every frame
    // (a disk full or a file-size limit leaves it short or without its index).
    const long long held = frames_in(partial_);
    if (held != frames_)
      return Error{path_, 0, "the video was not written whole (" + (held < 0 ? std::string("unreadable") :
                             std::to_string(held) + " of " + std::to_string(frames_) + " frames") + " in " + partial_ +
                             "): is the disk full or the file size limited?"};
    if (std::rename(partial_.c_str(), path_.c_str()) != 0)
      return Error{path_, 0, "cannot rename " + partial_ + " to it"};
    return true;
  }

 private:
  cv::VideoWriter writer_;
  std::string partial_, path_;
  long long frames_ = 0;
};

/// OpenCV reports on stderr what its backends try and fail; our messages say what failed, once.
void silence_opencv() {
  static const bool silenced = [] {
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    return true;
  }();
  (void)silenced;
}

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
  silence_opencv();
  cv::VideoCapture capture(path);
  if (!capture.isOpened()) return Error{path, 0, "unreadable video (OpenCV cannot open it)"};
  return std::unique_ptr<VideoInput>(new CaptureInput(std::move(capture)));
}

Result<std::unique_ptr<VideoInput>> open_camera_device(int device) {
  silence_opencv();
  cv::VideoCapture capture(device);
  if (!capture.isOpened()) return Error{"camera " + std::to_string(device), 0, "no such camera, or it cannot be opened"};
  return std::unique_ptr<VideoInput>(new CaptureInput(std::move(capture)));
}

Result<std::unique_ptr<VideoOutput>> open_video_output(const std::string& path, int width, int height, double fps) {
  silence_opencv();
  const std::string ext = extension_of(path);
  if (ext != "mp4" && ext != "avi" && ext != "mkv" && ext != "mov")
    return Error{path, 0, "a video is written as .mp4, .avi, .mkv or .mov, not '." + ext + "'"};
  const std::string partial = path.substr(0, path.size() - ext.size()) + "partial." + ext;
  cv::VideoWriter writer;
  try {
    writer.open(partial, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps, cv::Size(width, height));
  } catch (const cv::Exception& e) {
    return Error{path, 0, std::string("cannot open the video for writing: ") + e.what()};
  }
  if (!writer.isOpened()) return Error{path, 0, "cannot open the video for writing (as " + partial + ")"};
  return std::unique_ptr<VideoOutput>(new WriterOutput(std::move(writer), partial, path));
}

}  // namespace edgetrack_app
