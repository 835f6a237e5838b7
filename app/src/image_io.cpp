// SPDX-License-Identifier: BSD-3-Clause
/// PGM/PPM and raw RGB565 reading and writing, RGB565 packing and downscaling.
#include "image_io.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "edgetrack/input_file.h"
#include "edgetrack/netpbm_header.h"
#include "visp3/core/vpImageConvert.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

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

namespace {

using edgetrack::NetpbmHeader;

Result<NetpbmHeader> read_netpbm_header(const std::string& path, const std::vector<uint8_t>& bytes) {
  size_t next = 0;
  const NetpbmHeader h =
      edgetrack::parse_netpbm_header([&]() -> int { return next < bytes.size() ? bytes[next++] : -1; });
  if (!h.ok()) return Error{path, h.line, h.problem};
  if (!usable_image_size(h.width, h.height))
    return Error{path, h.size_line, "image size " + size_text(h.width, h.height) + " is outside 1.." +
                                   std::to_string(kMaxImageSide) + " per side and " +
                                   std::to_string(kMaxImagePixels >> 20) + " M pixels"};
  const size_t samples = static_cast<size_t>(h.width) * h.height * (h.colour ? 3 : 1);
  const size_t bytes_per_sample = h.maxval > 255 ? 2 : 1;
  if (!h.ascii && bytes.size() < h.samples_at + samples * bytes_per_sample)
    return Error{path, 0, "the pixel data is truncated (" + std::to_string(bytes.size() - h.samples_at) + " bytes, " +
                              std::to_string(samples * bytes_per_sample) + " expected)"};
  return h;
}

/// The samples of an ASCII or 16-bit file, scaled to 8 bits: round(255 * min(sample, maxval) /
/// maxval), one division per level, not per pixel.
Result<std::vector<uint8_t>> decode_netpbm_samples(const std::string& path, const std::vector<uint8_t>& bytes,
                                                   const NetpbmHeader& h) {
  const size_t samples = static_cast<size_t>(h.width) * h.height * (h.colour ? 3 : 1);
  std::vector<uint8_t> to_8bit(static_cast<size_t>(h.maxval) + 1);
  for (int v = 0; v <= h.maxval; ++v) to_8bit[v] = static_cast<uint8_t>((v * 255 + h.maxval / 2) / h.maxval);
  std::vector<uint8_t> out(samples);
  const size_t at = h.samples_at;
  size_t next = at;
  edgetrack::NetpbmNumbers numbers([&]() -> int { return next < bytes.size() ? bytes[next++] : -1; });
  for (size_t i = 0; i < samples; ++i) {
    int v = 0;
    if (h.ascii) {
      if (!numbers.number(v)) return Error{path, h.samples_line + numbers.line() - 1, "the pixel data is truncated or not numbers"};
    } else {
      v = h.maxval > 255 ? (bytes[at + 2 * i] << 8) | bytes[at + 2 * i + 1] : bytes[at + i];
    }
    out[i] = to_8bit[std::min(v, h.maxval)];
  }
  return out;
}

}  // namespace

Result<FramePixels> read_netpbm_pixels(const std::string& path) {
  auto loaded = read_bytes(path);
  if (!loaded.ok()) return loaded.error();
  auto header = read_netpbm_header(path, loaded.value());
  if (!header.ok()) return header.error();
  const NetpbmHeader& h = header.value();
  FramePixels frame;
  frame.width = h.width;
  frame.height = h.height;
  frame.layout = h.colour ? edgetrack::PixelLayout::kRgb24 : edgetrack::PixelLayout::kGrey8;
  if (!h.ascii && h.maxval == 255) {  // the samples are the pixels
    frame.bytes = std::move(loaded).value();
    frame.offset = h.samples_at;
    return frame;
  }
  auto decoded = decode_netpbm_samples(path, loaded.value(), h);
  if (!decoded.ok()) return decoded.error();
  frame.bytes = std::move(decoded).value();
  return frame;
}

Result<RgbImage> read_netpbm(const std::string& path) {
  auto frame = read_netpbm_pixels(path);
  if (!frame.ok()) return frame.error();
  return to_rgb_image(frame.value().view());
}

FramePixels frame_pixels(RgbImage image) {
  FramePixels frame;
  frame.width = image.width;
  frame.height = image.height;
  frame.layout = edgetrack::PixelLayout::kRgb24;
  frame.bytes = std::move(image.rgb);
  return frame;
}

