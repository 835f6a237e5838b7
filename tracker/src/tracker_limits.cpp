// SPDX-License-Identifier: BSD-3-Clause
/// The tracker's stated maxima: all or none.
#include "edgetrack/tracker_limits.h"

namespace edgetrack {

std::optional<std::string> check_tracker_limits(const TrackerLimits& limits) {
  if (!limits.stated()) return std::nullopt;
  if (limits.primitives < 1 || limits.control_points < 1 || limits.image_width < 1 || limits.image_height < 1)
    return std::string("the tracker's limits state a maximum and leave another at 0 or below: primitives ") +
           std::to_string(limits.primitives) + ", control points " + std::to_string(limits.control_points) +
           ", image " + std::to_string(limits.image_width) + "x" + std::to_string(limits.image_height);
  return std::nullopt;
}

}  // namespace edgetrack
