// SPDX-License-Identifier: BSD-3-Clause
/// Viewpoints on a subdivided icosahedron, in-plane rotations and distances.
#include "edgetrack/detector/viewpoints.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace edgetrack {

namespace {

/// Adds `v` unless a direction within 1e-3 of it is there already; returns its index.
int add_unique(std::vector<Vec3>& directions, const Vec3& v) {
  using std::fabs;
  const real tolerance = real(1e-3);
  for (size_t i = 0; i < directions.size(); ++i) {
    const Vec3 d = directions[i] - v;
    if (fabs(d.x) < tolerance && fabs(d.y) < tolerance && fabs(d.z) < tolerance) return static_cast<int>(i);
  }
  directions.push_back(v);
  return static_cast<int>(directions.size() - 1);
}

struct Face3 {
  int a, b, c;
};

/// The 20 faces of the icosahedron on `v`: the triples of vertices at the edge length apart.
std::vector<Face3> icosahedron_faces(const std::vector<Vec3>& v, const real& edge) {
  using std::fabs;
  auto adjacent = [&](int i, int j) { return fabs(norm(v[i] - v[j]) - edge) < real(0.01); };
  std::vector<Face3> faces;
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k)
        if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) faces.push_back({i, j, k});
  return faces;
}

}  // namespace

ModelExtent model_extent(const EdgeModel& model) {
  ModelExtent extent;
  if (model.vertices.empty()) return extent;
  Vec3 low = model.vertices[0], high = model.vertices[0];
  for (const Vec3& p : model.vertices) {
    low = {p.x < low.x ? p.x : low.x, p.y < low.y ? p.y : low.y, p.z < low.z ? p.z : low.z};
    high = {p.x > high.x ? p.x : high.x, p.y > high.y ? p.y : high.y, p.z > high.z ? p.z : high.z};
  }
  extent.centre = real(0.5) * (low + high);
  for (const Vec3& p : model.vertices) {
    const real r = norm(p - extent.centre);
    if (r > extent.radius) extent.radius = r;
  }
  return extent;
}

