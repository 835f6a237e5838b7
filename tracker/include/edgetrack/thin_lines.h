// SPDX-License-Identifier: BSD-3-Clause
/// Matches on a thin dark line beside an edge rather than on the edge itself (issue #27, drift
/// in clutter). A line a pixel or two wide has the polarity of the object's boundary on one of
/// its sides, so the contrast test passes it; what an edge between two surfaces does not show is
/// the intensity coming back: a few pixels into the darker side, a line is over and the image
/// is about as bright as on the brighter side again, while behind an object's boundary the darker
/// surface goes on.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/edge_match.h"
#include "visp3/core/vpImage.h"

namespace edgetrack {

/// The thin-line test's settings (TrackerParams::thin_lines), set by name from the XML's
/// <edgetrack><thin_lines> block and `track --thin-lines` (set_thin_line_param). Off by
/// default: on ViSP's real mbt/cube it also takes out true edges (a third of the matches at
/// return_share 0.2, docs/ME.md "Thin lines beside the edges"), so it is not a rule yet.
struct ThinLineParams {
  bool enabled = false;
  /// Pixels into the darker side (from the match) a line's darkest pixel may lie: its width.
  int dark_px = 2;
  /// Pixels beyond that darkest pixel where the image may come back.
  int beyond_px = 2;
  /// A match is on a line when the brightest pixel beyond is brighter than the darkest by at
  /// least this share of the edge's step (the pixel 2 px into the brighter side against the
  /// darkest): 0 < share <= 1. Measured on the generated clutter (docs/ME.md, "Thin lines").
  real return_share{0.2};
};

/// Sets the setting `name` (enabled, dark_px, beyond_px, return_share) of `p` to `value`:
/// an empty string, or what is wrong (no such setting, a value outside its limits).
std::string set_thin_line_param(ThinLineParams& p, const std::string& name, double value);

/// Whether the grey profile through `at` along `normal` looks like a thin dark line's side:
/// `brighter_along_normal` says which side the edge's brighter one is. A profile that leaves
/// the image counts as no line.
bool on_thin_line(const vpImage<unsigned char>& grey, const Vec2& at, const Vec2& normal, bool brighter_along_normal,
                  const ThinLineParams& params);

/// Each match whose `found` lies on a thin line takes its first alternative that does not; a
/// match left with none is removed. Returns the number of matches that changed or went.
int reject_thin_line_matches(const vpImage<unsigned char>& grey, std::vector<EdgeMatch>& matches,
                             const ThinLineParams& params);

}  // namespace edgetrack
