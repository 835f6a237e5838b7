// SPDX-License-Identifier: BSD-3-Clause
/// Moving-edge sites on real images, written against ViSP 3.5's ME API only. It is built twice,
/// against Debian's ViSP (me_sites_upstream) and against ports/visp (me_sites_ports), and the
/// two run as separate processes, so the two libraries' identical class names never meet.
/// me_compare runs both and compares their output.
///
///   me_sites masks SIZE NMASK        prints every mask weight
///   me_sites defaults                prints vpMe's default parameters
///   me_sites track RANGE PATTERN FIRST LAST SEGMENT...
///       sites every SPACING px along each segment "i1,j1,i2,j2,SPACING" of frame FIRST, snapped
///       with track(I, &me, false), then tracked frame to frame with track(I, &me) while kept;
///       prints "frame site state ifloat jfloat" for every site and frame.
///   me_sites bench RANGE PGM REPEATS SEGMENT...   prints nanoseconds per track() call
///   me_sites grey                    prints "r g b grey" of RGB24 to grey for a grid of colours
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/me/vpMe.h>
#include <visp3/me/vpMeSite.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

bool read_pgm(const std::string& path, vpImage<unsigned char>& image) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return false;
  unsigned int width = 0, height = 0, max_value = 0;
  const bool header = std::fscanf(file, "P5 %u %u %u", &width, &height, &max_value) == 3 && max_value == 255;
  if (!header || std::fgetc(file) == EOF) {
    std::fclose(file);
    return false;
  }
  image.resize(height, width);
  const bool ok = std::fread(image.bitmap, 1, image.getSize(), file) == image.getSize();
  std::fclose(file);
  return ok;
}

std::string frame_path(const std::string& pattern, int frame) {
  char path[1024];
  std::snprintf(path, sizeof path, pattern.c_str(), frame);
  return path;
}

struct Seed {
  double i, j, alpha;
};

/// Sites every `spacing` pixels along each segment; alpha is the segment's normal angle.
std::vector<Seed> seeds_from(int argc, char** argv, int first_arg) {
  std::vector<Seed> seeds;
  for (int a = first_arg; a < argc; ++a) {
    double i1, j1, i2, j2, spacing;
    if (std::sscanf(argv[a], "%lf,%lf,%lf,%lf,%lf", &i1, &j1, &i2, &j2, &spacing) != 5 || spacing <= 0) {
      std::fprintf(stderr, "me_sites: bad segment '%s'\n", argv[a]);
      std::exit(2);
    }
    const double length = std::hypot(i2 - i1, j2 - j1);
    const double alpha = std::atan2(-(j2 - j1), i2 - i1);
    for (double t = 0; t <= length; t += spacing) {
      seeds.push_back({i1 + (i2 - i1) * t / length, j1 + (j2 - j1) * t / length, alpha});
    }
  }
  return seeds;
}

int print_masks(unsigned int size, unsigned int n_mask) {
  vpMe me;
  me.setMaskNumber(n_mask);
  me.setMaskSize(size);
  for (unsigned int k = 0; k < me.getMaskNumber(); ++k) {
    for (unsigned int a = 0; a < size; ++a) {
      std::printf("%u %u", k, a);
      for (unsigned int b = 0; b < size; ++b) std::printf(" %d", static_cast<int>(me.getMask()[k][a][b]));
      std::printf("\n");
    }
  }
  return 0;
}

int print_defaults() {
  vpMe me;
  std::printf("threshold %g\nmu1 %g\nmu2 %g\nmin_samplestep %g\nanglestep %u\nmask_sign %d\nrange %u\n",
              static_cast<double>(me.getThreshold()), static_cast<double>(me.getMu1()),
              static_cast<double>(me.getMu2()), static_cast<double>(me.getMinSampleStep()), me.getAngleStep(),
              me.getMaskSign(), me.getRange());
  std::printf("sample_step %g\nmask_size %u\nn_mask %u\nstrip %d\n", static_cast<double>(me.getSampleStep()),
              me.getMaskSize(), me.getMaskNumber(), me.getStrip());
  vpMeSite site;
  std::printf("site state %d weight %g mask_sign %d\n", static_cast<int>(site.getState()),
              static_cast<double>(site.getWeight()), site.mask_sign);
  return 0;
}

