// SPDX-License-Identifier: BSD-3-Clause
/// LINE-2D templates made from the model, with no image rendered: for each viewpoint
/// (viewpoints.h) the model's edges are projected, Edge-ID keeps their visible points, and each
/// feature is such a point with the orientation of its projected edge's normal (the direction of
/// the image gradient the edge makes). A template keeps a bounded number of well-spread features.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "edgetrack/detector/template_array.h"
#include "edgetrack/detector/viewpoints.h"
#include "edgetrack/downscaled_camera.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// How templates are made; stored with them (template_io.h).
struct TemplateParams {
  ViewRange views;
  /// Matching runs on the image downscaled by this factor (1 to 4): half a QVGA frame still
  /// resolves the edges of an object a third of the image wide, at a quarter of the cost.
  int downscale = 2;
  /// Features per template (at most 63: 63 x 4 fits a byte, LINE-2D's bound).
  int features = 32;
  /// Views with fewer visible edge points than this are skipped (edge-on, mostly hidden).
  int min_features = 16;
  /// Pixels (downscaled) between the edge points features are chosen from.
  real sample_step = real(2);
};

/// One feature: its pixel relative to the template's top-left corner and its orientation bin.
struct TemplateFeature {
  uint8_t x = 0;
  uint8_t y = 0;
  uint8_t bin = 0;
};

/// One view: its pose, where the model's centre projects (relative to the corner, downscaled
/// pixels), its features' extent and its features (TemplateSet::features[first, first + count)).
struct Template {
  /// The view's rotation (camera_from_model's, as theta u: 3 numbers where a matrix takes 9);
  /// the model's centre is on the optical axis at `distance` (template_pose).
  Vec3 theta_u;
  real distance{0};
  int distance_index = 0;  ///< which of the range's distances (0: the nearest)
  Vec2 anchor;
  int width = 0;   ///< largest feature x + 1
  int height = 0;  ///< largest feature y + 1
  int first = 0;
  int count = 0;
};

struct TemplateSet {
  TemplateParams params;
  /// The camera of the frames they are for, at full size (what a template file records). The
  /// templates themselves are made at detection_camera(): smaller for frames above
  /// kMaxDetectionSide.
  PinholeCamera camera;
  ModelExtent extent;
  std::string model_fingerprint;
  /// On the heap, or read in place from constant data (template_array.h).
  TemplateArray<Template> templates;
  TemplateArray<TemplateFeature> features;
  int distance_count = 0;  ///< distances of the range: every distance_index is below it

  /// The camera detection (templates, matching, refinement) runs at: detection_camera(camera).
  PinholeCamera detection_camera() const;
  /// The camera of the image matching runs on: detection_camera() downscaled by params.downscale.
  PinholeCamera matching_camera() const;
  /// Bytes held by the templates and their features (on the heap, or in constant data).
  size_t memory_bytes() const;
};

/// camera_from_model of a template's view.
Se3 template_pose(const Template& t, const ModelExtent& extent);

/// The longest shorter image side detection runs on at full size: VGA's. The refinement's
/// settings (DetectorParams, and the tracking settings the detector's trackers take as given)
/// are pixels chosen on frames of QVGA to VGA size, and a template's features lie within 255
/// pixels of its corner (a byte each) in the matching image, so that beyond about 1280 pixels no
/// view of the default range fits one. What each bound finds: tests/bench/detection/large_frames.sh.
constexpr int kMaxDetectionSide = 480;

/// The factor a frame of `camera`'s size is reduced by for detection (templates, matching and
/// refinement alike): 1 up to kMaxDetectionSide pixels on its shorter side, else the smallest
/// integer that brings the side there. Detector reduces its frames itself (block averages), so a
/// caller feeds full-size frames; a pose found with the reduced camera is the full-size
/// camera's: the reduced camera sees the same rays.
int detection_reduction(const PinholeCamera& camera);

/// The camera detection runs at for frames of `camera`: downscaled_camera(camera,
/// detection_reduction(camera)).
PinholeCamera detection_camera(const PinholeCamera& camera);

/// A short text that changes when the model's geometry changes: a hash of its vertices (in
/// micrometres), faces, edges and curved primitives.
std::string model_fingerprint(const EdgeModel& model);

/// Checks the parameters; an Error names the first one out of its range.
Result<bool> check_template_params(const TemplateParams& params);

/// Makes the templates of every view of params.views for frames of `camera` (full size; the
/// templates are made at detection_camera(camera)).
Result<TemplateSet> make_template_set(const EdgeModel& model, const PinholeCamera& camera,
                                      const TemplateParams& params);

}  // namespace edgetrack
