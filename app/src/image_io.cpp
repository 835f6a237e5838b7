// SPDX-License-Identifier: BSD-3-Clause
/// PGM/PPM and raw RGB565 reading and writing, RGB565 packing and downscaling.
#include "image_io.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "edgetrack/input_file.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

/// Reads the next header number of a netpbm file, skipping white space and # comments.
bool header_number(const std::vector<uint8_t>& bytes, size_t& at, int& value) {
  while (at < bytes.size()) {
    if (bytes[at] == '#') {
      while (at < bytes.size() && bytes[at] != '\n') ++at;
    } else if (std::isspace(bytes[at])) {
      ++at;
    } else {
      break;
    }
  }
  if (at >= bytes.size() || !std::isdigit(bytes[at])) return false;
  long v = 0;
  while (at < bytes.size() && std::isdigit(bytes[at])) {
    v = v * 10 + (bytes[at++] - '0');
    if (v > 1000000) return false;
  }
  value = static_cast<int>(v);
  return true;
}

Result<std::vector<uint8_t>> read_bytes(const std::string& path) {
  return edgetrack::read_input_file(path, edgetrack::kMaxImageFileBytes);
}

std::string size_text(long long width, long long height) { return std::to_string(width) + "x" + std::to_string(height); }

}  // namespace

bool usable_image_size(long long width, long long height) {
  return width > 0 && height > 0 && width <= kMaxImageSide && height <= kMaxImageSide &&
         width * height <= kMaxImagePixels;
}

RgbImage make_image(int width, int height) {
  RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<size_t>(width) * height * 3, 0);
  return image;
}

std::string extension_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

Result<RgbImage> read_netpbm(const std::string& path) {
  auto loaded = read_bytes(path);
  if (!loaded.ok()) return loaded.error();
  const std::vector<uint8_t>& bytes = loaded.value();
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '3' && bytes[1] != '5' && bytes[1] != '6'))
    return Error{path, 0, "not a PGM or PPM image (no P2, P3, P5 or P6 signature)"};
  const bool colour = bytes[1] == '3' || bytes[1] == '6';
  const bool ascii = bytes[1] == '2' || bytes[1] == '3';
  size_t at = 2;
  int width = 0, height = 0, maxval = 0;
  if (!header_number(bytes, at, width) || !header_number(bytes, at, height) || !header_number(bytes, at, maxval))
    return Error{path, 0, "malformed PGM/PPM header"};
  if (!usable_image_size(width, height))
    return Error{path, 0, "image size " + size_text(width, height) + " is outside 1.." + std::to_string(kMaxImageSide) +
                              " per side and " + std::to_string(kMaxImagePixels >> 20) + " M pixels"};
  if (maxval <= 0 || maxval > 65535) return Error{path, 0, "maxval " + std::to_string(maxval) + " is out of range"};
  const int channels = colour ? 3 : 1;
  const size_t pixels = static_cast<size_t>(width) * height;
  const size_t samples = pixels * channels;
  const size_t bytes_per_sample = maxval > 255 ? 2 : 1;
  if (!ascii) {
    ++at;  // the single white space after maxval
    if (bytes.size() < at + samples * bytes_per_sample)
      return Error{path, 0, "the pixel data is truncated (" + std::to_string(bytes.size() - std::min(at, bytes.size())) +
                                " bytes, " + std::to_string(samples * bytes_per_sample) + " expected)"};
  }
  // sample -> round(255 * min(sample, maxval) / maxval), one division per level, not per pixel.
  std::vector<uint8_t> to_8bit(static_cast<size_t>(maxval) + 1);
  for (int v = 0; v <= maxval; ++v) to_8bit[v] = static_cast<uint8_t>((v * 255 + maxval / 2) / maxval);
  RgbImage image = make_image(width, height);
  uint8_t* out = image.rgb.data();
  for (size_t i = 0; i < samples; ++i) {
    int v = 0;
    if (ascii) {
      if (!header_number(bytes, at, v)) return Error{path, 0, "the pixel data is truncated or not numbers"};
    } else {
      v = bytes_per_sample == 1 ? bytes[at + i] : (bytes[at + 2 * i] << 8) | bytes[at + 2 * i + 1];
    }
    const uint8_t level = to_8bit[std::min(v, maxval)];
    if (colour) {
      *out++ = level;
    } else {
      out[0] = out[1] = out[2] = level;
      out += 3;
    }
  }
  return image;
}

