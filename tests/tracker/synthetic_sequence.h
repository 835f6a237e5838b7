// SPDX-License-Identifier: BSD-3-Clause
/// The synthetic sequences of the tracking tests and the Table 1 benchmark: the paper's set-up
/// (QVGA, px = py = 220, a model about 150 mm away, 60 frames, smooth motion of up to about
/// 3 pixels per frame), rendered in-process by the test-image renderer.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/se3.h"
#include "edgetrack/synthetic_trajectory.h"

namespace edgetrack_test {

/// The QVGA camera of the sequences: px = py = 220, u0 = 160, v0 = 120 (the .cxx says why).
edgetrack::PinholeCamera qvga_camera();

/// kCubeCylinder: the cube with a cylinder beside it and a circle closing the cylinder's end
/// (data/models/cube60_cylinder.cao), on the cube's trajectory.
enum class Scene { kCube, kWoodToy, kCubeCylinder };

/// The true camera_from_model of each frame; with `subsample` k, every k-th pose of the
/// k * frames long trajectory: the same path k times faster.
std::vector<edgetrack::Se3> true_poses(Scene scene, int frames, int subsample = 1);

/// The model file of the scene, under data/models.
std::string model_path(Scene scene);

/// The camera position in the model frame, -R^T t: what the paper's accuracy figures compare.
edgetrack::Vec3 camera_position(const edgetrack::Se3& camera_from_model);

}  // namespace edgetrack_test
