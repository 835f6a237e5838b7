// SPDX-License-Identifier: BSD-3-Clause
/// Generated detection trials (detection_scene.h).
#include "detection_scene.h"

#include <cmath>
#include <random>

#include "edgetrack/detector/viewpoints.h"

using namespace edgetrack;

namespace edgetrack_test {

namespace {

double uniform(std::mt19937& rng, double low, double high) {
  return low + (high - low) * (static_cast<double>(rng() - rng.min()) / (static_cast<double>(rng.max() - rng.min()) + 1.0));
}

/// A unit direction uniformly inside the cone of `angle` radians about `axis`.
Vec3 direction_in_cone(std::mt19937& rng, const Vec3& axis, double angle) {
  const double cos_min = std::cos(angle);
  const double z = uniform(rng, cos_min, 1.0), phi = uniform(rng, 0, 2 * M_PI), r = std::sqrt(1 - z * z);
  const Vec3 a = normalized(axis);
  const Vec3 helper = std::fabs(static_cast<double>(a.z)) < 0.9 ? Vec3{real(0), real(0), real(1)} : Vec3{real(1), real(0), real(0)};
  const Vec3 u = normalized(cross(helper, a)), v = cross(a, u);
  return normalized(real(r * std::cos(phi)) * u + real(r * std::sin(phi)) * v + real(z) * a);
}

bool in_view(const EdgeModel& model, const PinholeCamera& camera, const Se3& pose, int margin) {
  for (const Vec3& p : model.vertices) {
    const Vec3 c = pose * p;
    if (c.z <= real(0.01)) return false;
    const Vec2 uv = camera.project(c);
    if (uv.x < real(margin) || uv.y < real(margin) || uv.x > real(camera.width - 1 - margin) ||
        uv.y > real(camera.height - 1 - margin))
      return false;
  }
  return true;
}

}  // namespace

std::vector<Mat33> cube_symmetries() {
  static const int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  std::vector<Mat33> rotations;
  for (int p = 0; p < 6; ++p) {
    for (int signs = 0; signs < 8; ++signs) {
      Mat33 m;
      for (int row = 0; row < 3; ++row) m.m[row][kPermutations[p][row]] = real((signs >> row) & 1 ? -1 : 1);
      const double det = static_cast<double>(m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
                                             m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
                                             m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]));
      if (det > 0) rotations.push_back(m);
    }
  }
  return rotations;
}

PoseError pose_error(const Se3& estimate, const Se3& truth, const Vec3& centre, const std::vector<Mat33>& symmetries) {
  // In double: squares of millimetres in metres are below S40.23's resolution.
  PoseError error;
  const Vec3 a = estimate * centre, b = truth * centre;
  const double dx = static_cast<double>(a.x) - static_cast<double>(b.x), dy = static_cast<double>(a.y) - static_cast<double>(b.y),
               dz = static_cast<double>(a.z) - static_cast<double>(b.z);
  error.centre_mm = 1000 * std::sqrt(dx * dx + dy * dy + dz * dz);
  error.rotation_deg = 360;
  for (const Mat33& s : symmetries) {
    // The angle of R_est^T R_true S: trace = 1 + 2 cos(angle).
    double trace = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double ts = 0;
        for (int k = 0; k < 3; ++k) ts += static_cast<double>(truth.rotation().m[j][k]) * static_cast<double>(s.m[k][i]);
        trace += static_cast<double>(estimate.rotation().m[j][i]) * ts;
      }
    const double c = std::fmax(-1.0, std::fmin(1.0, (trace - 1) / 2));
    error.rotation_deg = std::fmin(error.rotation_deg, std::acos(c) * 180 / M_PI);
  }
  return error;
}

Se3 random_view(const EdgeModel& model, const PinholeCamera& camera, const ViewRange& range, uint32_t seed) {
  std::mt19937 rng(seed);
  const ModelExtent extent = model_extent(model);
  const std::vector<real> distances = view_distances(range, camera, extent);
  const double near = static_cast<double>(distances.front()), far = static_cast<double>(distances.back());
  for (;;) {
    const Vec3 direction = direction_in_cone(rng, range.axis, static_cast<double>(range.max_angle));
    const double distance = near * std::pow(far / near, uniform(rng, 0, 1));
    const Se3 centred = view_pose(direction, real(uniform(rng, 0, 2 * M_PI)), real(distance), extent.centre);
    // Move the centre's image to a random pixel: turn the camera about its centre.
    const Vec2 pixel{real(uniform(rng, 0.2, 0.8) * camera.width), real(uniform(rng, 0.2, 0.8) * camera.height)};
    const Vec3 ray = normalized(camera.unproject(pixel, real(1)));
    const Vec3 axis{-ray.y, ray.x, real(0)};
    const double sine = static_cast<double>(norm(axis));
    const Mat33 turn = sine > 0 ? rotation_exp(real(std::atan2(sine, static_cast<double>(ray.z)) / sine) * axis)
                                : Mat33::identity();
    const Mat33 rotation = turn * centred.rotation();
    const Se3 pose(rotation, real(distance) * ray - rotation * extent.centre);
    if (in_view(model, camera, pose, 8)) return pose;
  }
}

std::vector<Segment3> background_lines(const EdgeModel& model, const Se3& camera_from_model, int count, uint32_t seed) {
  std::mt19937 rng(seed * 2654435761u + 17);
  const ModelExtent extent = model_extent(model);
  const Vec3 towards_camera = normalized(camera_from_model.inverse().translation() - extent.centre);
  const double r = static_cast<double>(extent.radius);
  std::vector<Segment3> lines;
  while (static_cast<int>(lines.size()) < count) {
    Vec3 offset = direction_in_cone(rng, -towards_camera, M_PI / 2 * 0.95);
    const Vec3 a = extent.centre + real(uniform(rng, 1.5, 4.0) * r) * offset;
    const Vec3 along = direction_in_cone(rng, Vec3{real(0), real(0), real(1)}, M_PI);
    const Vec3 b = a + real(uniform(rng, 0.5, 2.0) * r) * along;
    const real behind = real(-0.5) * extent.radius;
    if (dot(a - extent.centre, towards_camera) > behind || dot(b - extent.centre, towards_camera) > behind) continue;
    lines.push_back({a, b});
  }
  return lines;
}

void render_trial(const EdgeModel& model, const PinholeCamera& camera, const Se3& pose, bool with_object, int lines,
                  uint32_t seed, Rgb565Frame& frame) {
  SceneStyle style;
  style.texture_seed = seed;
  SceneRenderer renderer(camera, style);
  const std::vector<Segment3> clutter = background_lines(model, pose, lines, seed);
  SceneAdditions additions;
  additions.clutter = &clutter;
  const EdgeModel nothing;
  renderer.render(with_object ? model : nothing, pose, seed + 1, additions, frame);
}

TemplateParams oblique_range() {
  TemplateParams params;
  params.views.axis = normalized(Vec3{real(0.5), real(-0.6), real(1)});
  params.views.max_angle = real(25.0 * 3.141592653589793 / 180);
  params.views.distance_min = real(0.14);
  params.views.distance_max = real(0.17);
  return params;
}

}  // namespace edgetrack_test
