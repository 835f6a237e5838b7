// SPDX-License-Identifier: BSD-3-Clause
/// The Edge-ID colour code of the paper's section 3.4: an edge index written as a colour, read
/// back from a 16-bit RGB565 colour buffer. Black is the background.
#pragma once

#include <cstdint>

namespace edgetrack {

struct Rgb888 {
  int r = 0;  ///< 0..255
  int g = 0;
  int b = 0;
};

inline bool operator==(const Rgb888& a, const Rgb888& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/// Equations (4)-(9): b_code = (i + 1) * 8, g_code = (b_code / 256) * 8, r_code = (g_code / 256) * 8,
/// then each channel modulo 256. Valid for 0 <= index < kMaxEdges (32767).
Rgb888 encode_edge_id(int index);
/// Equations (10)-(12): the index back from a colour; -1 for the black background.
int decode_edge_id(const Rgb888& colour);

/// The paper's first, naive code: index + 1 as a 24-bit number, one byte per channel.
Rgb888 encode_edge_id_naive(int index);
int decode_edge_id_naive(const Rgb888& colour);

/// Writing to an RGB565 buffer keeps the top 5, 6 and 5 bits of r, g and b.
uint16_t pack_rgb565(const Rgb888& colour);
/// Reading an RGB565 pixel back to 8 bits per channel by bit replication, as display hardware
/// and glReadPixels do: r8 = r5 << 3 | r5 >> 2, g8 = g6 << 2 | g6 >> 4.
Rgb888 unpack_rgb565(uint16_t pixel);
/// decode_edge_id(unpack_rgb565(pixel)) in bit operations, for reading an Edge-ID buffer per
/// control point: after the replication r8 / 8 is r5, g8 / 8 is g6 >> 1 and b8 / 8 is b5, so
/// the index is r5 * 1024 + (g6 >> 1) * 32 + b5 - 1.
inline int decode_edge_id_rgb565(uint16_t pixel) {
  return ((pixel >> 11) << 10 | ((pixel >> 6) & 31) << 5 | (pixel & 31)) - 1;
}

}  // namespace edgetrack
