// SPDX-License-Identifier: BSD-3-Clause
/// OSMesa rendering of synthetic scenes and of the AR overlay.
#include "gl_renderer.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "edgetrack/contours.h"

using edgetrack::EdgeModel;
using edgetrack::Error;
using edgetrack::PinholeCamera;
using edgetrack::Result;
using edgetrack::Se3;
using edgetrack::Vec3;

namespace edgetrack_app {

void vertex(const Vec3& p) { glVertex3d(static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z)); }
void normal(const Vec3& n) { glNormal3d(static_cast<double>(n.x), static_cast<double>(n.y), static_cast<double>(n.z)); }

namespace {

constexpr double kNear = 0.01;  ///< metres
constexpr double kFar = 10.0;


Vec3 scaled(double s, const Vec3& v) { return real(s) * v; }

}  // namespace

void load_pinhole_projection(const PinholeCamera& camera) {
  // Image row v goes to GL row v (buffers are read back bottom row first, which is image row 0),
  // so the pinhole model needs no flip: x_ndc = 2 (u + 0.5) / W - 1 with u = u0 + px X / Z.
  const double w = camera.width, h = camera.height;
  const double px = static_cast<double>(camera.px), py = static_cast<double>(camera.py);
  const double u0 = static_cast<double>(camera.u0), v0 = static_cast<double>(camera.v0);
  const double projection[16] = {2 * px / w, 0, 0, 0,
                                 0, 2 * py / h, 0, 0,
                                 2 * (u0 + 0.5) / w - 1, 2 * (v0 + 0.5) / h - 1, (kFar + kNear) / (kFar - kNear), 1,
                                 0, 0, -2 * kFar * kNear / (kFar - kNear), 0};
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(projection);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void load_pose(const Se3& camera_from_model) {
  const Vec3 t = camera_from_model.translation();
  const edgetrack::Mat33& r = camera_from_model.rotation();
  double modelview[16];
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) modelview[col * 4 + row] = static_cast<double>(r.m[row][col]);
  modelview[3] = modelview[7] = modelview[11] = 0;
  modelview[12] = static_cast<double>(t.x);
  modelview[13] = static_cast<double>(t.y);
  modelview[14] = static_cast<double>(t.z);
  modelview[15] = 1;
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(modelview);
}

void draw_model_faces(const EdgeModel& model) {
  glBegin(GL_TRIANGLES);
  for (const edgetrack::Triangle& tri : model.triangles) {
    normal(model.faces[tri.face].normal);
    vertex(model.vertices[tri.a]);
    vertex(model.vertices[tri.b]);
    vertex(model.vertices[tri.c]);
  }
  for (const edgetrack::SurfaceTriangle& tri : model.cylinder_surface) {
    normal(tri.normal);
    for (const Vec3& corner : tri.corners) vertex(corner);
  }
  glEnd();
}

void draw_model_depth(const EdgeModel& model) {
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 2.0f);
  draw_model_faces(model);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

Result<std::unique_ptr<GlRenderer>> GlRenderer::create(const PinholeCamera& camera, int supersample) {
  std::unique_ptr<GlRenderer> renderer(new GlRenderer(camera, supersample));
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context) return Error{"OSMesa", 0, "cannot create an off-screen GL context"};
  renderer->context_ = context;
  if (!OSMesaMakeCurrent(context, renderer->buffer_.data(), GL_UNSIGNED_BYTE, renderer->width_, renderer->height_))
    return Error{"OSMesa", 0, "cannot bind the off-screen buffer"};
  return renderer;
}

GlRenderer::GlRenderer(const PinholeCamera& camera, int supersample)
    : camera_(camera),
      supersample_(std::max(1, supersample)),
      width_(camera.width * supersample_),
      height_(camera.height * supersample_),
      buffer_(static_cast<size_t>(width_) * height_ * 4) {}

