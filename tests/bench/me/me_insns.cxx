// SPDX-License-Identifier: BSD-3-Clause
/// Count windows for the moving edges on the emulated PXA270 (toolchains/qemu/count-insns.sh):
///   me_insns sites PGM      one window per vpMeSite::track() (range 7, mask 5) on the cube's
///                           straight edges, after a first track(I, &me, false) outside windows
///   me_insns convert PGM    the PGM halved to QVGA and stored as RGB565, converted as the tracker's
///                           grey step does (grey_conversion.h): window 1 the whole frame
///                           (GreyScaling::kWholeFrame), window 2 only the read boxes of control
///                           points on the cube's edges (me_search_box.h, BoxGreyScaler: the
///                           default kOnDemand); the moving edges then search both grey images and
///                           the matches are compared.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "count_markers.h"
#include "edgetrack/grey_conversion.h"
#include "edgetrack/moving_edges.h"
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

/// The straight edges of mbt/cube's first frame (640x480): row and column of each end.
constexpr double kSegments[][4] = {
    {228, 316, 205, 385}, {205, 385, 238, 430}, {232, 318, 250, 355}, {250, 355, 238, 430},
    {250, 355, 348, 358}, {238, 430, 318, 445}, {348, 358, 320, 445}, {232, 318, 330, 330}};

/// Sites every 5 px on those edges, scaled by `scale`.
std::vector<vpMeSite> cube_sites(double scale) {
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

/// Control points every 5 px on the same edges, scaled by `scale`, as the tracker samples them:
/// the edge's unit direction and the normal turned +90 degrees from it (x along columns).
std::vector<edgetrack::ControlPoint> cube_points(double scale) {
  std::vector<edgetrack::ControlPoint> points;
  for (const auto& s : kSegments) {
    const double di = (s[2] - s[0]) * scale, dj = (s[3] - s[1]) * scale;
    const double length = std::hypot(di, dj);
    for (double t = 0; t <= length; t += 5) {
      edgetrack::ControlPoint point;
      point.pixel = edgetrack::Vec2{real(s[1] * scale + dj * t / length), real(s[0] * scale + di * t / length)};
      point.direction = edgetrack::Vec2{real(dj / length), real(di / length)};
      point.normal = edgetrack::Vec2{-point.direction.y, point.direction.x};
      points.push_back(point);
    }
  }
  return points;
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
  const int width = static_cast<int>(full.getWidth() / 2), height = static_cast<int>(full.getHeight() / 2);
  std::vector<uint16_t> rgb565(static_cast<std::size_t>(width) * height);
  for (int i = 0; i < height; ++i) {
    for (int j = 0; j < width; ++j) {
      const unsigned int g = full[2 * i][2 * j];
      rgb565[static_cast<std::size_t>(i) * width + j] = static_cast<uint16_t>(((g >> 3) << 11) | ((g >> 2) << 5) | (g >> 3));
    }
  }
  const edgetrack::FrameView frame = edgetrack::packed_frame(rgb565.data(), width, height, edgetrack::PixelLayout::kRgb565);
  edgetrack::MovingEdgeParams params;
  params.mask_size = 5;
  const vpMe me = edgetrack::moving_edge_masks(params);
  const unsigned int range = 7;
  const std::vector<edgetrack::ControlPoint> points = cube_points(0.5);

  vpImage<unsigned char> whole(static_cast<unsigned>(height), static_cast<unsigned>(width));
  edgetrack_count_begin();
  const unsigned int whole_pixels = edgetrack::convert_to_grey(frame, edgetrack::PixelBox{0, 0, height, width}, whole);
  edgetrack_count_end();

  vpImage<unsigned char> boxes(static_cast<unsigned>(height), static_cast<unsigned>(width));
  edgetrack::BoxGreyScaler scaler;
  edgetrack_count_begin();
  scaler.clear();
  for (const edgetrack::ControlPoint& point : points) scaler.add(edgetrack::me_search_box(point, me, range));
  const unsigned int box_pixels = scaler.convert(frame, boxes);
  edgetrack_count_end();

  const auto a = edgetrack::search_moving_edges(whole, points, me, range);
  const auto b = edgetrack::search_moving_edges(boxes, points, me, range);
  bool same = a.size() == b.size();
  for (std::size_t k = 0; same && k < a.size(); ++k)
    same = a[k].found.x == b[k].found.x && a[k].found.y == b[k].found.y && a[k].contrast == b[k].contrast;
  std::printf("frame %dx%d points %zu converted_on_demand %u of %u matches %zu same_matches %s\n", width, height,
              points.size(), box_pixels, whole_pixels, a.size(), same ? "yes" : "no");
  return same ? 0 : 1;
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
