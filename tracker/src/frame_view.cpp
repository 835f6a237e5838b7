// SPDX-License-Identifier: BSD-3-Clause
/// The layouts' names and sizes, and the one check of a frame view.
#include "edgetrack/frame_view.h"

#include <string>

namespace edgetrack {

const char* layout_name(PixelLayout layout) {
  switch (layout) {
    case PixelLayout::kRgb565: return "RGB565";
    case PixelLayout::kGrey8: return "grey8";
    case PixelLayout::kRgb24: return "RGB24";
    case PixelLayout::kBgr24: return "BGR24";
    case PixelLayout::kNv21: return "NV21";
    case PixelLayout::kI420: return "I420";
    case PixelLayout::kNv12: return "NV12";
    case PixelLayout::kYuv420_888: return "YUV_420_888";
    case PixelLayout::kRgba32: return "RGBA32";
    case PixelLayout::kBgra32: return "BGRA32";
  }
  return "?";
}

int bytes_per_pixel(PixelLayout layout) {
  switch (layout) {
    case PixelLayout::kRgb565: return 2;
    case PixelLayout::kRgb24:
    case PixelLayout::kBgr24: return 3;
    case PixelLayout::kRgba32:
    case PixelLayout::kBgra32: return 4;
    case PixelLayout::kGrey8:
    case PixelLayout::kNv21:
    case PixelLayout::kI420:
    case PixelLayout::kNv12:
    case PixelLayout::kYuv420_888: return 1;
  }
  return 1;
}

FrameView packed_frame(const void* pixels, int width, int height, PixelLayout layout) {
  return FrameView{pixels, width, height, width * bytes_per_pixel(layout), layout};
}

namespace {

/// The start of every message (built on failure only: a good frame allocates nothing).
std::string frame_named(const FrameView& frame) { return std::string("the ") + layout_name(frame.layout) + " frame"; }

}  // namespace

std::optional<Error> check_frame(const FrameView& frame, int width, int height) {
  if (layout_name(frame.layout)[0] == '?')
    return Error{"", 0, "the frame's pixel layout (" + std::to_string(static_cast<int>(frame.layout)) +
                            ") is none of PixelLayout's values"};
  if (frame.pixels == nullptr) return Error{"", 0, frame_named(frame) + " has no pixels (a null pointer)"};
  if (frame.width != width || frame.height != height)
    return Error{"", 0, frame_named(frame) + " is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                            ", the camera's images are " + std::to_string(width) + "x" + std::to_string(height)};
  const long long row = static_cast<long long>(width) * bytes_per_pixel(frame.layout);
  if (frame.row_bytes < row)
    return Error{"", 0, frame_named(frame) + "'s rows are " + std::to_string(frame.row_bytes) + " bytes apart, less than the " +
                            std::to_string(row) + " bytes of a row of pixels"};
  if (frame.layout == PixelLayout::kRgb565 &&
      ((reinterpret_cast<std::uintptr_t>(frame.pixels) | static_cast<std::uintptr_t>(frame.row_bytes)) & 1u) != 0)
    return Error{"", 0, frame_named(frame) + "'s rows do not start on 2-byte boundaries (odd pointer or row stride)"};
  return std::nullopt;
}

Result<FrameView> yuv_420_888_frame(const Yuv420Planes& planes, int width, int height) {
  const FrameView y_plane{planes.y, width, height, planes.y_row_bytes, PixelLayout::kYuv420_888};
  const auto refused = [&](const std::string& why) { return Result<FrameView>(Error{"", 0, frame_named(y_plane) + why}); };
  // The Y plane is then checked as any frame's, by Tracker::track (check_frame).
  if (planes.y == nullptr || planes.u == nullptr || planes.v == nullptr)
    return refused(" lacks a plane (a null Y, U or V pointer)");
  if (planes.uv_pixel_stride != 1 && planes.uv_pixel_stride != 2)
    return refused("'s chroma pixel stride is " + std::to_string(planes.uv_pixel_stride) +
                   ", not 1 (planar) or 2 (interleaved)");
  // The last chroma sample of a row is its first byte plus (samples - 1) pixel strides.
  const long long chroma_row = static_cast<long long>((width + 1) / 2 - 1) * planes.uv_pixel_stride + 1;
  if (planes.uv_row_bytes < chroma_row)
    return refused("'s chroma rows are " + std::to_string(planes.uv_row_bytes) + " bytes apart, less than the " +
                   std::to_string(chroma_row) + " bytes of a row of chroma samples");
  return y_plane;
}

}  // namespace edgetrack
