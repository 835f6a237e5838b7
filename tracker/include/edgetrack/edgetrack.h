// SPDX-License-Identifier: BSD-3-Clause
/// The public tracking API in one include (docs/API.md): open a model (model_io.h), read the
/// camera and settings of a ViSP XML (visp_config.h) or a calibration file (camera_file.h) and an initial pose (pose_io.h), create a
/// Tracker, feed it frames in the layouts device cameras deliver (frame_view.h), and read each
/// frame's pose, status and step times (tracker.h, tracking_status.h), printed as the poses CSV
/// (poses_csv.h); or, with no pose, make
/// or read the model's templates and let an AutoInitTracker detect the model on the first frame
/// and after each lost one (detector/).
#pragma once

#include "edgetrack/camera_file.h"
#include "edgetrack/detector/auto_init_tracker.h"
#include "edgetrack/detector/template_io.h"
#include "edgetrack/detector/template_set.h"
#include "edgetrack/frame_view.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/poses_csv.h"
#include "edgetrack/result.h"
#include "edgetrack/tracker.h"
#include "edgetrack/tracker_inputs.h"
#include "edgetrack/tracking_status.h"
#include "edgetrack/visp_config.h"
