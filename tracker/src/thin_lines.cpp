// SPDX-License-Identifier: BSD-3-Clause
#include "edgetrack/thin_lines.h"

#include <algorithm>

namespace edgetrack {
namespace {

/// The grey level at the pixel holding `at`, or -1 outside the image.
int level(const vpImage<unsigned char>& grey, const Vec2& at) {
  if (at.x < real(0) || at.y < real(0)) return -1;
  const unsigned j = static_cast<unsigned>(static_cast<int>(at.x)), i = static_cast<unsigned>(static_cast<int>(at.y));
  if (i >= grey.getHeight() || j >= grey.getWidth()) return -1;
  return grey[i][j];
}

/// The longest profile a test reads into the darker side: dark_px and beyond_px, 8 each at most
/// (set_thin_line_param).
constexpr int kMostProfilePx = 16;

}  // namespace

bool on_thin_line(const vpImage<unsigned char>& grey, const Vec2& at, const Vec2& normal, bool brighter_along_normal,
                  const ThinLineParams& params) {
  const Vec2 darker = brighter_along_normal ? Vec2{-normal.x, -normal.y} : normal;
  // The profile's pixels a step apart, each point the last plus `darker`: in fixed point the
  // same points as at + k darker, without a multiplication per pixel.
  Vec2 point = at - (darker + darker);
  const int bright = level(grey, point);
  if (bright < 0) return false;
  point = at;
  // The darkest pixel within the line's width, then the brightest within as much again beyond
  // it: the profile read once, as far as the darkest could reach.
  const int read = std::min(params.dark_px + params.beyond_px, kMostProfilePx);
  const int width = std::min(params.dark_px, read);
  int profile[kMostProfilePx + 1];
  for (int k = 1; k <= read; ++k) {
    point = point + darker;
    profile[k] = level(grey, point);
    if (k <= width && profile[k] < 0) return false;
  }
  int dark = 256, dark_k = 0;
  for (int k = 1; k <= width; ++k)
    if (profile[k] < dark) dark = profile[k], dark_k = k;
  int beyond = -1;
  for (int k = dark_k + 1; k <= std::min(dark_k + params.beyond_px, read); ++k) beyond = std::max(beyond, profile[k]);
  if (beyond < 0 || bright <= dark) return false;
  return real(beyond - dark) >= params.return_share * real(bright - dark);
}

std::string set_thin_line_param(ThinLineParams& p, const std::string& name, double value) {
  const bool whole = value == static_cast<double>(static_cast<long>(value));
  if (name == "enabled") {
    if (value != 0 && value != 1) return "enabled must be 0 or 1";
    p.enabled = value == 1;
  } else if (name == "check") {
    if (value != 0 && value != 1 && value != 2) return "check must be 0 (none), 1 (report) or 2 (correct)";
    p.check = static_cast<DriftAction>(static_cast<int>(value));
  } else if (name == "check_sigmas") {
    if (!(value > 0 && value <= 100)) return "check_sigmas must be above 0 and at most 100";
    p.check_sigmas = real(value);  // set-up time conversion
  } else if (name == "dark_px" || name == "beyond_px") {
    if (!whole || value < 1 || value > 8) return name + " must be a whole number of pixels from 1 to 8";
    (name == "dark_px" ? p.dark_px : p.beyond_px) = static_cast<int>(value);
  } else if (name == "return_share") {
    if (!(value > 0 && value <= 1)) return "return_share must be above 0 and at most 1";
    p.return_share = real(value);  // set-up time conversion
  } else {
    return "'" + name + "' is not a thin-line setting (enabled, check, check_sigmas, dark_px, beyond_px, return_share)";
  }
  return "";
}

int reject_thin_line_matches(const vpImage<unsigned char>& grey, std::vector<EdgeMatch>& matches,
                             const ThinLineParams& params) {
  int changed = 0;
  size_t kept = 0;
  for (size_t m = 0; m < matches.size(); ++m) {
    EdgeMatch match = matches[m];
    const bool brighter_along_normal = match.contrast < real(0);  // the mask response is positive where the image darkens along the normal
    const bool line = on_thin_line(grey, match.found, match.point.normal, brighter_along_normal, params);
    if (line) {
      ++changed;
      const int held = match.alternatives_held();
      int a = 0;
      while (a < held && on_thin_line(grey, match.alternatives[a], match.point.normal, brighter_along_normal, params))
        ++a;
      if (a == held) continue;
      match.found = match.alternatives[a];
      std::copy(match.alternatives + a + 1, match.alternatives + held, match.alternatives);
      match.alternative_count = held - (a + 1);
    }
    matches[kept++] = match;
  }
  matches.resize(kept);
  return changed;
}

}  // namespace edgetrack
