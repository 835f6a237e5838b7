// SPDX-License-Identifier: BSD-3-Clause
/// The cone of the AR overlay and the portable overlay renderer.
#include "overlay.h"

#include <algorithm>
#include <cmath>

#include "edgetrack/angles.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/raster.h"

using edgetrack::EdgeModel;
using edgetrack::PinholeCamera;
using edgetrack::Se3;
using edgetrack::Vec3;

namespace edgetrack_app {
namespace {

Vec3 scaled(double s, const Vec3& v) { return real(s) * v; }

/// The overlay drawn with the tracker's integer rasteriser: the Edge-ID buffer gives the
/// visible edge pixels, its depth buffer hides the cone behind the model's faces.
class SoftOverlay : public Overlay {
 public:
  explicit SoftOverlay(const PinholeCamera& camera) : camera_(camera), edge_ids_(camera) {}

  RgbImage draw(const RgbImage& frame, const EdgeModel& model, const Se3& camera_from_model, const Cone& cone) override {
    edge_ids_.render(model, camera_from_model);
    RgbImage out = frame;
    std::vector<int32_t> depth;
    edge_ids_.surface_depth(depth);
    std::vector<uint8_t> covered(depth.size(), 0);
    const ConeMesh mesh = cone_mesh(cone, 32);
    const double light[3] = {0.45, -0.75, -0.5};
    const double light_norm = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
    for (size_t t = 0; t + 2 < mesh.corners.size(); t += 3) {
      const Vec3 in_camera[3] = {camera_from_model * mesh.corners[t], camera_from_model * mesh.corners[t + 1],
                                 camera_from_model * mesh.corners[t + 2]};
      const Vec3 n = edgetrack::normalized(camera_from_model.rotation() *
                                           (mesh.normals[t] + mesh.normals[t + 1] + mesh.normals[t + 2]));
      const double lambert = std::max(0.0, (static_cast<double>(n.x) * light[0] + static_cast<double>(n.y) * light[1] +
                                            static_cast<double>(n.z) * light[2]) / light_norm);
      const double shade = std::min(1.0, 0.3 + 0.75 * lambert);
      const uint8_t colour[3] = {static_cast<uint8_t>(242 * shade), static_cast<uint8_t>(115 * shade),
                                 static_cast<uint8_t>(26 * shade)};
      edgetrack::ScreenVertex v[edgetrack::kMaxClippedVertices];
      const int count = edgetrack::clip_and_project_triangle(camera_, in_camera, v);
      for (int i = 1; i + 1 < count; ++i)
        edgetrack::fill_triangle(v[0], v[i], v[i + 1], camera_.width, camera_.height, [&](int x, int y, int32_t w) {
          const size_t at = static_cast<size_t>(y) * camera_.width + x;
          if (w < depth[at]) return;
          depth[at] = w;
          covered[at] = 1;
          std::copy(colour, colour + 3, out.pixel(x, y));
        });
    }
    for (int y = 0; y < camera_.height; ++y)
      for (int x = 0; x < camera_.width; ++x) {
        const size_t at = static_cast<size_t>(y) * camera_.width + x;
        if (edge_ids_.edge_at(x, y) < 0 || covered[at]) continue;
        uint8_t* p = &out.rgb[at * 3];
        p[0] = 26;
        p[1] = 255;
        p[2] = 51;
      }
    return out;
  }

 private:
  PinholeCamera camera_;
  edgetrack::EdgeIdBuffer edge_ids_;
};

}  // namespace

void plane_axes(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 helper = std::fabs(static_cast<double>(n.x)) < 0.9 ? Vec3{real(1), real(0), real(0)} : Vec3{real(0), real(1), real(0)};
  u = edgetrack::normalized(edgetrack::cross(helper, n));
  v = edgetrack::cross(n, u);
}

Cone cone_on_top_face(const EdgeModel& model, const Se3& camera_from_model) {
  Cone cone;
  int best = -1;
  double best_up = -2;
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const Vec3 n_in_camera = camera_from_model.rotation() * model.faces[f].normal;
    const double up = -static_cast<double>(n_in_camera.y);
    if (up > best_up) {
      best_up = up;
      best = static_cast<int>(f);
    }
  }
  if (best < 0) return cone;
  const edgetrack::Face& face = model.faces[best];
  Vec3 centre;
  for (int i : face.vertices) centre = centre + model.vertices[i];
  centre = real(1.0 / face.vertices.size()) * centre;
  double nearest_side = 1e9;
  for (size_t i = 0; i < face.vertices.size(); ++i) {
    const Vec3 a = model.vertices[face.vertices[i]], b = model.vertices[face.vertices[(i + 1) % face.vertices.size()]];
    const Vec3 d = edgetrack::normalized(b - a);
    const Vec3 off = (centre - a) - edgetrack::dot(centre - a, d) * d;
    nearest_side = std::min(nearest_side, static_cast<double>(edgetrack::norm(off)));
  }
  cone.base_centre = centre;
  cone.axis = face.normal;
  cone.radius = 0.6 * nearest_side;
  cone.height = 2.2 * cone.radius;
  return cone;
}

ConeMesh cone_mesh(const Cone& cone, int sides) {
  ConeMesh mesh;
  if (cone.radius <= 0) return mesh;
  Vec3 u, v;
  plane_axes(cone.axis, u, v);
  const Vec3 apex = cone.base_centre + scaled(cone.height, cone.axis);
  const double slope = cone.radius / cone.height;
  auto rim = [&](double a) { return cone.base_centre + scaled(cone.radius * std::cos(a), u) + scaled(cone.radius * std::sin(a), v); };
  auto side = [&](double a) { return edgetrack::normalized(scaled(std::cos(a), u) + scaled(std::sin(a), v) + scaled(slope, cone.axis)); };
  for (int i = 0; i < sides; ++i) {
    const double a0 = 2 * edgetrack::kPi * i / sides, a1 = 2 * edgetrack::kPi * (i + 1) / sides;
    mesh.corners.insert(mesh.corners.end(), {apex, rim(a0), rim(a1), cone.base_centre, rim(a1), rim(a0)});
    mesh.normals.insert(mesh.normals.end(), {side((a0 + a1) / 2), side(a0), side(a1), -cone.axis, -cone.axis, -cone.axis});
  }
  return mesh;
}

std::unique_ptr<Overlay> make_soft_overlay(const PinholeCamera& camera) {
  return std::unique_ptr<Overlay>(new SoftOverlay(camera));
}

}  // namespace edgetrack_app
