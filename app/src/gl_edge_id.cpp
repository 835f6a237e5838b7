// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID rendered by OSMesa into an RGB565 colour buffer.
#include "gl_edge_id.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <cmath>

#include "gl_renderer.h"
#include "visibility.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

Result<std::unique_ptr<GlEdgeIdBuffer>> GlEdgeIdBuffer::create(const edgetrack::PinholeCamera& camera) {
  std::unique_ptr<GlEdgeIdBuffer> buffer(new GlEdgeIdBuffer(camera));
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGB_565, 24, 0, 0, nullptr);
  if (!context) return Error{"OSMesa", 0, "cannot create an RGB565 off-screen GL context"};
  buffer->context_ = context;
  if (!OSMesaMakeCurrent(context, buffer->pixels_.data(), GL_UNSIGNED_SHORT_5_6_5, camera.width, camera.height))
    return Error{"OSMesa", 0, "cannot bind the RGB565 buffer"};
  return buffer;
}

GlEdgeIdBuffer::GlEdgeIdBuffer(const edgetrack::PinholeCamera& camera)
    : camera_(camera), pixels_(static_cast<size_t>(camera.width) * camera.height) {}

GlEdgeIdBuffer::~GlEdgeIdBuffer() {
  if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void GlEdgeIdBuffer::make_current() {
  OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), pixels_.data(), GL_UNSIGNED_SHORT_5_6_5, camera_.width,
                    camera_.height);
  glViewport(0, 0, camera_.width, camera_.height);
  glDisable(GL_LIGHTING);
  glDisable(GL_DITHER);  // the colours are codes: no dithering into neighbouring values
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_CULL_FACE);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void GlEdgeIdBuffer::render(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model) {
  make_current();
  load_pinhole_projection(camera_);
  load_pose(camera_from_model);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  draw_model_depth(model);
  glLineWidth(1.0f);
  glBegin(GL_LINES);
  for (size_t i = 0; i < model.edges.size(); ++i) {
    const edgetrack::Rgb888 code = edgetrack::encode_edge_id(static_cast<int>(i));
    glColor3ub(static_cast<GLubyte>(code.r), static_cast<GLubyte>(code.g), static_cast<GLubyte>(code.b));
    vertex(model.vertices[model.edges[i].a]);
    vertex(model.vertices[model.edges[i].b]);
  }
  edgetrack::curved_contours(model, camera_from_model, curved_);
  for (const edgetrack::ContourSegment& segment : curved_) {
    const edgetrack::Rgb888 code = edgetrack::encode_edge_id(segment.primitive);
    glColor3ub(static_cast<GLubyte>(code.r), static_cast<GLubyte>(code.g), static_cast<GLubyte>(code.b));
    vertex(segment.a);
    vertex(segment.b);
  }
  glEnd();
  glFinish();
}

int GlEdgeIdBuffer::edge_at(int x, int y) const {
  if (x < 0 || y < 0 || x >= camera_.width || y >= camera_.height) return -1;
  const uint16_t pixel = pixels_[static_cast<size_t>(y) * camera_.width + x];
  if (pixel == 0) return -1;
  return edgetrack::decode_edge_id(edgetrack::unpack_rgb565(pixel));
}

bool GlEdgeIdBuffer::shows(int edge, const edgetrack::Vec2& pixel, const edgetrack::Vec2& along) const {
  const int x = static_cast<int>(std::floor(static_cast<double>(pixel.x) + 0.5));
  const int y = static_cast<int>(std::floor(static_cast<double>(pixel.y) + 0.5));
  const bool x_major = std::fabs(static_cast<double>(along.x)) >= std::fabs(static_cast<double>(along.y));
  const int dx = x_major ? 0 : 1, dy = x_major ? 1 : 0;
  return edge_at(x, y) == edge || edge_at(x - dx, y - dy) == edge || edge_at(x + dx, y + dy) == edge;
}

std::vector<uint16_t> GlEdgeIdBuffer::draw_colours(const std::vector<edgetrack::Rgb888>& colours) {
  make_current();
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, camera_.width, 0, camera_.height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glPointSize(1.0f);
  glBegin(GL_POINTS);
  for (size_t i = 0; i < colours.size() && i < pixels_.size(); ++i) {
    glColor3ub(static_cast<GLubyte>(colours[i].r), static_cast<GLubyte>(colours[i].g), static_cast<GLubyte>(colours[i].b));
    glVertex2d(static_cast<double>(i % camera_.width) + 0.5, static_cast<double>(i / camera_.width) + 0.5);
  }
  glEnd();
  glFinish();
  return pixels_;
}

void GlEdgeIdSource::draw(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model,
                          edgetrack::EdgeIdBuffer& out) {
  gl_->render(model, camera_from_model);
  // No flip: load_pinhole_projection sends image row v to GL row v, and OSMesa stores GL's
  // bottom row first, so the buffer already starts with image row 0 as assign() wants.
  out.assign(gl_->pixels().data());
}

Result<std::unique_ptr<edgetrack::EdgeIdSource>> make_gl_edge_id_source(const edgetrack::PinholeCamera& camera) {
  auto gl = GlEdgeIdBuffer::create(camera);
  if (!gl.ok()) return gl.error();
  return std::unique_ptr<edgetrack::EdgeIdSource>(new GlEdgeIdSource(std::move(gl).value()));
}

}  // namespace edgetrack_app