Result<bool> write_ppm(const std::string& path, const RgbImage& image) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  bool ok = std::fprintf(file, "P6\n%d %d\n255\n", image.width, image.height) > 0;
  ok = ok && std::fwrite(image.rgb.data(), 1, image.rgb.size(), file) == image.rgb.size();
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

Result<RgbImage> read_raw_rgb565(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return Error{path, 0, "raw RGB565 frames need --raw-size WIDTHxHEIGHT"};
  if (!usable_image_size(width, height)) return Error{path, 0, "raw frame size " + size_text(width, height) + " is too large"};
  auto loaded = read_bytes(path);
  if (!loaded.ok()) return loaded.error();
  const std::vector<uint8_t>& bytes = loaded.value();
  const size_t expected = static_cast<size_t>(width) * height * 2;
  if (bytes.size() != expected)
    return Error{path, 0, "raw RGB565 file has " + std::to_string(bytes.size()) + " bytes, " + std::to_string(expected) +
                              " expected for " + std::to_string(width) + "x" + std::to_string(height)};
  std::vector<uint16_t> pixels(static_cast<size_t>(width) * height);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<uint16_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
  return from_rgb565(pixels, width, height);
}

Result<bool> write_raw_rgb565(const std::string& path, const std::vector<uint16_t>& pixels) {
  std::vector<uint8_t> bytes(pixels.size() * 2);
  for (size_t i = 0; i < pixels.size(); ++i) {
    bytes[2 * i] = static_cast<uint8_t>(pixels[i] & 0xff);
    bytes[2 * i + 1] = static_cast<uint8_t>(pixels[i] >> 8);
  }
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

void to_rgb565(const RgbImage& image, std::vector<uint16_t>& pixels) {
  pixels.resize(static_cast<size_t>(image.width) * image.height);
  for (size_t i = 0; i < pixels.size(); ++i) {
    const uint8_t* p = &image.rgb[i * 3];
    pixels[i] = static_cast<uint16_t>(((p[0] >> 3) << 11) | ((p[1] >> 2) << 5) | (p[2] >> 3));
  }
}

RgbImage from_rgb565(const std::vector<uint16_t>& pixels, int width, int height) {
  RgbImage image = make_image(width, height);
  for (size_t i = 0; i < pixels.size() && i < static_cast<size_t>(width) * height; ++i) {
    const int r5 = pixels[i] >> 11, g6 = (pixels[i] >> 5) & 63, b5 = pixels[i] & 31;
    image.rgb[i * 3] = static_cast<uint8_t>((r5 << 3) | (r5 >> 2));
    image.rgb[i * 3 + 1] = static_cast<uint8_t>((g6 << 2) | (g6 >> 4));
    image.rgb[i * 3 + 2] = static_cast<uint8_t>((b5 << 3) | (b5 >> 2));
  }
  return image;
}

RgbImage downscale(const RgbImage& image, int factor) {
  if (factor <= 1) return image;
  RgbImage out = make_image(image.width / factor, image.height / factor);
  const int n = factor * factor;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy)
          for (int dx = 0; dx < factor; ++dx) sum += image.pixel(x * factor + dx, y * factor + dy)[c];
        out.pixel(x, y)[c] = static_cast<uint8_t>((sum + n / 2) / n);
      }
  return out;
}

}  // namespace edgetrack_app
