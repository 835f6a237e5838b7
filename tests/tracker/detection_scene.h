// SPDX-License-Identifier: BSD-3-Clause
/// Generated detection trials for the detector's tests and its evaluation: the model at a random
/// pose inside a template range, wholly in view, over a textured background with random
/// distractor lines behind it; frames with the lines and no object; and the pose error modulo
/// the model's symmetries.
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/detector/template_set.h"
#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/se3.h"

namespace edgetrack_test {

/// The 24 rotations of the cube onto itself (signed permutation matrices of determinant 1).
std::vector<edgetrack::Mat33> cube_symmetries();

struct PoseError {
  double centre_mm = 0;     ///< distance between the model centres in the camera frame
  double rotation_deg = 0;  ///< the smallest angle between the rotations over the symmetries
};

/// The error of `estimate` against `truth`, taking any of `symmetries` (rotations about the
/// model's `centre`, model frame; the identity among them) as the truth too.
PoseError pose_error(const edgetrack::Se3& estimate, const edgetrack::Se3& truth, const edgetrack::Vec3& centre,
                     const std::vector<edgetrack::Mat33>& symmetries);

/// A random camera_from_model inside `range` (views.h's direction cone, any in-plane angle, a
/// distance between its nearest and farthest) with the model wholly in view 8 pixels inside the
/// border, its centre anywhere that allows it. Deterministic for a seed.
edgetrack::Se3 random_view(const edgetrack::EdgeModel& model, const edgetrack::PinholeCamera& camera,
                           const edgetrack::ViewRange& range, uint32_t seed);

/// `count` distractor segments behind the model seen from camera_from_model (model frame): random
/// points 1.5 to 4 model radii from its centre on the far side, 0.5 to 2 radii long.
std::vector<edgetrack::Segment3> background_lines(const edgetrack::EdgeModel& model,
                                                  const edgetrack::Se3& camera_from_model, int count, uint32_t seed);

/// A small template range for the tests on one or two views: a 25-degree cone about an oblique
/// axis (0.5, -0.6, 1), 140 to 170 mm.
edgetrack::TemplateParams oblique_range();

/// Renders a trial: `model` (or, when `with_object` is false, nothing but the background and
/// the lines) at `pose`, background texture and noise from `seed`.
void render_trial(const edgetrack::EdgeModel& model, const edgetrack::PinholeCamera& camera,
                  const edgetrack::Se3& pose, bool with_object, int lines, uint32_t seed,
                  edgetrack::Rgb565Frame& frame);

}  // namespace edgetrack_test
