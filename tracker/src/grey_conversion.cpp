// SPDX-License-Identifier: BSD-3-Clause
/// Row converters for each pixel layout, and the box loop of the grey step.
#include "edgetrack/grey_conversion.h"

#include <algorithm>
#include <cstring>

#include "real/vector_kernels.h"
#include "visp3/core/vpImageConvert.h"

namespace edgetrack {
namespace {

/// Rows of colour pixels of kBytes bytes, red at byte kRed, green at 1, blue at kBlue (a fourth
/// byte, alpha, is not read). The row loop is a vector kernel (real/vector_kernels.h): integer
/// sums, so every choice gives vpImageConvert::rgbToGrey's byte; a size_t index, since an
/// unsigned int one may wrap and keeps GCC from vectorising the interleaved loads.
template <int kBytes, int kRed, int kBlue>
void colour_rows(const uint8_t* in, unsigned int in_step, unsigned char* out, unsigned int out_step, int rows,
                 unsigned int count) {
  // The lambda's captures are copied to locals first: a byte store may alias the closure.
  vector_kernels::run([&]() __attribute__((always_inline)) {
    const uint8_t* const first_in = in;
    unsigned char* const first_out = out;
    const size_t pixels = count, in_bytes = in_step, out_bytes = out_step;
    const int row_count = rows;
    for (int r = 0; r < row_count; ++r) {
      const uint8_t* __restrict row = first_in + static_cast<size_t>(r) * in_bytes;
      unsigned char* __restrict grey = first_out + static_cast<size_t>(r) * out_bytes;
      for (size_t k = 0; k < pixels; ++k)
        grey[k] = vpImageConvert::rgbToGrey(row[kBytes * k + kRed], row[kBytes * k + 1], row[kBytes * k + kBlue]);
    }
  });
}

/// Rows of `count` pixels, from the first pixel to be converted of each, `rows` times, the rows
/// `in_stride` and `out_stride` bytes apart: the layout is looked at once per box.
void convert_rows(PixelLayout layout, const uint8_t* in, int in_stride, unsigned char* out, int out_stride, int rows,
                  unsigned int count) {
  const auto in_step = static_cast<unsigned int>(in_stride), out_step = static_cast<unsigned int>(out_stride);
  switch (layout) {
    case PixelLayout::kRgb565:
      vpImageConvert::RGB565ToGrey(in, in_step, out, out_step, static_cast<unsigned int>(rows), count);
      return;
    case PixelLayout::kRgb24: return colour_rows<3, 0, 2>(in, in_step, out, out_step, rows, count);
    case PixelLayout::kBgr24: return colour_rows<3, 2, 0>(in, in_step, out, out_step, rows, count);
    case PixelLayout::kRgba32: return colour_rows<4, 0, 2>(in, in_step, out, out_step, rows, count);
    case PixelLayout::kBgra32: return colour_rows<4, 2, 0>(in, in_step, out, out_step, rows, count);
    case PixelLayout::kGrey8:
    case PixelLayout::kNv21:
    case PixelLayout::kI420:
    case PixelLayout::kNv12:
    case PixelLayout::kYuv420_888:
      for (; rows > 0; --rows, in += in_step, out += out_step) std::memcpy(out, in, count);
      return;
  }
}

}  // namespace

unsigned int convert_to_grey(const FrameView& frame, const PixelBox& box, vpImage<unsigned char>& grey) {
  const int top = std::max(box.top, 0), left = std::max(box.left, 0);
  const int bottom = std::min(box.bottom, frame.height), right = std::min(box.right, frame.width);
  if (left >= right || top >= bottom) return 0;
  const unsigned int count = static_cast<unsigned int>(right - left);
  const int width = static_cast<int>(grey.getWidth());
  convert_rows(frame.layout, frame.row(top) + left * bytes_per_pixel(frame.layout), frame.row_bytes, grey[top] + left,
               width, bottom - top, count);
  return static_cast<unsigned int>(bottom - top) * count;
}

unsigned int BoxGreyScaler::convert(const FrameView& frame, vpImage<unsigned char>& grey) {
  // Only the rows the boxes reach carry spans: those are reset and summed, not the frame's.
  int first_row = frame.height, end_row = 0;
  unsigned int box_pixels = 0;
  for (PixelBox& box : boxes_) {
    box.top = std::max(box.top, 0);
    box.left = std::max(box.left, 0);
    box.bottom = std::min(box.bottom, frame.height);
    box.right = std::min(box.right, frame.width);
    if (box.left >= box.right || box.top >= box.bottom) continue;
    box_pixels += static_cast<unsigned int>(box.bottom - box.top) * static_cast<unsigned int>(box.right - box.left);
    first_row = std::min(first_row, box.top);
    end_row = std::max(end_row, box.bottom);
  }
  if (first_row >= end_row) return 0;
  left_.resize(static_cast<size_t>(frame.height));
  right_.resize(static_cast<size_t>(frame.height));
  std::fill(left_.begin() + first_row, left_.begin() + end_row, frame.width);
  std::fill(right_.begin() + first_row, right_.begin() + end_row, 0);
  int* const lefts = left_.data();
  int* const rights = right_.data();
  for (const PixelBox& box : boxes_) {
    const int left = box.left, right = box.right, bottom = box.bottom;  // not reloaded after each store
    if (left >= right) continue;
    for (int y = box.top; y < bottom; ++y) {
      lefts[y] = std::min(lefts[y], left);
      rights[y] = std::max(rights[y], right);
    }
  }
  unsigned int span_pixels = 0;
  for (int y = first_row; y < end_row; ++y)
    if (left_[y] < right_[y]) span_pixels += static_cast<unsigned int>(right_[y] - left_[y]);
  if (span_pixels >= box_pixels) {
    unsigned int converted = 0;
    for (const PixelBox& box : boxes_) converted += convert_to_grey(frame, box, grey);
    return converted;
  }
  for (int y = first_row; y < end_row; ++y)
    if (left_[y] < right_[y]) convert_to_grey(frame, PixelBox{y, left_[y], y + 1, right_[y]}, grey);
  return span_pixels;
}

bool grey_in_place(const FrameView& frame) {
  return bytes_per_pixel(frame.layout) == 1 && frame.row_bytes == frame.width;
}

}  // namespace edgetrack
