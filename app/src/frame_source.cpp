// SPDX-License-Identifier: BSD-3-Clause
/// Frame sources: numbered files, the image files of a directory in name order, video and cameras.
#include "frame_source.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "host_io.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

bool is_raw(const std::string& ext) { return ext == "rgb565" || ext == "raw"; }
bool is_netpbm(const std::string& ext) { return ext == "pgm" || ext == "ppm" || ext == "pnm"; }
bool is_image(const std::string& ext) {
  static const char* const kHostImages[] = {"png", "jpg", "jpeg", "bmp", "tif", "tiff", "webp"};
  if (is_raw(ext) || is_netpbm(ext)) return true;
  return std::find(std::begin(kHostImages), std::end(kHostImages), ext) != std::end(kHostImages);
}
bool is_video(const std::string& ext) {
  return ext == "mp4" || ext == "avi" || ext == "mkv" || ext == "mov" || ext == "mpg" || ext == "webm";
}

/// Whether anything is at `path`, or an Error saying why that cannot be known (a name too long,
/// a directory that may not be entered); never throws.
Result<bool> path_exists(const std::string& path) {
  std::error_code error;
  const bool found = std::filesystem::exists(path, error);
  if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory)
    return Error{path, 0, error.message()};
  return found;
}

/// Where the one integer conversion of a printf pattern is: [begin, end) of "%...d", or begin = npos.
bool find_conversion(const std::string& pattern, size_t& begin, size_t& end) {
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    size_t j = i + 1;
    while (j < pattern.size() && (std::isdigit(static_cast<unsigned char>(pattern[j])) || pattern[j] == '0')) ++j;
    if (j < pattern.size() && (pattern[j] == 'd' || pattern[j] == 'i' || pattern[j] == 'u')) {
      begin = i;
      end = j + 1;
      return true;
    }
    return false;
  }
  return false;
}

class PatternSource : public FrameSource {
 public:
  PatternSource(std::string pattern, int first, int last, int raw_width, int raw_height)
      : pattern_(std::move(pattern)), next_(first), last_(last), raw_width_(raw_width), raw_height_(raw_height) {}
  Result<bool> next(Frame& frame) override {
    if (last_ >= 0 && next_ > last_) return false;
    const std::string path = expand_pattern(pattern_, next_);
    auto exists = path_exists(path);
    if (!exists.ok()) return exists.error();
    if (!exists.value()) {
      if (last_ >= 0) return Error{path, 0, "missing frame (the sequence should run to " + std::to_string(last_) + ")"};
      warn_of_gap(path);
      return false;
    }
    auto image = read_frame_file(path, raw_width_, raw_height_);
    if (!image.ok()) return image.error();
    frame.index = next_++;
    frame.name = path;
    frame.pixels = std::move(image).value();
    return true;
  }

 private:
  /// The sequence ends at the first missing frame; a frame soon after it means a gap, which the
  /// run would otherwise pass over in silence.
  void warn_of_gap(const std::string& missing) const {
    constexpr int kGapProbe = 100;
    for (int k = next_ + 1; k <= next_ + kGapProbe; ++k) {
      const std::string later = expand_pattern(pattern_, k);
      auto found = path_exists(later);
      if (found.ok() && found.value()) {
        std::fprintf(stderr, "note: %s is missing but %s exists: the sequence stops at the gap "
                             "(give --last to require every frame)\n", missing.c_str(), later.c_str());
        return;
      }
    }
  }

  std::string pattern_;
  int next_;
  int last_;
  int raw_width_, raw_height_;
};

/// The image files of a directory (or one file), each with its frame number.
struct ListedFrame {
  std::string path;
  int number = 0;
};

class ListSource : public FrameSource {
 public:
  ListSource(std::vector<ListedFrame> files, int first, int last, int raw_width, int raw_height)
      : files_(std::move(files)), first_(first), last_(last), raw_width_(raw_width), raw_height_(raw_height) {}
  Result<bool> next(Frame& frame) override {
    while (next_ < files_.size() && files_[next_].number < first_) ++next_;
    if (next_ >= files_.size() || (last_ >= 0 && files_[next_].number > last_)) return false;
    const ListedFrame& file = files_[next_++];
    auto image = read_frame_file(file.path, raw_width_, raw_height_);
    if (!image.ok()) return image.error();
    frame.index = file.number;
    frame.name = file.path;
    frame.pixels = std::move(image).value();
    return true;
  }

 private:
  std::vector<ListedFrame> files_;
  size_t next_ = 0;
  int first_;
  int last_;
  int raw_width_, raw_height_;
};

/// The image files of `dir` in name order, numbered by the number their names end with when
/// every name has one and no two share it (image0000.pgm ... as ViSP writes them), else by
/// their position in that order.
Result<std::vector<ListedFrame>> list_directory(const std::string& dir) {
  std::error_code error;
  std::vector<std::string> paths;
  std::filesystem::directory_iterator it(dir, error), end;
  for (; !error && it != end; it.increment(error)) {
    std::error_code type_error;
    if (it->is_regular_file(type_error) && !type_error && is_image(extension_of(it->path().string())))
      paths.push_back(it->path().string());
  }
  if (error) return Error{dir, 0, "cannot list the directory: " + error.message()};
  std::sort(paths.begin(), paths.end());
  std::vector<ListedFrame> files;
  bool numbered = true;
  for (size_t i = 0; i < paths.size(); ++i) {
    const int number = number_in_name(paths[i]);
    numbered = numbered && number >= 0 && (files.empty() || number > files.back().number);
    files.push_back({paths[i], number});
  }
  if (!numbered)
    for (size_t i = 0; i < files.size(); ++i) files[i].number = static_cast<int>(i);
  return files;
}

