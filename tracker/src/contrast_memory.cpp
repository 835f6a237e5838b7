// SPDX-License-Identifier: BSD-3-Clause
/// The contrast memory between frames.
#include "edgetrack/contrast_memory.h"

#include <cmath>

namespace edgetrack {
namespace {

/// |a - b| summed over the axes, metres: no squares, which S47.16 would round at millimetres.
real taxicab(const Vec3& a, const Vec3& b) {
  using std::fabs;
  return fabs(a.x - b.x) + fabs(a.y - b.y) + fabs(a.z - b.z);
}

}  // namespace

void ContrastMemory::remember(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera,
                              const Se3& camera_from_model, const real& within) {
  using std::fabs;
  remembered_.clear();
  // Sized by the matches, so that it grows only on a frame with more matches than any before.
  remembered_.reserve(matches.size());
  // Mean |contrast| per primitive over the kept matches (matches come grouped by primitive).
  size_t first = 0;
  while (first < matches.size()) {
    size_t end = first;
    real sum(0);
    int count = 0;
    for (; end < matches.size() && matches[end].point.edge == matches[first].point.edge; ++end)
      if (!matches[end].outlier) {
        sum += fabs(matches[end].contrast);
        ++count;
      }
    const real half_mean = count > 0 ? sum / real(2 * count) : real(0);
    for (size_t k = first; k < end; ++k) {
      const EdgeMatch& m = matches[k];
      if (m.outlier || fabs(m.contrast) < half_mean) continue;
      const Vec3 p = camera_from_model * m.point.point_in_model;
      if (p.z <= real(0) || !(fabs(dot(m.point.normal, camera.project(p) - m.found)) < within)) continue;
      remembered_.push_back({m.point.edge, m.point.point_in_model, m.contrast});
    }
    first = end;
  }
}

void ContrastMemory::references(const std::vector<ControlPoint>& points, const PinholeCamera& camera,
                                const Se3& camera_from_model, const real& reach, std::vector<real>& out) const {
  out.assign(points.size(), real(0));
  // The remembered points come grouped by primitive: [first, end) are those of the current
  // point's, found again only when the primitive changes.
  size_t first = 0, end = 0;
  int edge = -1;
  for (size_t p = 0; p < points.size(); ++p) {
    const ControlPoint& point = points[p];
    if (point.edge != edge) {
      edge = point.edge;
      for (first = 0; first < remembered_.size() && remembered_[first].edge != edge; ++first) {
      }
      for (end = first; end < remembered_.size() && remembered_[end].edge == edge; ++end) {
      }
    }
    const real depth = (camera_from_model * point.point_in_model).z;
    if (depth <= real(0)) continue;
    // `reach` pixels at this depth, in metres, doubled: the bound is on the taxicab distance,
    // 1 to sqrt(3) times the straight one, so every point within reach passes it.
    real nearest = real(2) * reach * depth / camera.px;
    for (size_t k = first; k < end; ++k) {
      const real d = taxicab(remembered_[k].point_in_model, point.point_in_model);
      if (d < nearest) {
        nearest = d;
        out[p] = remembered_[k].contrast;
      }
    }
  }
}

}  // namespace edgetrack
