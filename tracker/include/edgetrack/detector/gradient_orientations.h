// SPDX-License-Identifier: BSD-3-Clause
/// Quantised gradient orientations of a grey image, as LINE-2D uses them (Hinterstoisser et al.,
/// "Gradient Response Maps for Real-Time Detection of Textureless Objects"): an integer Sobel
/// gradient, its direction modulo 180 degrees in 8 bins of 22.5 degrees (centred on 0, 22.5, ...), kept where it is strong
/// and where it dominates its 3x3 neighbourhood, each pixel a byte with one bit per bin; then the
/// bins spread over T x T pixels by a bitwise OR. Integers only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace edgetrack {

constexpr int kOrientationBins = 8;

/// One byte per pixel, row-major: bit b set when orientation bin b is present there.
struct OrientationImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> bits;
};

/// The bin (0..7) of the direction of (gx, gy) modulo 180 degrees: bin b covers 22.5 b +- 11.25
/// degrees, measured from +x towards +y (image y down). Centred bins put the gradients of
/// horizontal and vertical edges, the commonest on made objects, in the middle of a bin, where
/// noise does not move them to the next one. (0, 0) gives 0.
int orientation_bin(int32_t gx, int32_t gy);

/// What makes a pixel's orientation count.
struct OrientationParams {
  /// Sobel magnitude (|gx|, |gy| up to 4 * 255) below which a pixel has no orientation: 80 is an
  /// edge of about 20 grey levels, above the renderer's and a camera's noise (a few levels).
  int min_magnitude = 80;
  /// Of the 9 pixels of a 3x3 neighbourhood, at least this many strong ones must share the
  /// most frequent bin for the centre to take it (LINE-2D's noise rejection).
  int min_agreeing = 5;
};

/// Quantises `grey` (width x height, row-major) into `out` (resized; border pixels get none).
/// `scratch` holds the per-pixel bins between the two passes and is resized as needed.
void quantise_orientations(const uint8_t* grey, int width, int height, const OrientationParams& params,
                           std::vector<uint8_t>& scratch, OrientationImage& out);

/// out(x, y) = OR of in(x + dx, y + dy) over 0 <= dx, dy < t (inside the image): a template
/// feature at (x, y) then finds its orientation anywhere t pixels to the right and below.
/// `scratch` holds the row pass and is resized as needed.
void spread_orientations(const OrientationImage& in, int t, std::vector<uint8_t>& scratch, OrientationImage& out);

/// Averages factor x factor blocks of `grey` (rounded); `out` is (width / factor) x (height / factor).
void downscale_grey(const uint8_t* grey, int width, int height, int factor, std::vector<uint8_t>& out);

}  // namespace edgetrack
