// SPDX-License-Identifier: BSD-3-Clause
/// The lens's inverse on a grid, and each sample's place in the pinhole image.
#include "edgetrack/lens_resampling.h"

#include <algorithm>
#include <cmath>

namespace edgetrack {

LensResampling::LensResampling(const PinholeCamera& camera, int samples, int scale)
    : samples_(samples), width_(camera.width) {
  using std::fabs;
  using std::floor;
  // The lens's inverse at the nodes of a grid every kGrid pixels, interpolated between them
  // (within 0.02 px of the exact inverse for |k1| r^2 up to 0.3): Newton's method at every
  // sample of every pixel would take minutes under the emulator. A node where the lens has no
  // inverse (beyond its fold) sees nothing.
  constexpr int kGrid = 4;
  const int nodes_x = (camera.width - 1) / kGrid + 2, nodes_y = (camera.height - 1) / kGrid + 2;
  std::vector<Vec2> node(static_cast<size_t>(nodes_x) * nodes_y);
  std::vector<uint8_t> node_seen(node.size(), 0);
  real reach(0);  // the farthest a node moves back through the lens
  for (int j = 0; j < nodes_y; ++j)
    for (int i = 0; i < nodes_x; ++i) {
      const Vec2 seen{real(i * kGrid), real(j * kGrid)};
      const Vec2 d = camera.to_normalised(seen);
      const Vec2 n = camera.invert_distortion(d);
      const Vec2 miss = camera.distort(n) - d;
      const size_t k = static_cast<size_t>(j) * nodes_x + i;
      if (!(fabs(miss.x) + fabs(miss.y) < real(1e-4))) continue;
      node[k] = camera.to_pixel(n);
      node_seen[k] = 1;
      reach = std::max(reach, std::max(fabs(node[k].x - seen.x), fabs(node[k].y - seen.y)));
    }
  // The pinhole image grown by that margin reaches every point the lens shows.
  const int margin = std::min(static_cast<int>(reach) + 2, std::max(camera.width, camera.height));
  PinholeCamera wide = camera.pinhole();
  wide.u0 = wide.u0 + real(margin);
  wide.v0 = wide.v0 + real(margin);
  wide.width += 2 * margin;
  wide.height += 2 * margin;
  pinhole_ = wide.scaled(scale);
  const int pw = pinhole_.width, ph = pinhole_.height;
  const real shift(margin), to_scale(scale), scale_shift = real(scale - 1) / 2;
  samples_of_.assign(static_cast<size_t>(camera.width) * camera.height * samples * samples, Sample{});
  size_t index = 0;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x)
      for (int sy = 0; sy < samples; ++sy)
        for (int sx = 0; sx < samples; ++sx, ++index) {
          const Vec2 seen{real(x) + (real(sx) + real(0.5)) / real(samples) - real(0.5),
                          real(y) + (real(sy) + real(0.5)) / real(samples) - real(0.5)};
          const int i = std::max(0, std::min(nodes_x - 2, static_cast<int>(floor(seen.x / real(kGrid)))));
          const int j = std::max(0, std::min(nodes_y - 2, static_cast<int>(floor(seen.y / real(kGrid)))));
          const size_t k = static_cast<size_t>(j) * nodes_x + i;
          if (!(node_seen[k] && node_seen[k + 1] && node_seen[k + nodes_x] && node_seen[k + nodes_x + 1])) continue;
          const real fx = (seen.x - real(i * kGrid)) / real(kGrid);
          const real fy = (seen.y - real(j * kGrid)) / real(kGrid);
          const Vec2 top = node[k] + fx * (node[k + 1] - node[k]);
          const Vec2 bottom = node[k + nodes_x] + fx * (node[k + nodes_x + 1] - node[k + nodes_x]);
          const Vec2 pinhole = top + fy * (bottom - top);
          // The wide image's pixel, then the scaled one (PinholeCamera::scaled's mapping), read
          // bilinearly from its four neighbours (the nearest alone shifts edges by up to a
          // quarter pixel: measured, twice the wood toy's error).
          const real px = (pinhole.x + shift) * to_scale + scale_shift;
          const real py = (pinhole.y + shift) * to_scale + scale_shift;
          const int u = static_cast<int>(floor(px)), v = static_cast<int>(floor(py));
          if (u < 0 || v < 0 || u + 1 >= pw || v + 1 >= ph) continue;
          Sample& sample = samples_of_[index];
          sample.index = v * pw + u;
          sample.fx = static_cast<uint16_t>(floor((px - real(u)) * real(kWeightOne) + real(0.5)));
          sample.fy = static_cast<uint16_t>(floor((py - real(v)) * real(kWeightOne) + real(0.5)));
        }
}

}  // namespace edgetrack
