// SPDX-License-Identifier: BSD-3-Clause
/// Frames as the application handles them: 8-bit RGB images, our own PGM/PPM reader and writer,
/// raw RGB565 files, the RGB565 conversion the tracker takes, and integer downscaling.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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

/// The largest frames accepted from files and options: sides up to 16384 pixels and at most
/// 64 M pixels (8192 x 8192, or 16384 x 4096), 192 MB as RGB.
constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 64LL << 20;
/// True when width x height is a frame size within those bounds.
bool usable_image_size(long long width, long long height);

/// Reads binary or ASCII PGM/PPM (P2, P3, P5, P6), maxval 1..65535 (scaled to 8 bits with
/// rounding, through a table: no division per pixel).
edgetrack::Result<RgbImage> read_netpbm(const std::string& path);
/// Writes a binary PPM (P6).
edgetrack::Result<bool> write_ppm(const std::string& path, const RgbImage& image);

/// Reads a raw little-endian RGB565 file of exactly width * height pixels.
edgetrack::Result<RgbImage> read_raw_rgb565(const std::string& path, int width, int height);
/// Writes a raw little-endian RGB565 file.
edgetrack::Result<bool> write_raw_rgb565(const std::string& path, const std::vector<uint16_t>& pixels);

/// Packs to RGB565 (top 5, 6, 5 bits), the format the tracker takes.
void to_rgb565(const RgbImage& image, std::vector<uint16_t>& pixels);
/// Expands RGB565 to 8 bits per channel by bit replication.
RgbImage from_rgb565(const std::vector<uint16_t>& pixels, int width, int height);

/// Averages factor x factor blocks (the size is divided by factor, rounding down).
RgbImage downscale(const RgbImage& image, int factor);

/// The lower-cased extension of a path, without the dot ("pgm"), or empty.
std::string extension_of(const std::string& path);

}  // namespace edgetrack_app
