// SPDX-License-Identifier: BSD-3-Clause
/// Row converters for each pixel layout, and the box loop of the grey step.
#include "edgetrack/grey_conversion.h"

#include <algorithm>
#include <cstring>

#include "visp3/core/vpImageConvert.h"

namespace edgetrack {
namespace {

/// `count` pixels of one row, from its first pixel to be converted.
void convert_row(PixelLayout layout, const uint8_t* in, unsigned char* out, unsigned int count) {
  switch (layout) {
    case PixelLayout::kRgb565:
      vpImageConvert::RGB565ToGrey(reinterpret_cast<const uint16_t*>(in), out, count);
      return;
    case PixelLayout::kRgb24:
      for (; count > 0; --count, in += 3) *out++ = vpImageConvert::rgbToGrey(in[0], in[1], in[2]);
      return;
    case PixelLayout::kBgr24:
      for (; count > 0; --count, in += 3) *out++ = vpImageConvert::rgbToGrey(in[2], in[1], in[0]);
      return;
    case PixelLayout::kGrey8:
    case PixelLayout::kNv21:
    case PixelLayout::kI420:
      std::memcpy(out, in, count);
      return;
  }
}

}  // namespace

unsigned int convert_to_grey(const FrameView& frame, const PixelBox& box, vpImage<unsigned char>& grey) {
  const int top = std::max(box.top, 0), left = std::max(box.left, 0);
  const int bottom = std::min(box.bottom, frame.height), right = std::min(box.right, frame.width);
  if (left >= right || top >= bottom) return 0;
  const unsigned int count = static_cast<unsigned int>(right - left);
  const int step = bytes_per_pixel(frame.layout);
  for (int y = top; y < bottom; ++y) convert_row(frame.layout, frame.row(y) + left * step, grey[y] + left, count);
  return static_cast<unsigned int>(bottom - top) * count;
}

unsigned int BoxGreyScaler::convert(const FrameView& frame, vpImage<unsigned char>& grey) {
  const size_t rows = static_cast<size_t>(frame.height);
  left_.assign(rows, frame.width);
  right_.assign(rows, 0);
  unsigned int box_pixels = 0;
  for (PixelBox& box : boxes_) {
    box.top = std::max(box.top, 0);
    box.left = std::max(box.left, 0);
    box.bottom = std::min(box.bottom, frame.height);
    box.right = std::min(box.right, frame.width);
    if (box.left >= box.right || box.top >= box.bottom) continue;
    box_pixels += static_cast<unsigned int>(box.bottom - box.top) * static_cast<unsigned int>(box.right - box.left);
    for (int y = box.top; y < box.bottom; ++y) {
      left_[y] = std::min(left_[y], box.left);
      right_[y] = std::max(right_[y], box.right);
    }
  }
  unsigned int span_pixels = 0;
  for (size_t y = 0; y < rows; ++y)
    if (left_[y] < right_[y]) span_pixels += static_cast<unsigned int>(right_[y] - left_[y]);
  if (span_pixels >= box_pixels) {
    unsigned int converted = 0;
    for (const PixelBox& box : boxes_) converted += convert_to_grey(frame, box, grey);
    return converted;
  }
  for (int y = 0; y < frame.height; ++y)
    if (left_[y] < right_[y]) convert_to_grey(frame, PixelBox{y, left_[y], y + 1, right_[y]}, grey);
  return span_pixels;
}

bool grey_in_place(const FrameView& frame) {
  return bytes_per_pixel(frame.layout) == 1 && frame.row_bytes == frame.width;
}

}  // namespace edgetrack
