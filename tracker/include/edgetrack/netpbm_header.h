// SPDX-License-Identifier: BSD-3-Clause
/// The header of a PGM or PPM image (P2, P3, P5, P6), read one byte at a time: the app reads it
/// from the bytes of a file it holds, the firmware from the file as it reads it into the camera
/// buffer. Nothing here allocates or needs a host library, so a bad header on bare metal, after
/// the heap is locked, is still reported.
#pragma once

#include <cstddef>

namespace edgetrack {

/// Header numbers above this are refused: no image side or maxval comes near it.
constexpr int kNetpbmLargestNumber = 1000000;

struct NetpbmHeader {
  bool colour = false;  ///< P3 or P6: three samples a pixel
  bool ascii = false;   ///< P2 or P3: samples as decimal numbers
  int width = 0;
  int height = 0;
  int maxval = 0;
  size_t samples_at = 0;  ///< the offset of the first sample: after the white space ending the header
  /// What is wrong with the header (static text), or null; `line` is the 1-based line it is on.
  const char* problem = nullptr;
  int line = 1;
  int size_line = 1;     ///< the line of the width and height (where a caller refuses a size)
  int samples_line = 1;  ///< the line the samples start on

  bool ok() const { return problem == nullptr; }
};

/// Netpbm's numbers from `next_byte()`, which gives a file's bytes in order and a negative
/// number at its end: each number after white space and # comments, ended by the byte after it.
template <class NextByte>
class NetpbmNumbers {
 public:
  explicit NetpbmNumbers(NextByte next_byte) : next_byte_(next_byte) { advance(); }

  /// The next number into `value`; false when the bytes there are not one (or it is too large).
  bool number(int& value) {
    while (c_ == '#' || space(c_)) {
      if (c_ == '#')
        while (c_ != '\n' && c_ >= 0) advance();
      else
        advance();
    }
    if (!(c_ >= '0' && c_ <= '9')) return false;
    value = 0;
    for (; c_ >= '0' && c_ <= '9'; advance()) {
      value = value * 10 + (c_ - '0');
      if (value > kNetpbmLargestNumber) return false;
    }
    return true;
  }
  /// The byte after the last one read (negative at the end).
  int current() const { return c_; }
  /// The bytes read, `current()` included.
  size_t consumed() const { return consumed_; }
  /// The 1-based line of `current()` (a newline belongs to the line it ends).
  int line() const { return line_; }
  /// The line of the byte after `current()`.
  int next_line() const { return line_ + (c_ == '\n' ? 1 : 0); }

  static bool space(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

 private:
  void advance() {
    const int c = next_byte_();
    if (c < 0) {
      c_ = -1;  // the end stays on the last line
      return;
    }
    line_ = next_line();
    c_ = c;
    ++consumed_;
  }

  NextByte next_byte_;
  int c_ = 0;
  size_t consumed_ = 0;
  int line_ = 1;
};

/// Parses a netpbm header from `next_byte()` (as NetpbmNumbers). Reads exactly the header's
/// bytes, the one white space ending it included; `maxval` is checked to be 1..65535, the size
/// is left to the caller's bounds.
template <class NextByte>
NetpbmHeader parse_netpbm_header(NextByte next_byte) {
  NetpbmHeader h;
  const int p = next_byte(), kind = next_byte();
  if (p != 'P' || (kind != '2' && kind != '3' && kind != '5' && kind != '6')) {
    h.problem = "not a PGM or PPM image (no P2, P3, P5 or P6 signature)";
    return h;
  }
  h.colour = kind == '3' || kind == '6';
  h.ascii = kind == '2' || kind == '3';
  NetpbmNumbers<NextByte&> in(next_byte);
  bool numbers = in.number(h.width) && in.number(h.height);
  h.size_line = in.line();
  numbers = numbers && in.number(h.maxval);
  h.line = in.line();
  h.samples_line = in.next_line();
  h.samples_at = 2 + in.consumed();
  if (!numbers || !in.space(in.current()))
    h.problem = "malformed PGM/PPM header (width, height and maxval, each after white space)";
  else if (h.maxval < 1 || h.maxval > 65535)
    h.problem = "maxval is outside 1..65535";
  return h;
}

}  // namespace edgetrack
