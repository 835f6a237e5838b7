// SPDX-License-Identifier: BSD-3-Clause
/// Linearised-memory template matching and the pose of a match.
#include "edgetrack/detector/template_matching.h"

#include <algorithm>
#include <cmath>

namespace edgetrack {

namespace {

/// scores[k] = the sum over the runs of run[k], k < count (rounded up to blocks of
/// kRunPadWords), four byte-wide positions per 32-bit add (no carry crosses a byte: a
/// template's sum stays under 256). A block of sums stays in registers over all the runs: two
/// instructions per word and run on a 32-bit core, where adding run by run into memory takes six.
void sum_runs(const std::vector<const uint32_t*>& runs, size_t count, uint32_t* scores) {
  static_assert(kRunPadWords == 8, "the block below is 8 words");
  for (size_t k = 0; k < count; k += kRunPadWords) {
    uint32_t s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0;
    for (const uint32_t* run : runs) {
      const uint32_t* p = run + k;
      s0 += p[0];
      s1 += p[1];
      s2 += p[2];
      s3 += p[3];
      s4 += p[4];
      s5 += p[5];
      s6 += p[6];
      s7 += p[7];
    }
    uint32_t* out = scores + k;
    out[0] = s0;
    out[1] = s1;
    out[2] = s2;
    out[3] = s3;
    out[4] = s4;
    out[5] = s5;
    out[6] = s6;
    out[7] = s7;
  }
}

struct BestPosition {
  int score = -1;  ///< -1: no position reaches the least score asked for
  size_t index = 0;
};

/// The first highest score of bytes[0, span) at a valid position (index % gw < valid_w), among
/// those reaching `least`; every score is at most `most`. Where most - least < 128 and least
/// <= 128, a word whose four scores all stay under `least` is passed over with one add and one
/// test: adding 128 - least to each byte sets its top bit exactly when it reaches `least`, and
/// no byte carries into the next. Most words of most templates are passed over so.
BestPosition best_position(const uint8_t* bytes, size_t span, int gw, int valid_w, int least, int most) {
  BestPosition best;
  auto consider = [&](size_t k) {
    if (bytes[k] >= least && bytes[k] > best.score && static_cast<int>(k % static_cast<size_t>(gw)) < valid_w) {
      best.score = bytes[k];
      best.index = k;
    }
  };
  if (least > 128 || most - least > 127) {
    for (size_t k = 0; k < span; ++k) consider(k);
    return best;
  }
  const uint32_t lift = static_cast<uint32_t>(128 - least) * 0x01010101u;
  const uint32_t* words = reinterpret_cast<const uint32_t*>(bytes);
  for (size_t w = 0; w < (span + 3) / 4; ++w) {
    if (((words[w] + lift) & 0x80808080u) == 0) continue;
    for (size_t k = 4 * w; k < 4 * w + 4 && k < span; ++k) consider(k);
  }
  return best;
}

/// least[count]: the smallest score whose share of a template of `count` features reaches
/// min_share, computed as the match's share is, so that passing over lower scores changes nothing.
void least_scores(const real& min_share, int (&least)[64]) {
  for (int count = 1; count < 64; ++count) {
    const real full(kBestSimilarity * count);
    int s = 0;
    while (s <= kBestSimilarity * count && real(s) / full < min_share) ++s;
    least[count] = s;
  }
  least[0] = 0;
}

bool better(const TemplateMatch& a, const TemplateMatch& b) {
  return a.share > b.share || (a.share == b.share && a.template_index < b.template_index);
}

/// Inserts `m` into `best` (sorted, best first) when it is among the `limit` best.
void keep_best(const TemplateMatch& m, int limit, std::vector<TemplateMatch>& best) {
  if (static_cast<int>(best.size()) == limit && !better(m, best.back())) return;
  best.insert(std::upper_bound(best.begin(), best.end(), m, better), m);
  if (static_cast<int>(best.size()) > limit) best.pop_back();
}

}  // namespace

void match_templates(const TemplateSet& set, const ResponseMaps& maps, const MatchParams& params,
                     std::vector<uint32_t>& scores, std::vector<const uint32_t*>& runs,
                     std::vector<std::vector<TemplateMatch>>& per_distance, std::vector<TemplateMatch>& out) {
  out.clear();
  per_distance.resize(static_cast<size_t>(set.distance_count));
  for (std::vector<TemplateMatch>& list : per_distance) list.clear();
  const int t = maps.step(), gw = maps.grid_width(), gh = maps.grid_height();
  scores.resize((static_cast<size_t>(gw) * gh + 3) / 4 + kRunPadWords);
  const uint8_t* score_bytes = reinterpret_cast<const uint8_t*>(scores.data());
  int least[64];
  least_scores(params.min_share, least);
  for (size_t index = 0; index < set.templates.size(); ++index) {
    const Template& tp = set.templates[index];
    const int valid_w = gw - (tp.width - 1) / t, valid_h = gh - (tp.height - 1) / t;
    if (valid_w <= 0 || valid_h <= 0) continue;
    const size_t span = static_cast<size_t>((valid_h - 1) * gw + valid_w), words = (span + 3) / 4;
    runs.clear();
    for (int f = tp.first; f < tp.first + tp.count; ++f) {
      const TemplateFeature& feature = set.features[static_cast<size_t>(f)];
      const size_t start = static_cast<size_t>((feature.y / t) * gw + feature.x / t);
      runs.push_back(maps.words(feature.bin, feature.x % t, feature.y % t, start));
    }
    sum_runs(runs, words, scores.data());
    const BestPosition best =
        best_position(score_bytes, span, gw, valid_w, least[tp.count], kBestSimilarity * tp.count);
    if (best.score < 0) continue;
    TemplateMatch m;
    m.template_index = static_cast<int>(index);
    m.x = static_cast<int>(best.index % static_cast<size_t>(gw)) * t;
    m.y = static_cast<int>(best.index / static_cast<size_t>(gw)) * t;
    m.score = best.score;
    m.share = real(best.score) / real(kBestSimilarity * tp.count);
    if (m.share >= params.min_share)
      keep_best(m, params.max_candidates, per_distance[static_cast<size_t>(tp.distance_index)]);
  }
  for (const std::vector<TemplateMatch>& list : per_distance) out.insert(out.end(), list.begin(), list.end());
  std::sort(out.begin(), out.end(), better);
}

Se3 pose_of_match(const TemplateSet& set, const TemplateMatch& match, int t) {
  using std::atan2;
  const Template& tp = set.templates[static_cast<size_t>(match.template_index)];
  const PinholeCamera camera = set.matching_camera();
  const real bias = real(t - 1) / real(2);
  const Vec2 centre{real(match.x) + bias + tp.anchor.x, real(match.y) + bias + tp.anchor.y};
  const Vec3 ray = normalized(camera.unproject(centre, real(1)));
  // The rotation taking the optical axis onto the ray, about their common normal.
  const Vec3 axis{-ray.y, ray.x, real(0)};
  const real sine = norm(axis);
  Mat33 turn = Mat33::identity();
  if (sine > real(0)) turn = rotation_exp(atan2(sine, ray.z) / sine * axis);
  const Mat33 rotation = turn * Se3::from_theta_u(Vec3{}, tp.theta_u).rotation();
  const Vec3 translation = tp.distance * ray - rotation * set.extent.centre;
  return Se3(rotation, translation);
}

}  // namespace edgetrack
