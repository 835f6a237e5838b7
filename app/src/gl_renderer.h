// SPDX-License-Identifier: BSD-3-Clause
/// Off-screen OpenGL through OSMesa (host only): the lit, anti-aliased scenes of `edgetrack synth`
/// (the paper rendered its ground truth with OGRE) and the AR overlay of `edgetrack track` (the
/// tracked wireframe with hidden lines removed and a solid shaded cone on the object's top face,
/// the paper's Fig. 6). The GL camera reproduces the pinhole model exactly: u = u0 + px X/Z with
/// pixel centres at integer u, so GL pixels and tracker pixels agree.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/scene_extras.h"
#include "edgetrack/se3.h"
#include "image_io.h"
#include "overlay.h"

namespace edgetrack_app {

/// What `synth` puts in the scene besides the model.
struct SceneExtras {
  const RgbImage* backdrop = nullptr;  ///< texture of a plane behind the model, or none
  edgetrack::Vec3 backdrop_centre;     ///< model frame
  edgetrack::Vec3 backdrop_normal;     ///< unit, towards the camera
  double backdrop_size = 0.4;          ///< side, metres
  bool occluder = false;               ///< a dark bar between camera and model
  double occluder_x = 0;               ///< its centre in the camera frame, metres
  double occluder_width = 0.012;
  edgetrack::OccluderBand band;        ///< image columns covered in front of everything (none if empty)
  const std::vector<edgetrack::Segment3>* clutter = nullptr;  ///< dark lines beside the edges, or none
};

/// With a current GL context: the projection matrix of the pinhole camera (near 10 mm, far
/// 10 m) and the modelview matrix of camera_from_model; glVertex/glNormal of our vectors; the
/// model's triangles with their face normals.
void load_pinhole_projection(const edgetrack::PinholeCamera& camera);
void load_pose(const edgetrack::Se3& camera_from_model);
void vertex(const edgetrack::Vec3& p);
void normal(const edgetrack::Vec3& n);
void draw_model_faces(const edgetrack::EdgeModel& model);
/// The model's faces into the depth buffer only, pushed back a little (polygon offset) so that
/// edges lying on them pass a GL_LEQUAL depth test and edges behind them do not.
void draw_model_depth(const edgetrack::EdgeModel& model);

class GlRenderer {
 public:
  /// An OSMesa context for images of the camera's size, rendered `supersample` times larger and
  /// averaged down (anti-aliasing).
  static edgetrack::Result<std::unique_ptr<GlRenderer>> create(const edgetrack::PinholeCamera& camera, int supersample);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  /// The model lit by a light above and behind the camera, over the extras.
  RgbImage render_scene(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model,
                        const SceneExtras& extras);

  /// The frame with the model's visible edges (hidden lines removed by the depth test) and the
  /// shaded cone drawn over it.
  RgbImage render_overlay(const RgbImage& frame, const edgetrack::EdgeModel& model,
                          const edgetrack::Se3& camera_from_model, const Cone& cone);

 private:
  GlRenderer(const edgetrack::PinholeCamera& camera, int supersample);
  void begin_frame(const edgetrack::Se3& camera_from_model, float r, float g, float b, float a);
  void draw_cone(const Cone& cone);
  void draw_band(const edgetrack::OccluderBand& band);
  std::vector<uint8_t> read_rgba() const;

  edgetrack::PinholeCamera camera_;
  int supersample_;
  int width_, height_;  ///< the supersampled size
  void* context_ = nullptr;
  std::vector<uint8_t> buffer_;
  unsigned backdrop_texture_ = 0;
  const RgbImage* uploaded_backdrop_ = nullptr;
};

}  // namespace edgetrack_app
