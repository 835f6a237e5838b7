// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID through real GL, as the paper did it (section 3.4), on the host with OSMesa: the
/// model's faces fill the depth buffer, its edges are drawn with the depth test (hidden-line
/// removal) into a 16-bit RGB565 colour buffer, each in the colour of its index, and read back.
/// Used by `track --visibility gl` (GlEdgeIdSource), to check the portable Edge-ID against GL
/// and to measure the colour approximation of the naive and the 8-level codes.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "edgetrack/contours.h"
#include "edgetrack/edge_id.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"
#include "edgetrack/tracker.h"

namespace edgetrack_app {

class GlEdgeIdBuffer {
 public:
  /// An OSMesa context with an RGB565 colour buffer of the camera's size.
  static edgetrack::Result<std::unique_ptr<GlEdgeIdBuffer>> create(const edgetrack::PinholeCamera& camera);
  ~GlEdgeIdBuffer();
  GlEdgeIdBuffer(const GlEdgeIdBuffer&) = delete;
  GlEdgeIdBuffer& operator=(const GlEdgeIdBuffer&) = delete;

  /// Redraws the Edge-ID image of the model seen from camera_from_model (8-level code).
  void render(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model);
  /// The index decoded at pixel (x, y), -1 for the background or outside.
  int edge_at(int x, int y) const;
  /// The same test as edgetrack::EdgeIdBuffer::shows: the nearest pixel or one of the two
  /// beside it across the line decodes to `edge`.
  bool shows(int edge, const edgetrack::Vec2& pixel, const edgetrack::Vec2& along) const;

  /// Writes each colour as one GL point (glColor3ub) into the RGB565 buffer, row-major from
  /// pixel (0, 0), and returns the pixels read back. At most width * height colours.
  std::vector<uint16_t> draw_colours(const std::vector<edgetrack::Rgb888>& colours);

  /// The RGB565 image of the last render, width * height pixels, image row 0 first.
  const std::vector<uint16_t>& pixels() const { return pixels_; }

 private:
  explicit GlEdgeIdBuffer(const edgetrack::PinholeCamera& camera);
  void make_current();

  edgetrack::PinholeCamera camera_;
  void* context_ = nullptr;
  std::vector<uint16_t> pixels_;
  std::vector<edgetrack::ContourSegment> curved_;  ///< this frame's cylinder silhouettes and circle sides
};

/// The tracker's Edge-ID drawn by GL (`track --visibility gl`): each frame the GL image is
/// copied into the tracker's EdgeIdBuffer, whose visibility test then reads it.
class GlEdgeIdSource : public edgetrack::EdgeIdSource {
 public:
  explicit GlEdgeIdSource(std::unique_ptr<GlEdgeIdBuffer> gl) : gl_(std::move(gl)) {}
  void draw(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model,
            edgetrack::EdgeIdBuffer& out) override;

 private:
  std::unique_ptr<GlEdgeIdBuffer> gl_;
};

}  // namespace edgetrack_app
