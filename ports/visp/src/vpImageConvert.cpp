// SPDX-License-Identifier: BSD-3-Clause
/// Integer grey conversions of vpImageConvert.
#include "visp3/core/vpImageConvert.h"

inline namespace edgetrack_ports {

#if !defined(EDGETRACK_RGB565_BY_RULE)
namespace {

/// The grey of every RGB565 value by the rule: one table load per pixel (64 KB of constants),
/// where the rule itself takes shifts and three multiplies.
struct Rgb565Greys {
  unsigned char grey[65536];
};

constexpr Rgb565Greys make_rgb565_greys() {
  Rgb565Greys greys{};
  for (uint32_t p = 0; p < 65536; ++p) greys.grey[p] = vpImageConvert::rgb565ToGrey(static_cast<uint16_t>(p));
  return greys;
}

constexpr Rgb565Greys kRgb565Greys = make_rgb565_greys();

}  // namespace
#endif

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
#if defined(EDGETRACK_RGB565_BY_RULE)
  for (; size > 0; --size) *grey++ = rgb565ToGrey(*rgb565++);
#else
  const unsigned char* table = kRgb565Greys.grey;
  // Four pixels a round: the loop's own compare and branch are a third of a pixel's cost.
  for (; size >= 4; size -= 4, rgb565 += 4, grey += 4) {
    grey[0] = table[rgb565[0]];
    grey[1] = table[rgb565[1]];
    grey[2] = table[rgb565[2]];
    grey[3] = table[rgb565[3]];
  }
  for (; size > 0; --size) *grey++ = table[*rgb565++];
#endif
}

void vpImageConvert::RGB565ToGrey(const uint8_t* src, unsigned int src_stride, unsigned char* grey,
                                  unsigned int grey_stride, unsigned int rows, unsigned int cols) {
  for (; rows > 0; --rows, src += src_stride, grey += grey_stride)
    RGB565ToGrey(reinterpret_cast<const uint16_t*>(src), grey, cols);
}

void vpImageConvert::RGB565ToGrey(const vpImage<uint16_t>& src, vpImage<unsigned char>& dest) {
  dest.resize(src.getHeight(), src.getWidth());
  RGB565ToGrey(src.bitmap, dest.bitmap, src.getSize());
}

}  // inline namespace edgetrack_ports
