// SPDX-License-Identifier: BSD-3-Clause
/// Integer grey conversions of vpImageConvert and the tile bookkeeping of vpGreyOnDemand.
#include "visp3/core/vpImageConvert.h"

#include <algorithm>

namespace {

/// The rule's weighted sum of an RGB565 pixel, split by byte: the high byte holds red and the
/// top three green bits, the low byte the low three green bits and blue. Bit replication widens
/// green as g8 = (gh << 5) + (gh >> 1) + (gl << 2) (no bits overlap), so the sum is exactly
/// high[p >> 8] + low[p & 0xFF]: two loads and an add per pixel instead of three multiplies.
struct Rgb565Sums {
  uint32_t high[256];  ///< 13933 r8 + 46871 (green from gh) + 32768 (the rounding)
  uint32_t low[256];   ///< 46871 (green from gl) + 4732 b8
};

constexpr Rgb565Sums make_rgb565_sums() {
  Rgb565Sums sums{};
  for (uint32_t byte = 0; byte < 256; ++byte) {
    const uint32_t r5 = byte >> 3, gh = byte & 7u, gl = byte >> 5, b5 = byte & 0x1Fu;
    sums.high[byte] = 13933u * ((r5 << 3) | (r5 >> 2)) + 46871u * ((gh << 5) + (gh >> 1)) + 32768u;
    sums.low[byte] = 46871u * (gl << 2) + 4732u * ((b5 << 3) | (b5 >> 2));
  }
  return sums;
}

constexpr Rgb565Sums kRgb565Sums = make_rgb565_sums();

}  // namespace

void vpImageConvert::convert(const vpImage<vpRGBa>& src, vpImage<unsigned char>& dest) {
  dest.resize(src.getHeight(), src.getWidth());
  const vpRGBa* in = src.bitmap;
  unsigned char* out = dest.bitmap;
  for (unsigned int n = src.getSize(); n > 0; --n, ++in, ++out) *out = rgbToGrey(in->R, in->G, in->B);
}

void vpImageConvert::convert(const vpImage<unsigned char>& src, vpImage<vpRGBa>& dest) {
  dest.resize(src.getHeight(), src.getWidth());
  for (unsigned int n = 0; n < src.getSize(); ++n) {
    const unsigned char v = src.bitmap[n];
    dest.bitmap[n] = vpRGBa(v, v, v, vpRGBa::alpha_default);
  }
}

void vpImageConvert::RGBToGrey(unsigned char* rgb, unsigned char* grey, unsigned int size) {
  for (; size > 0; --size, rgb += 3) *grey++ = rgbToGrey(rgb[0], rgb[1], rgb[2]);
}

void vpImageConvert::RGBaToGrey(unsigned char* rgba, unsigned char* grey, unsigned int size) {
  for (; size > 0; --size, rgba += 4) *grey++ = rgbToGrey(rgba[0], rgba[1], rgba[2]);
}

void vpImageConvert::RGB565ToGrey(const uint16_t* rgb565, unsigned char* grey, unsigned int size) {
  for (; size > 0; --size) {
    const unsigned int p = *rgb565++;
    *grey++ = static_cast<unsigned char>((kRgb565Sums.high[p >> 8] + kRgb565Sums.low[p & 0xFFu]) >> 16);
  }
}

void vpImageConvert::RGB565ToGrey(const vpImage<uint16_t>& src, vpImage<unsigned char>& dest) {
  dest.resize(src.getHeight(), src.getWidth());
  RGB565ToGrey(src.bitmap, dest.bitmap, src.getSize());
}

void vpImageConvert::RGB565ToGrey(const vpImage<uint16_t>& src, vpImage<unsigned char>& dest, int top,
                                  int left, int bottom, int right) {
  RGB565ToGrey(src.bitmap, dest, top, left, bottom, right);
}

unsigned int vpImageConvert::RGB565ToGrey(const uint16_t* src, vpImage<unsigned char>& dest, int top, int left,
                                          int bottom, int right) {
  const int width = static_cast<int>(dest.getWidth());
  top = std::max(top, 0);
  left = std::max(left, 0);
  bottom = std::min(bottom, static_cast<int>(dest.getHeight()));
  right = std::min(right, width);
  if (left >= right || top >= bottom) return 0;
  for (int i = top; i < bottom; ++i) {
    RGB565ToGrey(src + i * width + left, dest[i] + left, static_cast<unsigned int>(right - left));
  }
  return static_cast<unsigned int>((bottom - top) * (right - left));
}

void vpGreyOnDemand::setFrame(const vpImage<uint16_t>& src) {
  src_ = src.bitmap;
  const unsigned int rows = src.getHeight(), cols = src.getWidth();
  if (grey_.getHeight() != rows || grey_.getWidth() != cols) {
    grey_.resize(rows, cols);
    tiles_down_ = (static_cast<int>(rows) + kTile - 1) / kTile;
    tiles_across_ = (static_cast<int>(cols) + kTile - 1) / kTile;
    tile_frame_.assign(static_cast<std::size_t>(tiles_down_) * tiles_across_, 0);
    frame_ = 0;
  }
  ++frame_;
  if (frame_ == 0) {  // the counter wrapped: forget every stamp once
    std::fill(tile_frame_.begin(), tile_frame_.end(), 0);
    frame_ = 1;
  }
  converted_ = 0;
}

void vpGreyOnDemand::require(int top, int left, int bottom, int right) {
  if (src_ == nullptr) return;
  const int ti0 = std::max(top, 0) / kTile, tj0 = std::max(left, 0) / kTile;
  const int ti1 = std::min((bottom + kTile - 1) / kTile, tiles_down_);
  const int tj1 = std::min((right + kTile - 1) / kTile, tiles_across_);
  for (int ti = ti0; ti < ti1; ++ti) {
    uint32_t* stamp = &tile_frame_[static_cast<std::size_t>(ti) * tiles_across_];
    for (int tj = tj0; tj < tj1; ++tj) {
      if (stamp[tj] == frame_) continue;
      stamp[tj] = frame_;
      const int i0 = ti * kTile, j0 = tj * kTile;
      converted_ += vpImageConvert::RGB565ToGrey(src_, grey_, i0, j0, i0 + kTile, j0 + kTile);
    }
  }
}
