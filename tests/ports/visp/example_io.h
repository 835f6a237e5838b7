// SPDX-License-Identifier: BSD-3-Clause
/// Input and output of the example programs, ViSP API only so that they build against upstream
/// too: the data set's place (VISP_INPUT_IMAGE_PATH when set, as upstream's examples, else the
/// build's EDGETRACK_VISP_IMAGES), its binary PGM
/// frames (standing in for upstream's vpImageIo::read, not ported), and the site listing.
#pragma once

#include <visp3/core/vpImage.h>
#include <visp3/me/vpMeSite.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <list>
#include <string>

namespace example {

inline std::string visp_images_path() {
  const char* env = std::getenv("VISP_INPUT_IMAGE_PATH");
  return env != nullptr ? std::string(env) + "/ViSP-images" : std::string(EDGETRACK_VISP_IMAGES);
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

/// True when the program was asked for the sites ("--sites").
inline bool wants_sites(int argc, char** argv) { return argc > 1 && std::strcmp(argv[1], "--sites") == 0; }

/// "site FRAME K STATE I J ALPHA" for every site of the list, in list order.
inline void print_sites(unsigned int frame, const std::list<vpMeSite>& list) {
  unsigned int k = 0;
  for (const vpMeSite& s : list) {
    std::printf("site %u %u %d %.6f %.6f %.6f\n", frame, k++, static_cast<int>(s.getState()),
                static_cast<double>(s.ifloat), static_cast<double>(s.jfloat), static_cast<double>(s.alpha));
  }
}

}  // namespace example
