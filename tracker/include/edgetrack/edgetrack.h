// SPDX-License-Identifier: BSD-3-Clause
/// The public tracking API in one include (docs/API.md): open a model (model_io.h), read the
/// camera and settings of a ViSP XML (visp_config.h) and an initial pose (pose_io.h), create a
/// Tracker, feed it frames in the layouts device cameras deliver (frame_view.h), and read each
/// frame's pose, status and step times (tracker.h, tracking_status.h).
#pragma once

#include "edgetrack/frame_view.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/result.h"
#include "edgetrack/tracker.h"
#include "edgetrack/tracking_status.h"
#include "edgetrack/visp_config.h"