GlRenderer::~GlRenderer() {
  if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void GlRenderer::begin_frame(const Se3& camera_from_model, float r, float g, float b, float a) {
  OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE, width_, height_);
  glViewport(0, 0, width_, height_);
  glClearColor(r, g, b, a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  load_pinhole_projection(camera_.scaled(supersample_));
  // The light, fixed to the camera: above, right of and behind it (camera -y is up, +z forward).
  const GLfloat light_direction[4] = {0.45f, -0.75f, -0.5f, 0.0f};
  const GLfloat diffuse[4] = {0.65f, 0.65f, 0.65f, 1.0f}, ambient[4] = {0.28f, 0.28f, 0.28f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_direction);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  load_pose(camera_from_model);
}

void GlRenderer::draw_cone(const Cone& cone) {
  const ConeMesh mesh = cone_mesh(cone, 48);
  glBegin(GL_TRIANGLES);
  for (size_t i = 0; i < mesh.corners.size(); ++i) {
    normal(mesh.normals[i]);
    vertex(mesh.corners[i]);
  }
  glEnd();
}

std::vector<uint8_t> GlRenderer::read_rgba() const {
  glFinish();
  // Average supersample x supersample blocks (premultiplied colours stay premultiplied).
  const int s = supersample_, n = s * s;
  std::vector<uint8_t> out(static_cast<size_t>(camera_.width) * camera_.height * 4);
  for (int y = 0; y < camera_.height; ++y)
    for (int x = 0; x < camera_.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int dy = 0; dy < s; ++dy)
          for (int dx = 0; dx < s; ++dx) sum += buffer_[((static_cast<size_t>(y) * s + dy) * width_ + x * s + dx) * 4 + c];
        out[(static_cast<size_t>(y) * camera_.width + x) * 4 + c] = static_cast<uint8_t>((sum + n / 2) / n);
      }
  return out;
}

RgbImage GlRenderer::render_scene(const EdgeModel& model, const Se3& camera_from_model, const SceneExtras& extras) {
  begin_frame(camera_from_model, 0.35f, 0.33f, 0.3f, 1.0f);
  glEnable(GL_LIGHTING);
  if (extras.backdrop) {
    if (uploaded_backdrop_ != extras.backdrop) {
      if (backdrop_texture_ == 0) glGenTextures(1, &backdrop_texture_);
      glBindTexture(GL_TEXTURE_2D, backdrop_texture_);
      glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, extras.backdrop->width, extras.backdrop->height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                   extras.backdrop->rgb.data());
      uploaded_backdrop_ = extras.backdrop;
    }
    Vec3 u, v;
    plane_axes(extras.backdrop_normal, u, v);
    const double half = extras.backdrop_size / 2;
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, backdrop_texture_);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor3f(1, 1, 1);
    glBegin(GL_QUADS);
    normal(extras.backdrop_normal);
    const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corners) {
      glTexCoord2d((c[0] + 1) / 2, (c[1] + 1) / 2);
      vertex(extras.backdrop_centre + scaled(half * c[0], u) + scaled(half * c[1], v));
    }
    glEnd();
    glDisable(GL_TEXTURE_2D);
  }
  glColor3f(0.85f, 0.82f, 0.7f);
  draw_model_faces(model);
  if (extras.clutter) {
    // Lines as dark as the backdrop's darkest strokes, hidden where the model is in front.
    glDisable(GL_LIGHTING);
    glLineWidth(1.5f * supersample_);
    glColor3f(0.1f, 0.09f, 0.08f);
    glBegin(GL_LINES);
    for (const edgetrack::Segment3& line : *extras.clutter) {
      vertex(line.a);
      vertex(line.b);
    }
    glEnd();
  }
  if (extras.band.x_end > extras.band.x_begin) draw_band(extras.band);
  if (extras.occluder) {
    // A bar standing 100 mm in front of the camera, in the camera frame.
    glDisable(GL_LIGHTING);
    glLoadIdentity();
    glColor3f(0.12f, 0.1f, 0.09f);
    const double x0 = extras.occluder_x - extras.occluder_width / 2, x1 = extras.occluder_x + extras.occluder_width / 2;
    glBegin(GL_QUADS);
    glVertex3d(x0, -1, 0.1);
    glVertex3d(x1, -1, 0.1);
    glVertex3d(x1, 1, 0.1);
    glVertex3d(x0, 1, 0.1);
    glEnd();
  }
  const std::vector<uint8_t> rgba = read_rgba();
  RgbImage image = make_image(camera_.width, camera_.height);
  for (size_t i = 0; i < static_cast<size_t>(camera_.width) * camera_.height; ++i)
    for (int c = 0; c < 3; ++c) image.rgb[i * 3 + c] = rgba[i * 4 + c];
  return image;
}

