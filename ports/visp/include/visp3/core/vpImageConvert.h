// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpImageConvert.h for the grey conversions the tracker needs
/// (RGBa, RGB24 and, new here, RGB565 to grey).
///
/// Rounding rule (all three colour formats): with 8-bit channels R, G, B,
///   grey = (13933 R + 46871 G + 4732 B + 32768) >> 16,
/// the BT.709 luma weights 0.2126, 0.7152, 0.0722 scaled by 2^16 to integers that sum to 65536,
/// rounded to nearest. RGB565 channels are first widened to 8 bits by bit replication
/// (r8 = r5 << 3 | r5 >> 2, g8 = g6 << 2 | g6 >> 4), so white stays 255 and black 0.
/// Upstream computes the same weights in double and truncates; docs/ME.md gives the difference.
#pragma once

#ifdef vpIMAGECONVERT_H
#error "edgetrack's drop-in visp3/core/vpImageConvert.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdint>

#include "visp3/core/vpImage.h"
#include "visp3/core/vpRGBa.h"

inline namespace edgetrack_ports {

class vpImageConvert {
 public:
  /// The rounding rule above for one pixel.
  static constexpr unsigned char rgbToGrey(unsigned int r, unsigned int g, unsigned int b) {
    return static_cast<unsigned char>((13933u * r + 46871u * g + 4732u * b + 32768u) >> 16);
  }
  /// One RGB565 pixel (red in the top 5 bits) to grey, by the rule above.
  static constexpr unsigned char rgb565ToGrey(uint16_t p) {
    const unsigned int r5 = p >> 11, g6 = (p >> 5) & 0x3Fu, b5 = p & 0x1Fu;
    return rgbToGrey((r5 << 3) | (r5 >> 2), (g6 << 2) | (g6 >> 4), (b5 << 3) | (b5 >> 2));
  }

  static void convert(const vpImage<vpRGBa>& src, vpImage<unsigned char>& dest);
  static void convert(const vpImage<unsigned char>& src, vpImage<vpRGBa>& dest);
  template <class Type>
  static void convert(const vpImage<Type>& src, vpImage<Type>& dest) {
    dest = src;
  }

  static void RGBToGrey(unsigned char* rgb, unsigned char* grey, unsigned int size);
  static void RGBaToGrey(unsigned char* rgba, unsigned char* grey, unsigned int size);
  /// New in the port (the paper's handheld pixel format): `size` RGB565 pixels to grey.
  static void RGB565ToGrey(const uint16_t* rgb565, unsigned char* grey, unsigned int size);
  /// New in the port: `rows` rows of `cols` RGB565 pixels to grey, the rows `src_stride` bytes
  /// apart in `src` (2-byte aligned) and `grey_stride` bytes apart in `grey` (a camera buffer's
  /// box into an image's, one call per box).
  static void RGB565ToGrey(const uint8_t* src, unsigned int src_stride, unsigned char* grey, unsigned int grey_stride,
                           unsigned int rows, unsigned int cols);
  /// Whole-frame RGB565 to grey; `dest` takes the size of `src`.
  static void RGB565ToGrey(const vpImage<uint16_t>& src, vpImage<unsigned char>& dest);
};

}  // inline namespace edgetrack_ports
