// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpRGBa.h: one 32-bit RGBA pixel, the colour pixel of vpImage.
/// Only the members the moving-edge port and its callers use: the four channels and construction.
#pragma once

#ifdef vpRGBa_h
#error "edgetrack's drop-in visp3/core/vpRGBa.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

class vpRGBa {
 public:
  enum AlphaDefault { alpha_default = 255 };

  vpRGBa() = default;
  vpRGBa(unsigned char r, unsigned char g, unsigned char b, unsigned char a = alpha_default)
      : R(r), G(g), B(b), A(a) {}
  /// All four channels set to `v`, as upstream does.
  explicit vpRGBa(unsigned char v) : R(v), G(v), B(v), A(v) {}

  bool operator==(const vpRGBa& o) const { return R == o.R && G == o.G && B == o.B && A == o.A; }
  bool operator!=(const vpRGBa& o) const { return !(*this == o); }

  unsigned char R = 0;
  unsigned char G = 0;
  unsigned char B = 0;
  unsigned char A = alpha_default;
};

}  // inline namespace edgetrack_ports
