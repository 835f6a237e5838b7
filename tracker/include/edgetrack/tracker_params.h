// SPDX-License-Identifier: BSD-3-Clause
/// The tracker's settings as plain values, and their limits in one place: the configuration
/// reader (visp_config.h) and the command line fill them, Tracker::create and
/// Tracker::set_params check them with check_tracker_params.
#pragma once

#include <optional>
#include <string>

#include "edgetrack/control_points.h"
#include "edgetrack/face_visibility.h"
#include "edgetrack/motion_model.h"
#include "edgetrack/pose_solver.h"
#include "edgetrack/thin_line_params.h"
#include "edgetrack/tracking_status.h"

namespace edgetrack {

/// The widest moving-edge range and image border a setting may ask for, pixels, and the
/// smallest sample step (a downscaled run divides the file's step by its factor).
constexpr unsigned int kMaxRange = 4096;
constexpr double kMinSampleStep = 0.1;

/// The moving edges' settings with ViSP's vpMe meanings and defaults, the one home of every
/// <ecm> setting (the tracker builds its masks from them once, at create or set_params).
struct MovingEdgeParams {
  /// Pixels searched either side of each control point along its normal. The configured one:
  /// each frame searches it or wider (MotionModel::search_range).
  unsigned int range = 4;  ///< 1 to kMaxRange
  real threshold{1500};          ///< the least mask response (likelihood) an edge needs
  unsigned int mask_size = 5;    ///< pixels on a side of each oriented mask (3 to 15)
  unsigned int mask_number = 180;  ///< oriented masks, 180 / mask_number degrees apart (1 to 180)
  /// The contrast a site accepts against the one its model point showed in the last trusted
  /// frame: from (1 - mu1) to (1 + mu2) times it (contrast_memory.h); each in [0, 1].
  real mu1{0.5};
  real mu2{0.5};
  real sample_step{10};  ///< pixels between control points along a projected edge, at least kMinSampleStep
};

/// How the grey step turns the frame into the grey image the moving edges read (a grey8 frame,
/// or the Y plane of NV21 and I420, packed, is read in place in both modes).
enum class GreyScaling {
  kOnDemand,   ///< only the boxes the control points' searches read (me_search_box.h)
  kWholeFrame  ///< every pixel, as the paper does
};

/// The tracker's settings, each in one place; check_tracker_params holds their limits, and the
/// configuration reader (visp_config.h) fills them from a ViSP XML file.
struct TrackerParams {
  MovingEdgeParams me;         ///< <ecm> and <sample>
  FaceVisibilityParams faces;  ///< <face> and <lod>: face angles, clipping, level of detail
  int border = 10;             ///< control points nearer the image border than this (pixels) are dropped
  PoseParams pose;
  /// Edge hypotheses each control point keeps (1 to kMaxHypotheses): the strongest edge along
  /// its normal and the next local maxima of the likelihood; the pose step uses the one nearest
  /// to the projection (moving_edges.h, pose_solver.h). 1 is the paper's single match, and the
  /// default: 3 lower the error where a parallel distractor edge lies inside the range but
  /// beyond the edge's own mask response, and raise it slightly on the plain generated
  /// sequences (docs/ME.md).
  int hypotheses = 1;
  ThinLineParams thin_lines;  ///< matches on a thin dark line beside an edge (thin_line_params.h)
  GreyScaling grey = GreyScaling::kOnDemand;
  MotionParams motion;  ///< prediction between frames and the range that follows it
  StatusParams status;  ///< the tracked / uncertain / lost rule
  /// A rolling shutter's readout time from the first row to the last, in frame intervals (the
  /// datasheet's readout time times the frame rate), -kMaxReadout..kMaxReadout, negative for
  /// rows read bottom first (rolling_shutter.h); <edgetrack><camera><readout>. 0, the default,
  /// is a global shutter: every row seen at the frame's time.
  real readout{0};
};

/// A setting outside what the tracker can use.
struct SettingProblem {
  /// The element of a ViSP XML file that holds it, as "ecm/range/tracking"; empty for the
  /// settings no XML element holds.
  std::string field;
  std::string message;  ///< what is wrong, naming the setting
};

/// The first setting of `params` outside its limits, or nothing. Every number must be finite.
std::optional<SettingProblem> check_tracker_params(const TrackerParams& params);

/// The sampling step's inputs for `params`: params.me.sample_step, params.border and the
/// clipping of params.faces.
SamplingParams sampling_params(const TrackerParams& params);

}  // namespace edgetrack