class VideoSource : public FrameSource {
 public:
  VideoSource(std::unique_ptr<VideoInput> input, std::string name, int first, int last)
      : input_(std::move(input)), name_(std::move(name)), first_(first < 0 ? 0 : first), last_(last) {}
  Result<bool> next(Frame& frame) override {
    for (;;) {
      if (last_ >= 0 && position_ > last_) return false;
      if (!input_->read(image_)) return false;
      frame.index = position_++;
      if (frame.index >= first_) break;
    }
    frame.name = name_ + ":" + std::to_string(frame.index);
    frame.pixels = frame_pixels(std::move(image_));
    return true;
  }

 private:
  std::unique_ptr<VideoInput> input_;
  RgbImage image_;
  std::string name_;
  int first_, last_;
  int position_ = 0;
};

/// A source whose first frame was read ahead.
class PeekedSource : public FrameSource {
 public:
  PeekedSource(std::unique_ptr<FrameSource> source, Frame first) : source_(std::move(source)), first_(std::move(first)) {}
  Result<bool> next(Frame& frame) override {
    if (has_first_) {
      frame = std::move(first_);
      has_first_ = false;
      return true;
    }
    return source_->next(frame);
  }

 private:
  std::unique_ptr<FrameSource> source_;
  Frame first_;
  bool has_first_ = true;
};

/// Wraps a source so that an empty sequence is an error, reading the first frame ahead.
Result<std::unique_ptr<FrameSource>> non_empty(std::unique_ptr<FrameSource> source, const std::string& what) {
  Frame first;
  auto got = source->next(first);
  if (!got.ok()) return got.error();
  if (!got.value()) return Error{what, 0, "empty sequence: no frame found"};
  return std::unique_ptr<FrameSource>(new PeekedSource(std::move(source), std::move(first)));
}

}  // namespace

int number_in_name(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  size_t digits = 0;
  while (digits < stem.size() && std::isdigit(static_cast<unsigned char>(stem[stem.size() - 1 - digits]))) ++digits;
  if (digits == 0 || digits > 9) return -1;
  return std::stoi(stem.substr(stem.size() - digits));
}

std::string expand_pattern(const std::string& pattern, int index) {
  size_t begin = 0, end = 0;
  if (!find_conversion(pattern, begin, end)) return pattern;
  const std::string spec = pattern.substr(begin, end - begin - 1) + "d";
  char number[64];
  std::snprintf(number, sizeof number, spec.c_str(), index);
  return pattern.substr(0, begin) + number + pattern.substr(end);
}

Result<FramePixels> read_frame_file(const std::string& path, int raw_width, int raw_height) {
  const std::string ext = extension_of(path);
  if (is_raw(ext)) return read_raw_rgb565(path, raw_width, raw_height);
  if (is_netpbm(ext)) return read_netpbm_pixels(path);
  auto image = read_image_any(path);
  if (!image.ok()) return image.error();
  return frame_pixels(std::move(image).value());
}

Result<std::unique_ptr<FrameSource>> open_frame_source(const SourceOptions& options) {
  if (options.camera_device >= 0) {
    auto camera = open_camera_device(options.camera_device);
    if (!camera.ok()) return camera.error();
    return non_empty(std::unique_ptr<FrameSource>(new VideoSource(std::move(camera).value(),
                                                                  "camera " + std::to_string(options.camera_device),
                                                                  options.first, options.last)),
                     "camera " + std::to_string(options.camera_device));
  }
  if (options.first >= 0 && options.last >= 0 && options.first > options.last)
    return Error{"", 0, "--first " + std::to_string(options.first) + " is after --last " + std::to_string(options.last) +
                            ": no frame to track"};
  const std::string& images = options.images;
  if (images.empty()) return Error{"", 0, "no frames given (--images PATTERN|DIR|VIDEO or --camera-device N)"};
  size_t begin = 0, end = 0;
  if (find_conversion(images, begin, end)) {
    int first = options.first;
    if (first < 0) {
      auto zero = path_exists(expand_pattern(images, 0));
      if (!zero.ok()) return zero.error();
      first = zero.value() ? 0 : 1;
    }
    return non_empty(std::unique_ptr<FrameSource>(
                         new PatternSource(images, first, options.last, options.raw_width, options.raw_height)),
                     images);
  }
  auto exists = path_exists(images);
  if (!exists.ok()) return exists.error();
  if (!exists.value()) return Error{images, 0, "no such file or directory"};
  std::error_code error;
  if (std::filesystem::is_directory(images, error)) {
    auto files = list_directory(images);
    if (!files.ok()) return files.error();
    return non_empty(std::unique_ptr<FrameSource>(new ListSource(std::move(files).value(), options.first, options.last,
                                                                 options.raw_width, options.raw_height)),
                     images);
  }
  if (is_video(extension_of(images))) {
    auto video = open_video_file(images);
    if (!video.ok()) return video.error();
    return non_empty(std::unique_ptr<FrameSource>(new VideoSource(std::move(video).value(), images, options.first, options.last)),
                     images);
  }
  // A single image file is a sequence of one frame.
  return non_empty(std::unique_ptr<FrameSource>(
                       new ListSource({{images, 0}}, 0, -1, options.raw_width, options.raw_height)),
                   images);
}

}  // namespace edgetrack_app
