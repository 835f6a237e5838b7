// SPDX-License-Identifier: BSD-3-Clause
/// numpy arrays as camera frames, read in place: the shape and dtype each layout comes in, the
/// row stride taken from the array, the pixels of a row required to follow one another.
#include <climits>
#include <string>

#include "bindings.h"

namespace edgetrack_python {

using edgetrack::PixelLayout;

namespace {

/// How a layout's frames come as arrays: uint8 or uint16 items, 2 or 3 axes, the channels of
/// the third axis, and whether the rows hold a YUV 4:2:0 frame ((3H/2) x W: the Y plane and the
/// chroma below it).
struct ArrayShape {
  bool uint16 = false;
  int channels = 1;  ///< 1: an H x W array; 3 or 4: H x W x channels
  bool yuv420 = false;
};

ArrayShape shape_of(PixelLayout layout) {
  switch (layout) {
    case PixelLayout::kRgb565: return {true, 1, false};
    case PixelLayout::kRgb24:
    case PixelLayout::kBgr24: return {false, 3, false};
    case PixelLayout::kRgba32:
    case PixelLayout::kBgra32: return {false, 4, false};
    case PixelLayout::kNv21:
    case PixelLayout::kNv12:
    case PixelLayout::kI420: return {false, 1, true};
    case PixelLayout::kGrey8:
    case PixelLayout::kYuv420_888: break;  // three separate planes: not one array (Python passes its Y plane as GREY8)
  }
  return {false, 1, false};
}

std::string expected_shape(const ArrayShape& shape) {
  const std::string type = shape.uint16 ? "uint16" : "uint8";
  if (shape.yuv420) return "a " + type + " array of (3H/2) x W (the Y plane's H rows, then the chroma)";
  if (shape.channels == 1) return "a " + type + " array of H x W";
  return "a " + type + " array of H x W x " + std::to_string(shape.channels);
}

/// Whether the array holds unsigned integers of `bytes` bytes in the machine's byte order.
bool native_unsigned(const py::buffer_info& info, py::ssize_t bytes) {
  const std::string& f = info.format;
  const char kind = bytes == 1 ? 'B' : 'H';
  if (info.itemsize != bytes || f.empty() || f.back() != kind || f.size() > 2) return false;
  if (f.size() == 1 || bytes == 1) return true;  // a byte has no order
  const char native = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? '<' : '>';
  return f[0] == '=' || f[0] == '@' || f[0] == native;
}

}  // namespace

std::string described(const py::array& array) {
  return std::string(py::str(array.dtype())) + " array of shape " + std::string(py::str(py::tuple(array.attr("shape"))));
}

edgetrack::FrameView frame_view_of(const py::array& array, PixelLayout layout) {
  const char* const name = edgetrack::layout_name(layout);
  if (name[0] == '?') raise("the frame's layout is none of edgetrack.Layout's values");
  const ArrayShape want = shape_of(layout);
  const py::buffer_info info = array.request();
  const auto refuse = [&](const std::string& why) {
    raise(std::string("the ") + name + " frame: " + why + " (" + expected_shape(want) + " expected, got a " + described(array) + ")");
  };
  if (!native_unsigned(info, want.uint16 ? 2 : 1)) refuse("wrong dtype");
  if (info.ndim != (want.channels == 1 ? 2 : 3) || (want.channels > 1 && info.shape[2] != want.channels))
    refuse("wrong shape");
  if (info.shape[0] == 0 || info.shape[1] == 0) refuse("an empty frame");
  const py::ssize_t pixel = want.channels * info.itemsize;
  if (info.ndim == 3 && info.strides[2] != 1) refuse("the channels of a pixel are not next to one another");
  if (info.strides[1] != pixel)
    refuse("the pixels of a row are not next to one another (column stride " + std::to_string(info.strides[1]) +
           " bytes, not " + std::to_string(pixel) + ")");
  if (info.strides[0] <= 0 || info.strides[0] > INT_MAX)
    refuse("row stride " + std::to_string(info.strides[0]) + " bytes (rows must go forward in memory, under 2 GiB apart)");
  py::ssize_t rows = info.shape[0];
  if (want.yuv420) {
    if (rows % 3 != 0) refuse("the row count is not 3H/2 for an even H");
    rows = rows / 3 * 2;
  }
  if (rows > INT_MAX || info.shape[1] > INT_MAX) refuse("too large");
  return edgetrack::FrameView{info.ptr, static_cast<int>(info.shape[1]), static_cast<int>(rows),
                              static_cast<int>(info.strides[0]), layout};
}

}  // namespace edgetrack_python
