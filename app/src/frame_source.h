// SPDX-License-Identifier: BSD-3-Clause
/// Where frames come from: a printf-style file pattern, a directory, a video file or a camera.
/// The one run-time interface of the application (the sources really are swapped at run time).
#pragma once

#include <memory>
#include <string>

#include "edgetrack/result.h"
#include "image_io.h"

namespace edgetrack_app {

struct Frame {
  int index = 0;     ///< frame number: the pattern's number, the number ending the file name, or the position
  std::string name;  ///< file name (or "video:N") for messages
  FramePixels pixels;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// Reads the next frame into `frame`: true when there was one, false at the end of the
  /// sequence, an Error naming the file when a frame cannot be read.
  virtual edgetrack::Result<bool> next(Frame& frame) = 0;
};

struct SourceOptions {
  std::string images;     ///< printf pattern ("seq/frame%04d.pgm"), directory, video file, or empty
  int first = -1;         ///< first frame number (pattern: default 0, or 1 when 0 is missing)
  int last = -1;          ///< last frame number, inclusive; -1: until the sequence ends
  int raw_width = 0;      ///< size of raw RGB565 frames (.rgb565 / .raw)
  int raw_height = 0;
  int camera_device = -1;  ///< >= 0: a live camera instead of `images`
};

/// Opens the source the options describe. Fails with a message naming the pattern or
/// directory when it holds no frame at all (an empty sequence).
edgetrack::Result<std::unique_ptr<FrameSource>> open_frame_source(const SourceOptions& options);

/// Reads one image file by its extension: PGM/PPM/PNM and raw RGB565 everywhere, the rest on the host.
edgetrack::Result<FramePixels> read_frame_file(const std::string& path, int raw_width, int raw_height);

/// The number a file name ends with, before its extension ("image0042.pgm" -> 42, as ViSP
/// numbers its sequences), or -1 when its stem does not end in digits (or in more than 9).
int number_in_name(const std::string& path);

/// Expands a printf pattern with one integer conversion (%d, %04d, ...) for `index`.
std::string expand_pattern(const std::string& pattern, int index);

}  // namespace edgetrack_app
