// SPDX-License-Identifier: BSD-3-Clause
/// The grey step's conversions: a box of a frame, in any layout, into the grey image the moving
/// edges read, with vpImageConvert's rounding rule for the colour layouts (so RGB565 gives what
/// it always gave) and the Y plane as it is for NV21 and I420.
#pragma once

#include "edgetrack/frame_view.h"
#include "edgetrack/me_search_box.h"
#include "visp3/core/vpImage.h"

namespace edgetrack {

/// Converts rows [box.top, box.bottom) x columns [box.left, box.right) of `frame`, clipped to
/// the frame, into the same pixels of `grey` (of the frame's size); returns the pixels converted.
/// `frame` must have passed check_frame.
unsigned int convert_to_grey(const FrameView& frame, const PixelBox& box, vpImage<unsigned char>& grey);

/// Whether the frame's own bytes are the grey image, packed (grey8, or NV21/I420 whose Y rows
/// follow one another): the moving edges then read them in place, with no conversion at all.
bool grey_in_place(const FrameView& frame);

}  // namespace edgetrack
