// SPDX-License-Identifier: BSD-3-Clause
/// The edge profile memory between frames.
#include "edgetrack/edge_profile_memory.h"

#include <cmath>

namespace edgetrack {
namespace {

/// Profile levels are grey x 16: bilinear weights in sixteenths keep them integers.
constexpr int kLevelScale = 16;
/// Gauss-Newton steps of the sub-pixel fit, and the step below which it stops (pixels).
constexpr int kRefinements = 3;
constexpr double kSmallestStep = 1.0 / 64;

/// |a - b| summed over the axes, metres (as the contrast memory: no squares, which S47.16 would
/// round at millimetres).
real taxicab(const Vec3& a, const Vec3& b) {
  using std::fabs;
  return fabs(a.x - b.x) + fabs(a.y - b.y) + fabs(a.z - b.z);
}

/// The grey level x 16 at (x, y), bilinear in sixteenths of a pixel; false outside the image.
bool level_at(const vpImage<unsigned char>& grey, const real& x, const real& y, int16_t& out) {
  const real fine_x = real(kLevelScale) * x, fine_y = real(kLevelScale) * y;
  if (!(fine_x >= real(0) && fine_y >= real(0))) return false;
  const int ix = static_cast<int>(fine_x), iy = static_cast<int>(fine_y);
  const int x0 = ix / kLevelScale, y0 = iy / kLevelScale, fx = ix % kLevelScale, fy = iy % kLevelScale;
  if (x0 + 1 >= static_cast<int>(grey.getWidth()) || y0 + 1 >= static_cast<int>(grey.getHeight())) return false;
  const unsigned char* top = grey[y0] + x0;
  const unsigned char* bottom = grey[y0 + 1] + x0;
  const int upper = top[0] * (kLevelScale - fx) + top[1] * fx, lower = bottom[0] * (kLevelScale - fx) + bottom[1] * fx;
  out = static_cast<int16_t>((upper * (kLevelScale - fy) + lower * fy + kLevelScale / 2) / kLevelScale);
  return true;
}

/// The profile `levels` (index 0 at offset -reach) linearly interpolated at offset `at`, and its
/// slope there; `at` within [-reach, reach].
real interpolated(const int16_t* levels, int reach, const real& at, real& slope) {
  const real index = at + real(reach);
  int i = static_cast<int>(index);  // index >= 0: truncation is floor
  if (i >= 2 * reach) i = 2 * reach - 1;
  const real f = index - real(i);
  slope = real(levels[i + 1] - levels[i]);
  return real(levels[i]) + f * slope;
}

}  // namespace

void EdgeProfileMemory::sample(const vpImage<unsigned char>& grey, const std::vector<EdgeMatch>& matches,
                               int mask_size, int range) {
  half_ = mask_size / 2 + 1;
  if (half_ > kMaxProfileHalf) half_ = kMaxProfileHalf;
  range_ = range;
  const int reach = range + half_, length = 2 * reach + 1;
  sampled_.resize(matches.size() * static_cast<size_t>(length));
  valid_.assign(matches.size(), 1);
  for (size_t m = 0; m < matches.size(); ++m) {
    const ControlPoint& p = matches[m].point;
    int16_t* levels = &sampled_[m * static_cast<size_t>(length)];
    for (int t = -reach; t <= reach && valid_[m]; ++t)
      valid_[m] = level_at(grey, p.pixel.x + real(t) * p.normal.x, p.pixel.y + real(t) * p.normal.y, levels[t + reach]);
  }
}

void EdgeProfileMemory::keep(const EdgeMatch& match, size_t m, const real& anchor) {
  using std::floor;
  const int reach = range_ + half_;
  const int16_t* levels = &sampled_[m * static_cast<size_t>(2 * reach + 1)];
  Profile profile;
  profile.edge = match.point.edge;
  profile.point_in_model = match.point.point_in_model;
  real slope;
  for (int s = -half_; s <= half_; ++s)
    profile.level[s + half_] = static_cast<int16_t>(floor(interpolated(levels, reach, anchor + real(s), slope) + real(0.5)));
  remembered_.push_back(profile);
}

void EdgeProfileMemory::remember_at_points(const std::vector<EdgeMatch>& matches) {
  remembered_.clear();
  remembered_.reserve(matches.size());
  for (size_t m = 0; m < matches.size(); ++m)
    if (valid_[m]) keep(matches[m], m, real(0));
}

void EdgeProfileMemory::remember(const std::vector<EdgeMatch>& matches, const PinholeCamera& camera,
                                 const Se3& camera_from_model, const real& within) {
  using std::fabs;
  remembered_.clear();
  remembered_.reserve(matches.size());
  for (size_t m = 0; m < matches.size(); ++m) {
    const EdgeMatch& match = matches[m];
    if (match.outlier || !valid_[m]) continue;
    const Vec3 in_camera = camera_from_model * match.point.point_in_model;
    if (in_camera.z <= real(0)) continue;
    const Vec2 projected = camera.project(in_camera);
    if (!(fabs(dot(match.point.normal, projected - match.found)) < within)) continue;
    // The profile at the projection, read from this frame's samples: within their reach.
    const real anchor = dot(match.point.normal, projected - match.point.pixel);
    if (!(fabs(anchor) < real(range_))) continue;
    keep(match, m, anchor);
  }
}

const EdgeProfileMemory::Profile* EdgeProfileMemory::nearest(const ControlPoint& point, size_t first, size_t end,
                                                             const real& reach_m) const {
  const Profile* best = nullptr;
  real nearest = reach_m;
  for (size_t k = first; k < end; ++k) {
    const Profile& p = remembered_[k];
    const real d = taxicab(p.point_in_model, point.point_in_model);
    if (d < nearest) {
      nearest = d;
      best = &p;
    }
  }
  return best;
}

void EdgeProfileMemory::relocate(const PinholeCamera& camera, const Se3& camera_from_model, const real& reach,
                                 std::vector<EdgeMatch>& matches) const {
  using std::fabs;
  const int reach_samples = range_ + half_, length = 2 * reach_samples + 1, n = 2 * half_ + 1;
  // Both come grouped by primitive: [first, end) are the profiles of the match's primitive.
  size_t first = 0, end = 0;
  int edge = -1;
  for (size_t m = 0; m < matches.size() && !remembered_.empty(); ++m) {
    EdgeMatch& match = matches[m];
    if (match.point.edge != edge) {
      edge = match.point.edge;
      for (first = 0; first < remembered_.size() && remembered_[first].edge != edge; ++first) {
      }
      for (end = first; end < remembered_.size() && remembered_[end].edge == edge; ++end) {
      }
    }
    if (!valid_[m]) continue;
    const real depth = (camera_from_model * match.point.point_in_model).z;
    if (depth <= real(0)) continue;
    // `reach` pixels at this depth in metres, doubled for the taxicab bound (contrast_memory.cpp).
    const Profile* profile = nearest(match.point, first, end, real(2) * reach * depth / camera.px);
    if (!profile) continue;
    const int16_t* levels = &sampled_[m * static_cast<size_t>(length)];
    const int16_t* kept = profile->level;
    // Integer shifts: n times the least squares after the mean difference is removed.
    int64_t best = -1;
    int best_shift = 0;
    for (int d = -range_; d <= range_; ++d) {
      int64_t sum = 0, squares = 0;
      for (int s = 0; s < n; ++s) {
        const int e = levels[d + s + range_] - kept[s];
        sum += e;
        squares += e * e;
      }
      const int64_t misfit = n * squares - sum * sum;
      if (best < 0 || misfit < best) {
        best = misfit;
        best_shift = d;
      }
    }
    int64_t sum = 0, squares = 0;
    for (int s = 0; s < n; ++s) {
      sum += kept[s];
      squares += kept[s] * kept[s];
    }
    const int64_t variation = n * squares - sum * sum;
    if (best_shift == -range_ || best_shift == range_ || 2 * best > variation) continue;
    // Gauss-Newton on the interpolated profile, within a pixel of the best whole shift.
    real shift(best_shift);
    for (int k = 0; k < kRefinements; ++k) {
      real e_sum(0), g_sum(0), eg(0), gg(0);
      for (int s = 0; s < n; ++s) {
        real g;
        const real e = interpolated(levels, reach_samples, shift + real(s - half_), g) - real(kept[s]);
        e_sum += e;
        g_sum += g;
        eg += e * g;
        gg += g * g;
      }
      const real centred_gg = gg - g_sum * g_sum / real(n);
      if (!(centred_gg > real(0))) break;
      const real step = -(eg - e_sum * g_sum / real(n)) / centred_gg;
      shift += step;
      if (shift < real(best_shift - 1)) shift = real(best_shift - 1);
      if (shift > real(best_shift + 1)) shift = real(best_shift + 1);
      if (fabs(step) < real(kSmallestStep)) break;
    }
    const Vec2 fitted = match.point.pixel + shift * match.point.normal;
    // The moving edge's maximum nearest to the fitted position, where one lies within a pixel.
    real nearest = fabs(dot(match.point.normal, match.found - fitted));
    int chosen = 0;
    for (int a = 0; a < match.alternative_count; ++a) {
      const real d = fabs(dot(match.point.normal, match.alternatives[a] - fitted));
      if (d < nearest) { nearest = d; chosen = a + 1; }
    }
    if (!(nearest < real(1))) {
      match.found = fitted;
    } else if (chosen > 0) {
      const Vec2 strongest = match.found;
      match.found = match.alternatives[chosen - 1];
      match.alternatives[chosen - 1] = strongest;
    }
  }
}

}  // namespace edgetrack