int track(unsigned int range, const std::string& pattern, int first, int last, const std::vector<Seed>& seeds) {
  vpMe me;
  me.setRange(range);
  vpImage<unsigned char> image;
  std::vector<vpMeSite> sites(seeds.size());
  for (int frame = first; frame <= last; ++frame) {
    if (!read_pgm(frame_path(pattern, frame), image)) {
      std::fprintf(stderr, "me_sites: cannot read %s\n", frame_path(pattern, frame).c_str());
      return 1;
    }
    for (std::size_t k = 0; k < sites.size(); ++k) {
      vpMeSite& site = sites[k];
      if (frame == first) {
        site.init(seeds[k].i, seeds[k].j, seeds[k].alpha);
        site.track(image, &me, false);
      } else if (site.getState() == vpMeSite::NO_SUPPRESSION) {
        site.track(image, &me, true);
      }
      std::printf("%d %zu %d %.6f %.6f\n", frame, k, static_cast<int>(site.getState()),
                  static_cast<double>(site.get_ifloat()), static_cast<double>(site.get_jfloat()));
    }
  }
  return 0;
}

int bench(unsigned int range, const std::string& pgm, int repeats, const std::vector<Seed>& seeds) {
  vpMe me;
  me.setRange(range);
  me.setMaskSize(5);
  vpImage<unsigned char> image;
  if (!read_pgm(pgm, image)) return 1;
  std::vector<vpMeSite> reference(seeds.size());
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    reference[k].init(seeds[k].i, seeds[k].j, seeds[k].alpha);
    reference[k].track(image, &me, false);
  }
  std::vector<vpMeSite> sites;
  long checksum = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) {
    sites = reference;
    for (vpMeSite& site : sites) {
      site.track(image, &me, true);
      checksum += site.get_i() + static_cast<int>(site.getState());
    }
  }
  const auto stop = std::chrono::steady_clock::now();
  const double ns = std::chrono::duration<double, std::nano>(stop - start).count();
  std::printf("ns_per_track %.1f sites %zu checksum %ld\n", ns / (static_cast<double>(repeats) * sites.size()),
              sites.size(), checksum);
  return 0;
}

/// RGB24 to grey through vpImageConvert::RGBToGrey for every colour of a 3 x 3 x 5 level grid.
int print_grey() {
  std::vector<unsigned char> rgb;
  for (int r = 0; r < 256; r += 3)
    for (int g = 0; g < 256; g += 3)
      for (int b = 0; b < 256; b += 5) rgb.insert(rgb.end(), {static_cast<unsigned char>(r),
                                                              static_cast<unsigned char>(g),
                                                              static_cast<unsigned char>(b)});
  const unsigned int n = static_cast<unsigned int>(rgb.size() / 3);
  std::vector<unsigned char> grey(n);
  vpImageConvert::RGBToGrey(rgb.data(), grey.data(), n);
  for (unsigned int k = 0; k < n; ++k) std::printf("%d %d %d %d\n", rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2], grey[k]);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "masks" && argc == 4) return print_masks(std::atoi(argv[2]), std::atoi(argv[3]));
  if (mode == "defaults") return print_defaults();
  if (mode == "grey") return print_grey();
  if (mode == "track" && argc >= 7) {
    return track(std::atoi(argv[2]), argv[3], std::atoi(argv[4]), std::atoi(argv[5]), seeds_from(argc, argv, 6));
  }
  if (mode == "bench" && argc >= 6) {
    return bench(std::atoi(argv[2]), argv[3], std::atoi(argv[4]), seeds_from(argc, argv, 5));
  }
  std::fprintf(stderr, "usage: me_sites masks SIZE NMASK | defaults | track RANGE PATTERN FIRST LAST SEGMENT... |"
                       " bench RANGE PGM REPEATS SEGMENT... | grey\n");
  return 2;
}
