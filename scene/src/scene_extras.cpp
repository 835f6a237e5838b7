// SPDX-License-Identifier: BSD-3-Clause
/// Faster motion, a path there and back, a covering occluder and parallel-line clutter for the generated sequences.
#include "edgetrack/scene_extras.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/raster.h"

namespace edgetrack {

std::vector<Se3> faster_poses(const std::vector<Se3>& slow, const real& speed, int frames) {
  std::vector<Se3> fast;
  for (int k = 0; k < frames; ++k) {
    const real at = speed * real(k);
    const int before = static_cast<int>(at);  // at >= 0: truncation is floor
    if (before + 1 >= static_cast<int>(slow.size())) {
      if (before < static_cast<int>(slow.size()) && at == real(before)) fast.push_back(slow[static_cast<size_t>(before)]);
      break;
    }
    const real t = at - real(before);
    const Se3& a = slow[static_cast<size_t>(before)];
    const Twist step = (a.inverse() * slow[static_cast<size_t>(before) + 1]).log();
    fast.push_back(a * Se3::exp({t * step.v, t * step.w}));
  }
  return fast;
}

std::vector<Se3> there_and_back(const std::vector<Se3>& forward) {
  std::vector<Se3> poses(forward);
  for (size_t k = forward.size(); k-- > 1;) poses.push_back(forward[k - 1]);
  return poses;
}

void silhouette_columns(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                        std::vector<uint8_t>& mask, std::vector<int>& columns) {
  const int w = camera.width, h = camera.height;
  mask.assign(static_cast<size_t>(w) * h, 0);
  for (const Triangle& t : model.triangles) {
    const Vec3 corners[3] = {camera_from_model * model.vertices[t.a], camera_from_model * model.vertices[t.b],
                             camera_from_model * model.vertices[t.c]};
    ScreenVertex polygon[kMaxClippedVertices];
    const int n = clip_and_project_triangle(camera, corners, polygon);
    for (int i = 1; i + 1 < n; ++i)
      fill_triangle(polygon[0], polygon[i], polygon[i + 1], w, h,
                    [&](int x, int y, int32_t) { mask[static_cast<size_t>(y) * w + x] = 1; });
  }
  columns.assign(static_cast<size_t>(w), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) columns[static_cast<size_t>(x)] += mask[static_cast<size_t>(y) * w + x];
}

OccluderBand occluder_band(const std::vector<int>& columns, int centre, const real& share) {
  OccluderBand band;
  const int width = static_cast<int>(columns.size());
  int total = 0;
  for (int c : columns) total += c;
  if (total == 0 || width == 0) return band;
  centre = std::min(std::max(centre, 0), width - 1);
  band.x_begin = centre;
  band.x_end = centre + 1;
  int covered = columns[static_cast<size_t>(centre)];
  for (bool right = true; real(covered) < share * real(total); right = !right) {
    if (right && band.x_end < width) {
      covered += columns[static_cast<size_t>(band.x_end++)];
    } else if (!right && band.x_begin > 0) {
      covered += columns[static_cast<size_t>(--band.x_begin)];
    } else if (band.x_begin == 0 && band.x_end == width) {
      break;
    }
  }
  band.covered_share = real(covered) / real(total);
  return band;
}

int sweeping_centre(const std::vector<int>& columns, int k, int frames) {
  int first = -1, last = -1;
  for (int x = 0; x < static_cast<int>(columns.size()); ++x)
    if (columns[static_cast<size_t>(x)] > 0) {
      if (first < 0) first = x;
      last = x;
    }
  if (first < 0) return 0;
  const int span = last - first;
  const int steps = frames > 1 ? frames - 1 : 1;
  return first + span / 4 + span * k / (2 * steps);
}

std::vector<Segment3> parallel_clutter(const EdgeModel& model, const real& offset) {
  using std::fabs;
  Vec3 centre;
  for (const Vec3& v : model.vertices) centre = centre + v;
  if (!model.vertices.empty()) centre = (real(1) / real(static_cast<int>(model.vertices.size()))) * centre;
  std::vector<Segment3> clutter;
  for (const Edge& e : model.edges) {
    const Vec3 a = model.vertices[e.a], b = model.vertices[e.b];
    const Vec3 along = normalized(b - a);
    const Vec3 out = (real(0.5) * (a + b)) - centre;
    Vec3 across = out - dot(out, along) * along;
    // An edge through the centre has no outside: any direction across it will do.
    if (norm(across) <= real(1e-6)) across = cross(along, fabs(along.z) < real(0.9) ? Vec3{0, 0, 1} : Vec3{1, 0, 0});
    const Vec3 shift = offset * normalized(across);
    clutter.push_back({a + shift, b + shift});
  }
  return clutter;
}

real clutter_image_offset(const EdgeModel& model, const std::vector<Segment3>& clutter, const PinholeCamera& camera,
                          const Se3& camera_from_model) {
  real sum(0);
  int counted = 0;
  size_t line = 0;  // parallel_clutter's lines follow the model's edges, one each
  for (const Edge& e : model.edges) {
    if (line >= clutter.size()) break;
    const Vec3 a = camera_from_model * model.vertices[e.a], b = camera_from_model * model.vertices[e.b];
    const Vec3 m = camera_from_model * (real(0.5) * (clutter[line].a + clutter[line].b));
    ++line;
    if (a.z <= real(0) || b.z <= real(0) || m.z <= real(0)) continue;
    const Vec2 pa = camera.project(a), pb = camera.project(b), pm = camera.project(m);
    const Vec2 d = pb - pa;
    const real length = norm(d);
    if (length <= real(1)) continue;  // seen end-on: no direction to measure across
    const Vec2 normal{-d.y / length, d.x / length};
    const real across = dot(normal, pm - pa);
    sum += across < real(0) ? -across : across;
    ++counted;
  }
  return counted > 0 ? sum / real(counted) : real(0);
}

}  // namespace edgetrack
