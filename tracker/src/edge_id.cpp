// SPDX-License-Identifier: BSD-3-Clause
/// The Edge-ID colour code, equations (4)-(12) of the paper, and the RGB565 pixel format.
#include "edgetrack/edge_id.h"

namespace edgetrack {

Rgb888 encode_edge_id(int index) {
  const int b_code = (index + 1) * 8;   // (4)
  const int g_code = (b_code / 256) * 8;  // (5)
  const int r_code = (g_code / 256) * 8;  // (6)
  return {r_code % 256, g_code % 256, b_code % 256};  // (7), (8), (9)
}

int decode_edge_id(const Rgb888& colour) {
  const int rg_decode = (colour.r / 8) * 256 + colour.g;   // (10)
  const int rgb_decode = (rg_decode / 8) * 256 + colour.b;  // (11)
  return rgb_decode / 8 - 1;                                // (12)
}

Rgb888 encode_edge_id_naive(int index) {
  const int code = index + 1;
  return {(code >> 16) & 255, (code >> 8) & 255, code & 255};
}

int decode_edge_id_naive(const Rgb888& colour) { return ((colour.r << 16) | (colour.g << 8) | colour.b) - 1; }

uint16_t pack_rgb565(const Rgb888& colour) {
  return static_cast<uint16_t>(((colour.r >> 3) << 11) | ((colour.g >> 2) << 5) | (colour.b >> 3));
}

Rgb888 unpack_rgb565(uint16_t pixel) {
  const int r5 = (pixel >> 11) & 31, g6 = (pixel >> 5) & 63, b5 = pixel & 31;
  return {(r5 << 3) | (r5 >> 2), (g6 << 2) | (g6 >> 4), (b5 << 3) | (b5 >> 2)};
}

}  // namespace edgetrack
