// SPDX-License-Identifier: BSD-3-Clause
/// The grey step's conversions: a box of a frame, in any layout, into the grey image the moving
/// edges read, with vpImageConvert's rounding rule for the colour layouts (so RGB565 gives what
/// it always gave) and the Y plane as it is for NV21 and I420.
#pragma once

#include <vector>

#include "edgetrack/frame_view.h"
#include "edgetrack/me_search_box.h"
#include "visp3/core/vpImage.h"

namespace edgetrack {

/// Converts rows [box.top, box.bottom) x columns [box.left, box.right) of `frame`, clipped to
/// the frame, into the same pixels of `grey` (of the frame's size); returns the pixels converted.
/// `frame` must have passed check_frame.
unsigned int convert_to_grey(const FrameView& frame, const PixelBox& box, vpImage<unsigned char>& grey);

/// The grey step on demand: the read boxes of a frame's control points, converted so that
/// overlapping boxes cost little. Row by row, the span from the leftmost to the rightmost box
/// pixel is converted when those spans hold fewer pixels than the boxes do together (the boxes
/// of points a few pixels apart overlap, at ViSP's sample steps several times over), else each
/// box is, as before. Either way every box pixel is converted, by the same rule.
class BoxGreyScaler {
 public:
  void clear() { boxes_.clear(); }
  /// Room for `boxes` boxes on frames of `rows` rows: convert then allocates nothing within them.
  void reserve(size_t boxes, int rows) {
    boxes_.reserve(boxes);
    left_.reserve(static_cast<size_t>(rows));
    right_.reserve(static_cast<size_t>(rows));
  }
  void add(const PixelBox& box) { boxes_.push_back(box); }
  /// Converts the boxes added since clear(), clipped to `frame` (which must have passed
  /// check_frame), into `grey`; returns the pixels converted.
  unsigned int convert(const FrameView& frame, vpImage<unsigned char>& grey);

 private:
  std::vector<PixelBox> boxes_;
  std::vector<int> left_, right_;  ///< per frame row: the boxes' span on it, empty when left >= right
};

/// Whether the frame's own bytes are the grey image, packed (grey8, or NV21/I420 whose Y rows
/// follow one another): the moving edges then read them in place, with no conversion at all.
bool grey_in_place(const FrameView& frame);

}  // namespace edgetrack