std::vector<Vec3> sphere_directions(int subdivisions) {
  const real phi = real(1.618033988749895);
  std::vector<Vec3> v;
  for (int s1 = -1; s1 <= 1; s1 += 2) {
    for (int s2 = -1; s2 <= 1; s2 += 2) {
      v.push_back(normalized(Vec3{real(0), real(s1), real(s2) * phi}));
      v.push_back(normalized(Vec3{real(s1), real(s2) * phi, real(0)}));
      v.push_back(normalized(Vec3{real(s2) * phi, real(0), real(s1)}));
    }
  }
  std::vector<Face3> faces = icosahedron_faces(v, real(2) / norm(Vec3{real(0), real(1), phi}));
  for (int level = 0; level < subdivisions; ++level) {
    std::vector<Face3> finer;
    for (const Face3& f : faces) {
      const int ab = add_unique(v, normalized(v[f.a] + v[f.b]));
      const int bc = add_unique(v, normalized(v[f.b] + v[f.c]));
      const int ca = add_unique(v, normalized(v[f.c] + v[f.a]));
      finer.push_back({f.a, ab, ca});
      finer.push_back({f.b, bc, ab});
      finer.push_back({f.c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = finer;
  }
  return v;
}

namespace {

real smaller_focal(const PinholeCamera& camera) { return camera.px < camera.py ? camera.px : camera.py; }

}  // namespace

void span_distances(const PinholeCamera& camera, const ModelExtent& extent, const real& largest_share,
                    const real& smallest_share, real& nearest, real& farthest) {
  const int side = camera.width < camera.height ? camera.width : camera.height;
  const real focal = smaller_focal(camera);
  nearest = focal * real(2) * extent.radius / (largest_share * real(side));
  farthest = focal * real(2) * extent.radius / (smallest_share * real(side));
}

ViewRange auto_init_views(const PinholeCamera& camera, const ModelExtent& extent) {
  ViewRange views;
  span_distances(camera, extent, real(1), real(0.1), views.distance_min, views.distance_max);
  return views;
}

namespace {

/// The range's nearest and farthest distances, the defaults resolved.
void distance_bounds(const ViewRange& range, const PinholeCamera& camera, const ModelExtent& extent, real& low,
                     real& high) {
  low = range.distance_min;
  high = range.distance_max;
  if (low == real(0)) span_distances(camera, extent, real(0.8), real(0.4), low, high);
}

/// The directions of sphere_directions within the range's cone.
std::vector<Vec3> cone_directions(const ViewRange& range) {
  using std::acos;
  const Vec3 axis = normalized(range.axis);
  std::vector<Vec3> kept;
  for (const Vec3& d : sphere_directions(range.subdivisions)) {
    const real c = dot(d, axis);
    if (acos(c < real(-1) ? real(-1) : c > real(1) ? real(1) : c) <= range.max_angle + real(1e-6)) kept.push_back(d);
  }
  return kept;
}

std::string metres(const real& value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", static_cast<double>(value));
  return text;
}

}  // namespace

Result<long long> checked_view_count(const ViewRange& range, const PinholeCamera& camera, const ModelExtent& extent) {
  real low, high;
  distance_bounds(range, camera, extent, low, high);
  if (!(low > extent.radius))
    return Error{"", 0, "the nearest distance " + metres(low) + " puts the camera inside the model (within " +
                            metres(extent.radius) + " of its centre)"};
  if (smaller_focal(camera) * real(2) * extent.radius < real(kMinModelPixels) * high)
    return Error{"", 0, "at the farthest distance " + metres(high) + " the model spans under " +
                            std::to_string(kMinModelPixels) + " pixels"};
  long long distances = 0;
  using std::sqrt;
  const real end = high * sqrt(range.distance_ratio);
  for (real d = low; (d <= end || distances == 0) && distances <= kMaxTemplateViews; d = d * range.distance_ratio)
    ++distances;
  const long long directions = static_cast<long long>(cone_directions(range).size());
  const long long views = distances * directions * range.in_plane_steps;
  if (views > kMaxTemplateViews)
    return Error{"", 0, "the range asks for " + std::string(distances > kMaxTemplateViews ? "over " : "") +
                            std::to_string(views) + " views (" + std::to_string(distances) + " distances x " +
                            std::to_string(directions) + " directions x " + std::to_string(range.in_plane_steps) +
                            " in-plane steps), more than the " + std::to_string(kMaxTemplateViews) +
                            " a template file holds"};
  return views;
}

std::vector<real> view_distances(const ViewRange& range, const PinholeCamera& camera, const ModelExtent& extent) {
  real low, high;
  distance_bounds(range, camera, extent, low, high);
  std::vector<real> distances;
  using std::sqrt;
  const real overshoot = sqrt(range.distance_ratio);
  for (real d = low; d <= high * overshoot || distances.empty(); d = d * range.distance_ratio) distances.push_back(d);
  return distances;
}

Se3 view_pose(const Vec3& direction, const real& in_plane, const real& distance, const Vec3& centre) {
  using std::cos;
  using std::fabs;
  using std::sin;
  const Vec3 z = -direction;
  const Vec3 up = fabs(z.z) < real(0.9) ? Vec3{real(0), real(0), real(1)} : Vec3{real(1), real(0), real(0)};
  const Vec3 x = normalized(cross(up, z));
  const Vec3 y = cross(z, x);
  const real c = cos(in_plane), s = sin(in_plane);
  const Vec3 xr = c * x - s * y, yr = s * x + c * y;  // the image turned by in_plane about the optical axis
  Mat33 rotation;
  const Vec3 rows[3] = {xr, yr, z};
  for (int r = 0; r < 3; ++r) {
    rotation.m[r][0] = rows[r].x;
    rotation.m[r][1] = rows[r].y;
    rotation.m[r][2] = rows[r].z;
  }
  const Vec3 translation = Vec3{real(0), real(0), distance} - rotation * centre;
  return Se3(rotation, translation);
}

std::vector<ViewPose> view_poses(const ViewRange& range, const PinholeCamera& camera, const ModelExtent& extent) {
  const real two_pi = real(6.283185307179586);
  const std::vector<Vec3> kept = cone_directions(range);
  std::vector<ViewPose> poses;
  const std::vector<real> distances = view_distances(range, camera, extent);
  for (size_t d = 0; d < distances.size(); ++d)
    for (const Vec3& direction : kept)
      for (int k = 0; k < range.in_plane_steps; ++k)
        poses.push_back({view_pose(direction, two_pi * real(k) / real(range.in_plane_steps), distances[d], extent.centre),
                         static_cast<int>(d)});
  return poses;
}

}  // namespace edgetrack
