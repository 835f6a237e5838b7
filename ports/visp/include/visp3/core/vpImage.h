// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpImage.h: a row-major image of `Type` pixels that owns its bitmap.
/// The subset the moving edges need: sizes, `I[i][j]`, `I(i, j)`, `I(ip)`, `bitmap`, resize,
/// copy, fill, sum and mean.
/// Unlike upstream there is no row-pointer table and no display pointer; `I[i]` computes the row.
/// As upstream, init(array, h, w) without copyData borrows the caller's pixels (a camera buffer
/// read in place); a copy of such an image owns its pixels.
#pragma once

#ifdef vpImage_H
#error "edgetrack's drop-in visp3/core/vpImage.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <algorithm>
#include <cstddef>
#include <vector>

#include "visp3/core/vpImagePoint.h"
#include "visp3/core/vpRGBa.h"

inline namespace edgetrack_ports {

template <class Type>
class vpImage {
 public:
  vpImage() = default;
  vpImage(unsigned int height, unsigned int width) { resize(height, width); }
  vpImage(unsigned int height, unsigned int width, Type value) { resize(height, width, value); }
  vpImage(Type* const array, unsigned int h, unsigned int w, bool copyData = false) { init(array, h, w, copyData); }
  vpImage(const vpImage& other) : height(other.height), width(other.width) {
    pixels_.assign(other.bitmap, other.bitmap + other.getSize());
    bitmap = pixels_.empty() ? nullptr : pixels_.data();
  }
  vpImage& operator=(const vpImage& other) {
    if (this != &other) {
      pixels_.assign(other.bitmap, other.bitmap + other.getSize());
      height = other.height;
      width = other.width;
      bitmap = pixels_.empty() ? nullptr : pixels_.data();
    }
    return *this;
  }

  /// Sets the size; the pixels are value-initialised (zero for the arithmetic types).
  void resize(unsigned int h, unsigned int w) { resize(h, w, Type()); }
  void resize(unsigned int h, unsigned int w, const Type& value) {
    pixels_.assign(static_cast<std::size_t>(h) * w, value);
    height = h;
    width = w;
    bitmap = pixels_.empty() ? nullptr : pixels_.data();
  }
  void init(unsigned int h, unsigned int w) { resize(h, w); }
  void init(unsigned int h, unsigned int w, Type value) { resize(h, w, value); }
  /// The h x w pixels at `array`, row after row: copied when copyData, else borrowed (they must
  /// outlive the image's use; nothing is allocated).
  void init(Type* const array, unsigned int h, unsigned int w, bool copyData = false) {
    height = h;
    width = w;
    if (copyData) {
      pixels_.assign(array, array + static_cast<std::size_t>(h) * w);
      bitmap = pixels_.empty() ? nullptr : pixels_.data();
    } else {
      pixels_.clear();
      bitmap = array;
    }
  }

  unsigned int getHeight() const { return height; }
  unsigned int getWidth() const { return width; }
  unsigned int getRows() const { return height; }
  unsigned int getCols() const { return width; }
  unsigned int getSize() const { return height * width; }
  unsigned int getNumberOfPixel() const { return height * width; }

  /// Sum of the pixels in double, 0 for an empty image (upstream's; set-up and statistics only).
  double getSum() const {
    double sum = 0.0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(height) * width; ++k) sum += static_cast<double>(bitmap[k]);
    return sum;
  }
  /// getSum() / (height * width) converted to Type (truncated for integer pixels), 0 when empty.
  Type getMeanValue() const {
    if (height == 0 || width == 0) return Type(0.0);
    return static_cast<Type>(getSum() / (static_cast<double>(height) * width));
  }
  /// Frees the pixels: the image becomes 0 x 0 (its size too, unlike upstream's, which keeps the
  /// numbers while bitmap is null).
  void destroy() {
    pixels_.clear();
    pixels_.shrink_to_fit();
    bitmap = nullptr;
    height = width = 0;
  }
  /// Every pixel becomes v.
  vpImage& operator=(const Type& v) {
    std::fill(bitmap, bitmap + getSize(), v);
    return *this;
  }

  Type* operator[](unsigned int i) { return bitmap + static_cast<std::size_t>(i) * width; }
  Type* operator[](int i) { return bitmap + static_cast<std::ptrdiff_t>(i) * width; }
  const Type* operator[](unsigned int i) const { return bitmap + static_cast<std::size_t>(i) * width; }
  const Type* operator[](int i) const { return bitmap + static_cast<std::ptrdiff_t>(i) * width; }

  Type operator()(unsigned int i, unsigned int j) const { return bitmap[static_cast<std::size_t>(i) * width + j]; }
  void operator()(unsigned int i, unsigned int j, const Type& v) { bitmap[static_cast<std::size_t>(i) * width + j] = v; }
  /// The pixel under ip, its coordinates truncated as upstream's cast does.
  Type operator()(const vpImagePoint& ip) const { return (*this)(pixel_of(ip.get_i()), pixel_of(ip.get_j())); }
  void operator()(const vpImagePoint& ip, const Type& v) { (*this)(pixel_of(ip.get_i()), pixel_of(ip.get_j()), v); }

  bool operator==(const vpImage& other) const {
    return height == other.height && width == other.width && std::equal(bitmap, bitmap + getSize(), other.bitmap);
  }
  bool operator!=(const vpImage& other) const { return !(*this == other); }

 private:
  static unsigned int pixel_of(real coordinate) { return static_cast<unsigned int>(coordinate); }

  std::vector<Type> pixels_;

 public:
  /// Points at the first pixel (row 0, column 0), or is null for an empty image, as upstream.
  Type* bitmap = nullptr;

 private:
  unsigned int height = 0;
  unsigned int width = 0;
};

}  // inline namespace edgetrack_ports
