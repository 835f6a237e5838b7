// SPDX-License-Identifier: BSD-3-Clause
/// The contrast of the edges found in the last trusted frame, kept at their model points, so that
/// the next frame's sites can refuse an edge of another polarity or contrast: ViSP's mu1/mu2
/// test, whose sites live from frame to frame, for control points sampled afresh every frame.
#pragma once

#include <cmath>
#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_match.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/se3.h"

namespace edgetrack {

class ContrastMemory {
 public:
  /// Forgets every contrast (a new start): the next frame's sites take the strongest edge.
  void clear() {
    remembered_.clear();
    groups_.clear();
  }
  /// Room for the contrasts of `matches` matches of up to `primitives` primitives: remember then
  /// allocates nothing for up to that many.
  void reserve(size_t matches, size_t primitives) {
    remembered_.reserve(matches);
    groups_.reserve(primitives);
  }
  /// Heap bytes it holds (tracker_memory.h).
  size_t heap_bytes() const {
    return remembered_.capacity() * sizeof(Remembered) + groups_.capacity() * sizeof(Group);
  }
  /// Replaces the memory with the contrast of each match that the pose step kept, that lies
  /// within `within` pixels (along its normal) of its projection at camera_from_model, the
  /// solved pose, and whose |contrast| is at least half its primitive's mean over the kept
  /// matches (a point under an occluder matched to noise by chance is not its edge). `matches`
  /// come grouped by primitive, one run per primitive, as the sampling orders them. `projected`, when given, holds
  /// the points the matches were searched from at camera_from_model (project_points), a match's
  /// at its point_index, so that no point is transformed or projected again.
  void remember(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera, const Se3& camera_from_model,
                const real& within, const ProjectedPoints* projected = nullptr);
  /// For each point, the contrast remembered at the nearest remembered point of the same
  /// primitive, when that lies within `reach` pixels of it at camera_from_model (about one
  /// sample step: where the edge was sampled last time). A point with none within reach whose
  /// primitive has remembered points of one polarity takes their mean, marked in `borrowed`
  /// (nonzero): the same edge between the same faces under the same light shows one contrast
  /// along its length, and a point not seen last time (under an occluder, in a shadow) is only
  /// seen again when its edge looks like that (moving_edges.h, strict). 0 where nothing is
  /// remembered.
  void references(const std::vector<ControlPoint>& points, const PinholeCamera& camera, const Se3& camera_from_model,
                  const real& reach, std::vector<real>& out, std::vector<unsigned char>& borrowed) const;

 private:
  /// The mean contrast of remembered_[first, end) when all share one sign, else 0.
  real mean_of_one_polarity(size_t first, size_t end) const;

  /// A remembered point; its primitive is its group's.
  struct Remembered {
    Vec3 point_in_model;
    real contrast{0};
  };
  /// The remembered points of one primitive, remembered_[first, end), and the model axis along
  /// which they spread most with whether their coordinate there only grows (+1), only falls (-1)
  /// or neither (0): along a straight edge the sampling's order is monotonic, so the points
  /// within reach of a point are a run that starts near the previous point's, instead of a scan
  /// of them all.
  struct Group {
    int edge = 0;
    size_t first = 0, end = 0;
    int axis = 0;
    int order = 0;
  };
  /// Groups remembered_[first, end) as primitive `edge`'s points.
  void add_group(int edge, size_t first);
  /// Along a monotonic group's axis, which remembered points fail a taxicab bound on that axis
  /// alone: |their coordinate - the point's|, computed as taxicab_below computes that term, is
  /// at least the bound (the rounded sum of the terms is never below one of them).
  class Window {
   public:
    Window(const Group& g, const Vec3& point) : g_(g), centre_(coordinate(point, g.axis)) {}
    /// Whether p lies before the point in g's order, `bound` or more away on the axis (never
    /// when g is not monotonic).
    bool before(const Vec3& p, const real& bound) const { return beyond(p, -g_.order, bound); }
    /// Whether p lies after the point in g's order, `bound` or more away on the axis (never
    /// when g is not monotonic): so do all of g's points after p.
    bool after(const Vec3& p, const real& bound) const { return beyond(p, g_.order, bound); }
    /// The first point of g not before() within `bound`, walked to from `from` (the previous
    /// point's first candidate, or g.first): before() holds for a prefix of a monotonic group,
    /// and never in another, whose points are all candidates.
    size_t first_candidate(const std::vector<Remembered>& remembered, size_t from, const real& bound) const {
      size_t k = from;
      while (k > g_.first && !before(remembered[k - 1].point_in_model, bound)) --k;
      while (k < g_.end && before(remembered[k].point_in_model, bound)) ++k;
      return k;
    }

   private:
    /// Whether p's coordinate lies on the `side` (+1 above, -1 below, 0 none) of the point's,
    /// `bound` or more away.
    bool beyond(const Vec3& p, int side, const real& bound) const {
      using std::fabs;
      const real& c = coordinate(p, g_.axis);
      const bool on_side = side > 0 ? c > centre_ : side < 0 && c < centre_;
      return on_side && !(fabs(c - centre_) < bound);
    }
    const Group& g_;
    real centre_;
  };
  static const real& coordinate(const Vec3& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
  std::vector<Remembered> remembered_;
  std::vector<Group> groups_;
};

}  // namespace edgetrack
