// SPDX-License-Identifier: BSD-3-Clause
/// A camera frame as a device delivers it, read in place by the tracker: a pointer, a size, a
/// row stride in bytes and a pixel layout. Nothing is copied; the grey step converts only the
/// pixels the moving edges read, straight from the layout (tracker.h, grey_conversion.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "edgetrack/result.h"

namespace edgetrack {

/// The pixel layouts of device cameras. The YUV layouts are read through their Y plane only
/// (the grey image itself); their chroma planes, wherever they lie, are never touched.
enum class PixelLayout {
  kRgb565,  ///< 16-bit pixels in native byte order, red in the top 5 bits (the paper's handheld)
  kGrey8,   ///< one byte per pixel
  kRgb24,   ///< three bytes per pixel: red, green, blue
  kBgr24,   ///< three bytes per pixel: blue, green, red (OpenCV's order)
  kNv21,    ///< Android's camera default: the Y plane, then interleaved V/U at half resolution
  kI420,    ///< YUV420 planar: the Y plane, then the U and V planes at half resolution
  kNv12,    ///< the Y plane, then interleaved U/V at half resolution (NV21's chroma order swapped)
  kYuv420_888,  ///< Android's YUV_420_888: three planes, each with its row stride (yuv_420_888_frame)
  kRgba32,  ///< four bytes per pixel: red, green, blue, then alpha (never read)
  kBgra32   ///< four bytes per pixel: blue, green, red, then alpha (OpenCV's BGRA; alpha never read)
};

/// "RGB565", "grey8", "RGB24", "BGR24", "NV21", "I420", "NV12", "YUV_420_888", "RGBA32", "BGRA32".
const char* layout_name(PixelLayout layout);
/// Bytes per pixel of the first plane (the Y plane for the YUV layouts).
int bytes_per_pixel(PixelLayout layout);

/// One frame, borrowed: it must stay alive and unchanged during Tracker::track.
struct FrameView {
  const void* pixels = nullptr;  ///< row 0, column 0 (for NV21 and I420: of the Y plane)
  int width = 0;
  int height = 0;
  int row_bytes = 0;  ///< from one row to the next (of the Y plane), at least width * bytes_per_pixel
  PixelLayout layout = PixelLayout::kRgb565;

  /// The first byte of row `y`.
  const uint8_t* row(int y) const { return static_cast<const uint8_t*>(pixels) + static_cast<std::ptrdiff_t>(y) * row_bytes; }
};

/// A frame whose rows follow one another without padding.
FrameView packed_frame(const void* pixels, int width, int height, PixelLayout layout);

/// Android's YUV_420_888 as Camera2's ImageReader and CameraX's ImageAnalysis hand it: for each
/// plane of Image.getPlanes(), its buffer, row stride and pixel stride (the Y plane's is 1).
struct Yuv420Planes {
  const void* y = nullptr;
  int y_row_bytes = 0;
  const void* u = nullptr;
  const void* v = nullptr;
  int uv_row_bytes = 0;     ///< the U and V planes' row stride (Android gives both the same)
  int uv_pixel_stride = 0;  ///< 1: U and V planar (I420-like); 2: interleaved (NV12/NV21-like)
};

/// The view of a YUV_420_888 frame: its Y plane, read in place. Fails (nothing is read) when
/// Android's promises do not hold: no plane, a chroma pixel stride other than 1 or 2, chroma
/// rows shorter than a row of samples. The Y plane is checked by Tracker::track as any frame.
Result<FrameView> yuv_420_888_frame(const Yuv420Planes& planes, int width, int height);

/// Why `frame` cannot be tracked by a camera of width x height pixels, or nothing: a layout
/// that is none of PixelLayout's values, no pixels,
/// a size that is not the camera's, rows shorter than a row of pixels, RGB565 rows not on
/// 2-byte boundaries.
std::optional<Error> check_frame(const FrameView& frame, int width, int height);

}  // namespace edgetrack