void GlRenderer::draw_band(const edgetrack::OccluderBand& band) {
  // A flat dark board 100 mm in front of the camera whose edges fall on the band's pixel borders,
  // drawn over everything (a model nearer than 100 mm too, as the band promises).
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glLoadIdentity();
  glColor3f(0.2f, 0.18f, 0.16f);
  const double z = 0.1, px = static_cast<double>(camera_.px), u0 = static_cast<double>(camera_.u0);
  const double x0 = (band.x_begin - 0.5 - u0) / px * z, x1 = (band.x_end - 0.5 - u0) / px * z;
  glBegin(GL_QUADS);
  glVertex3d(x0, -1, z);
  glVertex3d(x1, -1, z);
  glVertex3d(x1, 1, z);
  glVertex3d(x0, 1, z);
  glEnd();
  glEnable(GL_DEPTH_TEST);
}

RgbImage GlRenderer::render_overlay(const RgbImage& frame, const EdgeModel& model, const Se3& camera_from_model,
                                    const Cone& cone) {
  begin_frame(camera_from_model, 0, 0, 0, 0);
  glDisable(GL_LIGHTING);
  draw_model_depth(model);
  if (cone.radius > 0) {
    glEnable(GL_LIGHTING);
    glColor4f(0.95f, 0.45f, 0.1f, 1.0f);
    draw_cone(cone);
    glDisable(GL_LIGHTING);
  }
  glLineWidth(1.5f * supersample_);
  glColor4f(0.1f, 1.0f, 0.2f, 1.0f);
  glBegin(GL_LINES);
  for (const edgetrack::Edge& edge : model.edges) {
    vertex(model.vertices[edge.a]);
    vertex(model.vertices[edge.b]);
  }
  std::vector<edgetrack::ContourSegment> curved;
  edgetrack::curved_contours(model, camera_from_model, curved);
  for (const edgetrack::ContourSegment& segment : curved) {
    vertex(segment.a);
    vertex(segment.b);
  }
  glEnd();
  const std::vector<uint8_t> rgba = read_rgba();
  RgbImage out = frame;
  for (size_t i = 0; i < static_cast<size_t>(camera_.width) * camera_.height; ++i) {
    const int alpha = rgba[i * 4 + 3];
    for (int c = 0; c < 3; ++c)
      out.rgb[i * 3 + c] = static_cast<uint8_t>(std::min(255, (frame.rgb[i * 3 + c] * (255 - alpha) + 127) / 255 + rgba[i * 4 + c]));
  }
  return out;
}

namespace {

class GlOverlay : public Overlay {
 public:
  explicit GlOverlay(std::unique_ptr<GlRenderer> renderer) : renderer_(std::move(renderer)) {}
  RgbImage draw(const RgbImage& frame, const EdgeModel& model, const Se3& camera_from_model, const Cone& cone) override {
    return renderer_->render_overlay(frame, model, camera_from_model, cone);
  }

 private:
  std::unique_ptr<GlRenderer> renderer_;
};

}  // namespace

Result<std::unique_ptr<Overlay>> make_overlay(const PinholeCamera& camera) {
  auto renderer = GlRenderer::create(camera, 3);
  if (!renderer.ok()) return renderer.error();
  return std::unique_ptr<Overlay>(new GlOverlay(std::move(renderer).value()));
}

}  // namespace edgetrack_app
