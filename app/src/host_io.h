// SPDX-License-Identifier: BSD-3-Clause
/// What the host build adds to frame I/O through OpenCV: reading any image format, video files
/// and cameras, writing PNG and video. In the host build `edgetrack` reaches them through the
/// host extras plugin (host_extras.h); the ARM build links host_none.cpp instead, whose
/// functions say that the format needs the host build.
#pragma once

#include <memory>
#include <string>

#include "edgetrack/result.h"
#include "image_io.h"

namespace edgetrack_app {

/// True when this build reads and writes through OpenCV.
bool host_io_available();

/// Reads any image OpenCV reads (PNG, JPEG, BMP, TIFF, ...).
edgetrack::Result<RgbImage> read_image_any(const std::string& path);
/// Writes an image in the format its extension names (PNG on the host; PPM everywhere).
edgetrack::Result<bool> write_image(const std::string& path, const RgbImage& image);

/// A video file or a camera, read frame by frame.
class VideoInput {
 public:
  virtual ~VideoInput() = default;
  /// The next frame; false at the end.
  virtual bool read(RgbImage& frame) = 0;
};
edgetrack::Result<std::unique_ptr<VideoInput>> open_video_file(const std::string& path);
edgetrack::Result<std::unique_ptr<VideoInput>> open_camera_device(int device);

/// A video file being written (MPEG-4 part 2 in an .mp4, .avi, .mkv or .mov container), under
/// `<stem>.partial.<ext>` until close() renames it: a run that fails leaves no file under the
/// name of a complete video.
class VideoOutput {
 public:
  virtual ~VideoOutput() = default;
  virtual bool write(const RgbImage& frame) = 0;
  /// Finishes the file and gives it its name.
  virtual edgetrack::Result<bool> close() = 0;
};
edgetrack::Result<std::unique_ptr<VideoOutput>> open_video_output(const std::string& path, int width, int height,
                                                                  double fps);

}  // namespace edgetrack_app
