// SPDX-License-Identifier: BSD-3-Clause
/// The limits of the tracker's settings, in one place: the configuration reader checks a file's
/// values with them (naming the file and line), and Tracker::create checks hand-built settings.
#pragma once

#include <optional>
#include <string>

#include "edgetrack/tracker.h"

namespace edgetrack {

/// A setting outside what the tracker can use.
struct SettingProblem {
  std::string field;    ///< the element of a ViSP XML file that holds it, as "ecm/range/tracking"
  std::string message;  ///< what is wrong, naming the element
};

/// The mask's limits alone, checked before vpMe builds its masks: size 3..15 pixels, 1..180 of them.
std::optional<SettingProblem> check_masks(unsigned int size, unsigned int number);

/// The first setting of `params` outside its limits, or nothing.
std::optional<SettingProblem> check_tracker_params(const TrackerParams& params);

/// The sampling step's inputs for `params`: the sample step of params.me, params.border and the
/// clipping of params.faces.
SamplingParams sampling_params(const TrackerParams& params);

}  // namespace edgetrack
