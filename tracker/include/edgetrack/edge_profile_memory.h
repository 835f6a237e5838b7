// SPDX-License-Identifier: BSD-3-Clause
/// The grey profile across each model edge, along its normal, in the last trusted frame, kept at
/// its model point: the next frame locates the edge where its profile fits the remembered one.
/// A line or a texture beside an edge that moves with the object moves the moving-edge
/// response's peak (its mask spans both, and their responses merge) or outweighs the edge; the
/// whole pattern moves with the edge, so the fitted shift is the edge's.
#pragma once

#include <cstdint>
#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_match.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"
#include "visp3/core/vpImage.h"

namespace edgetrack {

/// The most samples either side of an edge a profile holds: half the largest mask (15 px), and one.
constexpr int kMaxProfileHalf = 8;

class EdgeProfileMemory {
 public:
  /// Forgets every profile (a new start).
  void clear() { remembered_.clear(); }

  /// Samples the profile of each match's control point along its normal, a pixel apart
  /// (bilinear), over +-(range + half) pixels, where half is
  /// mask_size / 2 + 1: the pixels the mask reads at the edge and the interpolation's one.
  /// Kept for relocate() and remember() in this frame.
  void sample(const vpImage<unsigned char>& grey, const std::vector<EdgeMatch>& matches, int mask_size, int range);

  /// At a given (trusted) start pose, before any frame: remembers each match's profile at its
  /// control point, the edge's projection there.
  void remember_at_points(const std::vector<EdgeMatch>& matches);

  /// Each match with a remembered profile at the nearest remembered point of its primitive
  /// within `reach` pixels (at camera_from_model, where the points were sampled) is fitted:
  /// the shift along the normal whose profile fits the remembered one best (least squares after
  /// removing the mean difference: a face lit differently shifts every level alike), refined
  /// below the pixel by Gauss-Newton on the linearly interpolated profile. Its `found` becomes
  /// the moving edge's maximum (found or an alternative) nearest to the fitted position when
  /// one lies within a pixel of it, else the fitted position: a fit alone, frame to frame,
  /// drifts where the background slides behind a silhouette (docs/ME.md), while a maximum of
  /// the mask response sits on the image's own edge. Matches whose best fit leaves more than
  /// half the remembered profile's variation unexplained (the look changed: an occluder, new
  /// background), or lies at the end of the range, keep the moving edge's.
  void relocate(const PinholeCamera& camera, const Se3& camera_from_model, const real& reach,
                std::vector<EdgeMatch>& matches) const;

  /// Replaces the memory with the profiles, at the projection at camera_from_model (the solved
  /// pose), of the matches the pose step kept whose `found` lies within `within` pixels of that
  /// projection along the normal (as ContrastMemory::remember: a point under an occluder
  /// matched by chance is not its edge). Uses the profiles of the last sample().
  void remember(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& camera_from_model,
                const real& within);

 private:
  struct Profile {
    int edge = 0;
    Vec3 point_in_model;
    int16_t level[2 * kMaxProfileHalf + 1] = {};  ///< grey x 16 at -half..half pixels along the normal
  };
  /// The remembered profile in [first, end) nearest to `point` within `reach_m` (taxicab,
  /// metres), or null.
  const Profile* nearest(const ControlPoint& point, size_t first, size_t end, const real& reach_m) const;
  /// Remembers the sampled profile of match number `m`, read at `anchor` pixels along the normal.
  void keep(const EdgeMatch& match, size_t m, const real& anchor);

  std::vector<Profile> remembered_;
  int half_ = 3;          ///< samples either side of the edge in a profile
  int range_ = 0;         ///< the last sample()'s range
  std::vector<int16_t> sampled_;  ///< per match, 2 (range + half) + 1 levels
  std::vector<uint8_t> valid_;    ///< per match: its profile lies inside the image
};

}  // namespace edgetrack