RgbImage to_rgb_image(const edgetrack::FrameView& frame) {
  RgbImage image = make_image(frame.width, frame.height);
  uint8_t* out = image.rgb.data();
  for (int y = 0; y < frame.height; ++y) {
    const uint8_t* in = frame.row(y);
    for (int x = 0; x < frame.width; ++x, out += 3) {
      if (frame.layout == edgetrack::PixelLayout::kGrey8) {
        out[0] = out[1] = out[2] = in[x];
      } else if (frame.layout == edgetrack::PixelLayout::kRgb565) {
        const unsigned p = reinterpret_cast<const uint16_t*>(in)[x];
        const unsigned r5 = p >> 11, g6 = (p >> 5) & 63u, b5 = p & 31u;
        out[0] = static_cast<uint8_t>((r5 << 3) | (r5 >> 2));
        out[1] = static_cast<uint8_t>((g6 << 2) | (g6 >> 4));
        out[2] = static_cast<uint8_t>((b5 << 3) | (b5 >> 2));
      } else {
        std::copy(in + 3 * x, in + 3 * x + 3, out);
      }
    }
  }
  return image;
}

namespace {

/// Writes a binary netpbm file: its header, then `pixels`.
Result<bool> write_netpbm(const std::string& path, char kind, const RgbImage& image, const std::vector<uint8_t>& pixels) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  bool ok = std::fprintf(file, "P%c\n%d %d\n255\n", kind, image.width, image.height) > 0;
  ok = ok && std::fwrite(pixels.data(), 1, pixels.size(), file) == pixels.size();
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

}  // namespace

Result<bool> write_ppm(const std::string& path, const RgbImage& image) { return write_netpbm(path, '6', image, image.rgb); }

Result<bool> write_pgm(const std::string& path, const RgbImage& image) {
  std::vector<uint8_t> grey(static_cast<size_t>(image.width) * image.height);
  for (size_t i = 0; i < grey.size(); ++i)
    grey[i] = vpImageConvert::rgbToGrey(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]);
  return write_netpbm(path, '5', image, grey);
}

Result<FramePixels> read_raw_rgb565(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return Error{path, 0, "raw RGB565 frames need --raw-size WIDTHxHEIGHT"};
  if (!usable_image_size(width, height)) return Error{path, 0, "raw frame size " + size_text(width, height) + " is too large"};
  auto loaded = read_bytes(path);
  if (!loaded.ok()) return loaded.error();
  const size_t expected = static_cast<size_t>(width) * height * 2;
  if (loaded.value().size() != expected)
    return Error{path, 0, "raw RGB565 file has " + std::to_string(loaded.value().size()) + " bytes, " +
                              std::to_string(expected) + " expected for " + std::to_string(width) + "x" +
                              std::to_string(height)};
  FramePixels frame;
  frame.width = width;
  frame.height = height;
  frame.layout = edgetrack::PixelLayout::kRgb565;
  frame.bytes = std::move(loaded).value();
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  for (size_t i = 0; i < expected; i += 2) std::swap(frame.bytes[i], frame.bytes[i + 1]);
#endif
  return frame;
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

void average_blocks(const uint8_t* in, int width, int height, int channels, int factor, uint8_t* out) {
  const int out_width = width / factor, out_height = height / factor, n = factor * factor;
  const size_t row = static_cast<size_t>(width) * channels;
  for (int y = 0; y < out_height; ++y)
    for (int x = 0; x < out_width; ++x)
      for (int c = 0; c < channels; ++c) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy)
          for (int dx = 0; dx < factor; ++dx)
            sum += in[(static_cast<size_t>(y) * factor + dy) * row + (static_cast<size_t>(x) * factor + dx) * channels + c];
        out[(static_cast<size_t>(y) * out_width + x) * channels + c] = static_cast<uint8_t>((sum + n / 2) / n);
      }
}

RgbImage downscale(const RgbImage& image, int factor) {
  if (factor <= 1) return image;
  RgbImage out = make_image(image.width / factor, image.height / factor);
  average_blocks(image.rgb.data(), image.width, image.height, 3, factor, out.rgb.data());
  return out;
}

}  // namespace edgetrack_app
