// SPDX-License-Identifier: BSD-3-Clause
/// The contrast memory between frames.
#include "edgetrack/contrast_memory.h"

#include <cmath>
#include <type_traits>

namespace edgetrack {
namespace {

/// Whether |a - b| summed over the axes (metres: no squares, which S47.16 would round at
/// millimetres) is below `bound`, and then that sum in `distance`. The partial sums only grow,
/// so an axis that alone reaches the bound settles it without the others.
bool taxicab_below(const Vec3& a, const Vec3& b, const real& bound, real& distance) {
  using std::fabs;
  if constexpr (std::is_floating_point<real>::value) {
    // The same test without its branches (a host CPU mispredicts them): the last partial sum
    // is below the bound exactly when all are.
    const real whole = fabs(a.x - b.x) + fabs(a.y - b.y) + fabs(a.z - b.z);
    if (!(whole < bound)) return false;
    distance = whole;
    return true;
  }
  real d = fabs(a.x - b.x);
  if (!(d < bound)) return false;
  d += fabs(a.y - b.y);
  if (!(d < bound)) return false;
  d += fabs(a.z - b.z);
  if (!(d < bound)) return false;
  distance = d;
  return true;
}

/// The depth of a model point in the camera frame: the z row of camera_from_model * point alone,
/// summed in the same order, so the same value without the x and y rows.
real depth_in_camera(const Se3& camera_from_model, const Vec3& point) {
  const Mat33& r = camera_from_model.rotation();
  return r.m[2][0] * point.x + r.m[2][1] * point.y + r.m[2][2] * point.z + camera_from_model.translation().z;
}

/// Whether the point p (camera frame, z > 0) projects within `within` pixels of `found` along
/// `normal`: the distance times z, so that the projection needs no division. `through_lens`:
/// camera.distorted(), asked once per frame; `pixel`, when given, p's projection through it.
bool projects_near(const PinholeCamera& camera, bool through_lens, const Vec3& p, const Vec2* pixel, const Vec2& normal,
                   const Vec2& found, const real& within) {
  using std::fabs;
  if (through_lens) return fabs(dot(normal, (pixel ? *pixel : camera.project_through_lens(p)) - found)) < within;
  const real along_times_z = normal.x * (camera.px * p.x + (camera.u0 - found.x) * p.z) +
                             normal.y * (camera.py * p.y + (camera.v0 - found.y) * p.z);
  return fabs(along_times_z) < within * p.z;
}

}  // namespace

void ContrastMemory::remember(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera,
                              const Se3& camera_from_model, const real& within,
                              const ProjectedPoints* projected) {
  using std::fabs;
  remembered_.clear();
  groups_.clear();
  // Sized by the matches, so that it grows only on a frame with more matches than any before.
  remembered_.reserve(matches.size());
  const bool through_lens = camera.distorted();
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
    const size_t group_first = remembered_.size();
    for (size_t k = first; k < end; ++k) {
      const EdgeMatch& m = matches[k];
      if (m.outlier || fabs(m.contrast) < half_mean) continue;
      // The match's point at the pose, and through a lens its pixel: shared, else computed here.
      Vec3 own;
      const Vec3* p = &own;
      const Vec2* pixel = nullptr;
      if (projected) {
        const size_t v = static_cast<size_t>(m.point_index);
        if (!projected->in_front[v]) continue;
        p = &projected->in_camera[v];
        pixel = &projected->pixel[v];
      } else {
        own = camera_from_model * m.point.point_in_model;
        if (own.z <= real(0)) continue;
      }
      if (!projects_near(camera, through_lens, *p, pixel, m.point.normal, m.found, within)) continue;
      remembered_.push_back({m.point.point_in_model, m.contrast});
    }
    if (remembered_.size() > group_first) add_group(matches[first].point.edge, group_first);
    first = end;
  }
}

void ContrastMemory::add_group(int edge, size_t first) {
  using std::fabs;
  Group g;
  g.edge = edge;
  g.first = first;
  g.end = remembered_.size();
  // The axis of the largest change from the first point to the last: a straight edge's.
  const Vec3 spread = remembered_[g.end - 1].point_in_model - remembered_[first].point_in_model;
  const real sx = fabs(spread.x), sy = fabs(spread.y), sz = fabs(spread.z);
  g.axis = sx >= sy && sx >= sz ? 0 : sy >= sz ? 1 : 2;
  bool grows = true, falls = true;
  for (size_t k = first + 1; k < g.end; ++k) {
    const real& before = coordinate(remembered_[k - 1].point_in_model, g.axis);
    const real& after = coordinate(remembered_[k].point_in_model, g.axis);
    grows = grows && !(after < before);
    falls = falls && !(after > before);
  }
  g.order = grows ? 1 : falls ? -1 : 0;
  groups_.push_back(g);
}

void ContrastMemory::references(const std::vector<ControlPoint>& points, const PinholeCamera& camera,
                                const Se3& camera_from_model, const real& reach, std::vector<real>& out,
                                std::vector<unsigned char>& borrowed) const {
  out.assign(points.size(), real(0));
  borrowed.assign(points.size(), 0);
  // The remembered points come grouped by primitive (groups_): the current point's group is
  // found again only when the primitive changes, with its mean contrast when its points share
  // one polarity (else 0).
  const Group none;
  const Group* g = &none;
  int edge = -1;
  size_t from = 0;  // the previous point's first candidate: the next one's lies near it
  real primitive(0);
  // `reach` pixels at depth 1 m, in metres, doubled: the bound is on the taxicab distance, 1 to
  // sqrt(3) times the straight one, so every point within reach passes it.
  const real bound_per_metre = real(2) * reach / camera.px;
  const size_t count = points.size();  // in a local: the stores to out[] could alias the vector's size
  for (size_t p = 0; p < count; ++p) {
    const ControlPoint& point = points[p];
    if (point.edge != edge) {
      edge = point.edge;
      g = &none;
      for (const Group& candidate : groups_)
        if (candidate.edge == edge) {
          g = &candidate;
          break;
        }
      primitive = mean_of_one_polarity(g->first, g->end);
      from = g->first;
    }
    const real depth = depth_in_camera(camera_from_model, point.point_in_model);
    if (depth <= real(0)) continue;
    real nearest = bound_per_metre * depth;
    const Window window(*g, point.point_in_model);
    from = window.first_candidate(remembered_, from, nearest);
    for (size_t k = from; k < g->end; ++k) {
      const Vec3& candidate = remembered_[k].point_in_model;
      if (taxicab_below(candidate, point.point_in_model, nearest, nearest))
        out[p] = remembered_[k].contrast;
      else if (window.after(candidate, nearest))
        break;  // nearest only shrinks: the points after this one fail it too
    }
    if (out[p] == real(0) && primitive != real(0)) {
      out[p] = primitive;
      borrowed[p] = 1;
    }
  }
}

real ContrastMemory::mean_of_one_polarity(size_t first, size_t end) const {
  real sum(0);
  int positive = 0;
  for (size_t k = first; k < end; ++k) {
    sum += remembered_[k].contrast;
    positive += remembered_[k].contrast > real(0);
  }
  const int count = static_cast<int>(end - first);
  if (count == 0 || (positive != 0 && positive != count)) return real(0);
  return sum / real(count);
}

}  // namespace edgetrack
