// SPDX-License-Identifier: BSD-3-Clause
/// Reads the binary PGM frames of ViSP's image data set for the example programs, which stand
/// in for upstream's vpImageIo::read (not ported). ViSP API only, so that the examples build
/// against upstream too. Also finds the data set: VISP_INPUT_IMAGE_PATH, as upstream's examples.
#pragma once

#include <visp3/core/vpImage.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace example {

inline std::string visp_images_path() {
  const char* env = std::getenv("VISP_INPUT_IMAGE_PATH");
  return std::string(env != nullptr ? env : "/usr/share/visp-images-data") + "/ViSP-images";
}

/// "<dir>/image.NNNN.pgm", as upstream's examples name their frames.
inline std::string frame_path(const std::string& dir, unsigned int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "/image.%04u.pgm", frame);
  return dir + name;
}

/// False (after one line on stderr naming the file) when the file is not an 8-bit binary PGM.
inline bool read_pgm(const std::string& path, vpImage<unsigned char>& image) {
  FILE* file = std::fopen(path.c_str(), "rb");
  unsigned int width = 0, height = 0, max_value = 0;
  bool ok = file != nullptr && std::fscanf(file, "P5 %u %u %u", &width, &height, &max_value) == 3 &&
            max_value == 255 && std::fgetc(file) != EOF;
  if (ok) {
    image.resize(height, width);
    ok = std::fread(image.bitmap, 1, image.getSize(), file) == image.getSize();
  }
  if (file != nullptr) std::fclose(file);
  if (!ok) std::fprintf(stderr, "%s: not a readable 8-bit binary PGM\n", path.c_str());
  return ok;
}

}  // namespace example
