// SPDX-License-Identifier: BSD-3-Clause
/// Count windows for the moving edges on the emulated PXA270 (toolchains/qemu/count-insns.sh):
///   me_insns sites PGM      one window per vpMeSite::track() (range 7, mask 5) on the cube's
///                           straight edges, after a first track(I, &me, false) outside windows
///   me_insns convert PGM    the PGM halved to QVGA and stored as RGB565; window 1 converts the
///                           whole frame to grey, window 2 only the tiles the sites read
///                           (vpGreyOnDemand), then both grey images are tracked and compared.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "count_markers.h"
#include "visp3/core/vpImageConvert.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeSite.h"

namespace {

bool read_pgm(const char* path, vpImage<unsigned char>& image) {
  FILE* file = std::fopen(path, "rb");
  if (file == nullptr) return false;
  unsigned int width = 0, height = 0, max_value = 0;
  const bool ok = std::fscanf(file, "P5 %u %u %u", &width, &height, &max_value) == 3 && std::fgetc(file) != EOF;
  if (ok) image.resize(height, width);
  const bool read = ok && std::fread(image.bitmap, 1, image.getSize(), file) == image.getSize();
  std::fclose(file);
  return read;
}

/// Sites every 5 px on the straight edges of mbt/cube's first frame (640x480), scaled by `scale`.
std::vector<vpMeSite> cube_sites(double scale) {
  static const double kSegments[][4] = {
      {228, 316, 205, 385}, {205, 385, 238, 430}, {232, 318, 250, 355}, {250, 355, 238, 430},
      {250, 355, 348, 358}, {238, 430, 318, 445}, {348, 358, 320, 445}, {232, 318, 330, 330}};
  std::vector<vpMeSite> sites;
  for (const auto& s : kSegments) {
    const double di = (s[2] - s[0]) * scale, dj = (s[3] - s[1]) * scale;
    const double length = std::hypot(di, dj), alpha = std::atan2(-dj, di);
    for (double t = 0; t <= length; t += 5) {
      vpMeSite site;
      site.init(real(s[0] * scale + di * t / length), real(s[1] * scale + dj * t / length), real(alpha));
      sites.push_back(site);
    }
  }
  return sites;
}

int sites_mode(const vpImage<unsigned char>& image) {
  vpMe me;
  me.setRange(7);
  me.setMaskSize(5);
  std::vector<vpMeSite> sites = cube_sites(1.0);
  for (vpMeSite& site : sites) site.track(image, &me, false);
  int kept = 0;
  for (vpMeSite& site : sites) {
    edgetrack_count_begin();
    site.track(image, &me, true);
    edgetrack_count_end();
    kept += site.getState() == vpMeSite::NO_SUPPRESSION;
  }
  std::printf("sites %zu kept %d\n", sites.size(), kept);
  return 0;
}

int convert_mode(const vpImage<unsigned char>& full) {
  vpImage<uint16_t> frame(full.getHeight() / 2, full.getWidth() / 2);
  for (unsigned int i = 0; i < frame.getHeight(); ++i) {
    for (unsigned int j = 0; j < frame.getWidth(); ++j) {
      const unsigned int g = full[2 * i][2 * j];
      frame[i][j] = static_cast<uint16_t>(((g >> 3) << 11) | ((g >> 2) << 5) | (g >> 3));
    }
  }
  vpMe me;
  me.setRange(7);
  me.setMaskSize(5);
  std::vector<vpMeSite> sites = cube_sites(0.5);

  vpImage<unsigned char> grey;
  edgetrack_count_begin();
  vpImageConvert::RGB565ToGrey(frame, grey);
  edgetrack_count_end();

  vpGreyOnDemand on_demand;
  edgetrack_count_begin();
  on_demand.setFrame(frame);
  for (const vpMeSite& site : sites) {
    int top, left, bottom, right;
    site.getSearchBox(&me, top, left, bottom, right);
    on_demand.require(top, left, bottom, right);
  }
  edgetrack_count_end();

  std::vector<vpMeSite> a = sites, b = sites;
  int same = 0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    a[k].track(grey, &me, false);
    b[k].track(on_demand.grey(), &me, false);
    same += a[k].getState() == b[k].getState() && a[k].ifloat == b[k].ifloat && a[k].jfloat == b[k].jfloat;
  }
  std::printf("frame %ux%u sites %zu converted_on_demand %u of %u same_results %d\n", frame.getWidth(),
              frame.getHeight(), sites.size(), on_demand.convertedPixels(), frame.getSize(), same);
  return same == static_cast<int>(sites.size()) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  vpImage<unsigned char> image;
  if (argc != 3 || !read_pgm(argv[2], image)) {
    std::fprintf(stderr, "usage: me_insns sites|convert PGM\n");
    return 2;
  }
  if (std::strcmp(argv[1], "sites") == 0) return sites_mode(image);
  if (std::strcmp(argv[1], "convert") == 0) return convert_mode(image);
  return 2;
}
