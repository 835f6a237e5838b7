// SPDX-License-Identifier: BSD-3-Clause
/// What the generated evaluation sequences add to a model's scene, in one portable place that
/// `edgetrack synth` (OSMesa) and the portable SceneRenderer both draw: faster motion along the
/// same path (or there and back), an occluder covering a chosen share of the object's projected area, and clutter of
/// lines parallel to the model's edges that are not part of the tracked model.
#pragma once

#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The same path `speed` times faster: pose k is slow pose speed * k, interpolated along the
/// screw motion between its two neighbours (exact at whole multiples); `frames` poses, or as
/// many as `slow` reaches.
std::vector<Se3> faster_poses(const std::vector<Se3>& slow, const real& speed, int frames);

/// The path there and back: `forward`, then the same poses backwards to the first (2 n - 1
/// poses for n): the motion reverses at once from one frame to the next at the turn, as a hand
/// that changes its mind does.
std::vector<Se3> there_and_back(const std::vector<Se3>& forward);

/// An occluder in front of everything: image columns [x_begin, x_end) of every row.
struct OccluderBand {
  int x_begin = 0;
  int x_end = 0;
  real covered_share{0};  ///< share of the object's projected area inside the band
};

/// The object's projected area per image column: its pixels (centres inside a face) counted
/// once each, `columns` resized to camera.width. `mask` is scratch (camera.width * height).
void silhouette_columns(const EdgeModel& model, const PinholeCamera& camera, const Se3& camera_from_model,
                        std::vector<uint8_t>& mask, std::vector<int>& columns);

/// The narrowest band centred on column `centre` (grown one column at a time, right first)
/// whose columns hold at least `share` of the silhouette's area. Empty for an empty silhouette.
OccluderBand occluder_band(const std::vector<int>& columns, int centre, const real& share);

/// The band's centre in frame `k` of `frames`: it sweeps over the middle half of the
/// silhouette's columns (from its first quarter to its third), left to right.
int sweeping_centre(const std::vector<int>& columns, int k, int frames);

struct Segment3 {
  Vec3 a;  ///< model frame, metres
  Vec3 b;
};

/// One distractor line per model edge, in the edges' order: the edge moved by `offset` metres,
/// perpendicular to it, away from the model's centre (the mean of its vertices), so that it sits
/// beside the edge in every view and runs parallel to it.
std::vector<Segment3> parallel_clutter(const EdgeModel& model, const real& offset);

/// What a render adds to the model's scene: the occluder (none when the band is empty) and the
/// clutter lines (none when null), each drawn flat in its own grey.
struct SceneAdditions {
  OccluderBand band;
  const std::vector<Segment3>* clutter = nullptr;
  int occluder_grey = 45;
  int clutter_grey = 25;
};

/// The mean image distance (pixels) between each clutter line's middle and its edge's image line,
/// at one pose: how far off the edges the distractors look.
real clutter_image_offset(const EdgeModel& model, const std::vector<Segment3>& clutter, const PinholeCamera& camera,
                          const Se3& camera_from_model);

}  // namespace edgetrack
