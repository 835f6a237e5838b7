// SPDX-License-Identifier: BSD-3-Clause
/// Frames as the application handles them: the pixels of a frame file in the layout the file
/// holds (the tracker reads them in place), 8-bit RGB images for drawing, our own PGM/PPM
/// reader and writer, raw RGB565 files, RGB565 packing and integer downscaling.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "edgetrack/image_limits.h"
#include "edgetrack/frame_view.h"
#include "edgetrack/result.h"

namespace edgetrack_app {

/// An 8-bit RGB image, row-major, 3 bytes per pixel.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;

  uint8_t* pixel(int x, int y) { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
  const uint8_t* pixel(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

RgbImage make_image(int width, int height);

/// A frame's pixels in the layout its file holds, inside the bytes read: a binary 8-bit PGM is
/// grey8 and a PPM RGB24 from just after the header, a raw RGB565 file is RGB565 from its first
/// byte; other files are decoded into `bytes` (grey8 or RGB24).
struct FramePixels {
  std::vector<uint8_t> bytes;
  size_t offset = 0;  ///< of the first pixel in `bytes`
  int width = 0;
  int height = 0;
  edgetrack::PixelLayout layout = edgetrack::PixelLayout::kRgb24;

  edgetrack::FrameView view() const {
    return edgetrack::packed_frame(bytes.data() + offset, width, height, layout);
  }
};

/// The RGB image's pixels as a frame (RGB24), taking its buffer.
FramePixels frame_pixels(RgbImage image);
/// The frame as an 8-bit RGB image (grey repeated in the three channels), for drawing on it.
/// Takes grey8, RGB24 and RGB565 frames (what FramePixels holds).
RgbImage to_rgb_image(const edgetrack::FrameView& frame);

/// The largest frames accepted from files and options (edgetrack/image_limits.h).
using edgetrack::kMaxImageSide;
using edgetrack::kMaxImagePixels;
/// True when width x height is a frame size within those bounds.
bool usable_image_size(long long width, long long height);

/// Reads binary or ASCII PGM/PPM (P2, P3, P5, P6), maxval 1..65535 (scaled to 8 bits with
/// rounding, through a table: no division per pixel); 8-bit binary files are not copied.
edgetrack::Result<FramePixels> read_netpbm_pixels(const std::string& path);
/// The same as an RGB image.
edgetrack::Result<RgbImage> read_netpbm(const std::string& path);
/// Writes a binary PPM (P6).
edgetrack::Result<bool> write_ppm(const std::string& path, const RgbImage& image);
/// Writes the image's grey (vpImageConvert's rounding rule) as a binary 8-bit PGM (P5).
edgetrack::Result<bool> write_pgm(const std::string& path, const RgbImage& image);

/// Reads a raw little-endian RGB565 file of exactly width * height pixels (not copied on a
/// little-endian machine).
edgetrack::Result<FramePixels> read_raw_rgb565(const std::string& path, int width, int height);
/// Writes a raw little-endian RGB565 file.
edgetrack::Result<bool> write_raw_rgb565(const std::string& path, const std::vector<uint16_t>& pixels);

/// Packs to RGB565 (top 5, 6, 5 bits), the format the tracker takes.
void to_rgb565(const RgbImage& image, std::vector<uint16_t>& pixels);
/// Expands RGB565 to 8 bits per channel by bit replication.
RgbImage from_rgb565(const std::vector<uint16_t>& pixels, int width, int height);

/// Averages factor x factor blocks (the size is divided by factor, rounding down).
RgbImage downscale(const RgbImage& image, int factor);
/// The same block averages on `channels` interleaved 8-bit channels: width x height pixels at
/// `in` (rows packed) to (width / factor) x (height / factor) at `out`.
void average_blocks(const uint8_t* in, int width, int height, int channels, int factor, uint8_t* out);

/// The lower-cased extension of a path, without the dot ("pgm"), or empty.
std::string extension_of(const std::string& path);

}  // namespace edgetrack_app
