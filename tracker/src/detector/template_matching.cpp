// SPDX-License-Identifier: BSD-3-Clause
/// Linearised-memory template matching and the pose of a match.
#include "edgetrack/detector/template_matching.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace edgetrack {

namespace {

/// One block of kRunPadWords sums, kept in registers while the runs are added.
struct Block {
  uint32_t s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0;
};

/// Adds word k + w of each run in [first, last) to the block's sum w.
inline void add_runs(const uint32_t* const* first, const uint32_t* const* last, size_t k, Block& b) {
  uint32_t s0 = b.s0, s1 = b.s1, s2 = b.s2, s3 = b.s3, s4 = b.s4, s5 = b.s5, s6 = b.s6, s7 = b.s7;
  for (const uint32_t* const* run = first; run != last; ++run) {
    const uint32_t* p = *run + k;
    s0 += p[0];
    s1 += p[1];
    s2 += p[2];
    s3 += p[3];
    s4 += p[4];
    s5 += p[5];
    s6 += p[6];
    s7 += p[7];
  }
  b.s0 = s0, b.s1 = s1, b.s2 = s2, b.s3 = s3, b.s4 = s4, b.s5 = s5, b.s6 = s6, b.s7 = s7;
}

/// Whether a byte of the block reaches `cut` (1 to 128), every byte at most 127 and `lift`
/// 128 - cut in each byte: adding it sets a byte's top bit exactly when the byte reaches cut,
/// with no carry into the next byte.
inline bool any_reaches(const Block& b, uint32_t lift) {
  return (((b.s0 + lift) | (b.s1 + lift) | (b.s2 + lift) | (b.s3 + lift) | (b.s4 + lift) | (b.s5 + lift) |
           (b.s6 + lift) | (b.s7 + lift)) &
          0x80808080u) != 0;
}

/// Runs added between the tests of whether a block can still reach the least score.
constexpr int kRunsPerTest = 2;

/// scores[k] = the sum over the runs of run[k], k < count (rounded up to blocks of
/// kRunPadWords), four byte-wide positions per 32-bit add (no carry crosses a byte: a
/// template's sum stays under 256). A block of sums stays in registers over all the runs: two
/// instructions per word and run on a 32-bit core, where adding run by run into memory takes six.
/// Only scores from `need` on count (best_position): from half the runs on, a block whose every
/// partial sum stays under `need` even with the best similarity in each run left is left with
/// its partial sums (all under `need`); on clutter most blocks are left so within a few runs.
/// False when every block was left so: no position reaches `need`.
bool sum_runs(const std::vector<const uint32_t*>& runs, size_t count, int need, uint32_t* scores) {
  static_assert(kRunPadWords == 8, "the block below is 8 words");
  const uint32_t* const* begin = runs.data();
  const int n = static_cast<int>(runs.size()), half = n / 2;
  // The tests after `done` runs, while partial sums stay under 128 (done <= 31): the score a
  // partial sum must reach (cut) and, when that is at most 128, its lift.
  struct Test {
    int done;
    int cut;
    uint32_t lift;
  };
  Test tests[32];
  int test_count = 0;
  for (int done = half; done < n && kBestSimilarity * done < 128; done += kRunsPerTest) {
    const int cut = need - kBestSimilarity * (n - done);
    if (cut <= 0) continue;
    tests[test_count++] = {done, cut, static_cast<uint32_t>(128 - std::min(cut, 128)) * 0x01010101u};
  }
  bool any_kept = false;
  for (size_t k = 0; k < count; k += kRunPadWords) {
    Block b;
    int done = 0;
    bool out_of_reach = false;
    for (int i = 0; i < test_count && !out_of_reach; ++i) {
      add_runs(begin + done, begin + tests[i].done, k, b);
      done = tests[i].done;
      out_of_reach = tests[i].cut > 128 || !any_reaches(b, tests[i].lift);
    }
    if (!out_of_reach) add_runs(begin + done, begin + n, k, b);
    any_kept = any_kept || !out_of_reach;
    uint32_t* out = scores + k;
    out[0] = b.s0;
    out[1] = b.s1;
    out[2] = b.s2;
    out[3] = b.s3;
    out[4] = b.s4;
    out[5] = b.s5;
    out[6] = b.s6;
    out[7] = b.s7;
  }
  return any_kept;
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

/// The share of `score` for a template of `count` features, as a match's share is computed.
real share_of(int score, int count) { return real(score) / real(kBestSimilarity * count); }

/// The smallest score whose share for `count` features exceeds `share` (a later template, its
/// index higher, needs a strictly higher share to pass a full list's last), at most 4 * count + 1.
int least_above(const real& share, int count) {
  const int full = kBestSimilarity * count;
  int s = std::min(full + 1, std::max(0, static_cast<int>(share * real(full))));
  while (s > 0 && share_of(s - 1, count) > share) --s;
  while (s <= full && !(share_of(s, count) > share)) ++s;
  return s;
}

/// Inserts `m` into `best` (sorted, best first) when it is among the `limit` best; true then.
bool keep_best(const TemplateMatch& m, int limit, std::vector<TemplateMatch>& best) {
  if (static_cast<int>(best.size()) == limit && !better(m, best.back())) return false;
  best.insert(std::upper_bound(best.begin(), best.end(), m, better), m);
  if (static_cast<int>(best.size()) > limit) best.pop_back();
  return true;
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
  // Per distance and feature count, the least score entering the full list (-1: not yet known).
  std::vector<std::array<int, 64>> need_above(static_cast<size_t>(set.distance_count));
  for (std::array<int, 64>& row : need_above) row.fill(-1);
  // A feature's grid cell and offset in it (x / t, x % t), looked up: no division per feature.
  uint8_t cell[256], offset[256];
  for (int x = 0, c = 0, o = 0; x < 256; ++x) {
    cell[x] = static_cast<uint8_t>(c);
    offset[x] = static_cast<uint8_t>(o);
    if (++o == t) o = 0, ++c;
  }
  for (size_t index = 0; index < set.templates.size(); ++index) {
    const Template& tp = set.templates[index];
    const int valid_w = gw - (tp.width > 0 ? cell[tp.width - 1] : 0), valid_h = gh - (tp.height > 0 ? cell[tp.height - 1] : 0);
    if (valid_w <= 0 || valid_h <= 0) continue;
    const size_t span = static_cast<size_t>((valid_h - 1) * gw + valid_w), words = (span + 3) / 4;
    // While its distance's list is full, a template only counts where it would enter it.
    int need = least[tp.count];
    std::vector<TemplateMatch>& list = per_distance[static_cast<size_t>(tp.distance_index)];
    if (static_cast<int>(list.size()) == params.max_candidates) {
      const TemplateMatch& last = list.back();
      int& above = need_above[static_cast<size_t>(tp.distance_index)][tp.count];
      if (above < 0) above = least_above(last.share, tp.count);
      need = std::max(need, above);
    }
    if (need > kBestSimilarity * tp.count) continue;
    runs.clear();
    for (int f = tp.first; f < tp.first + tp.count; ++f) {
      const TemplateFeature& feature = set.features[static_cast<size_t>(f)];
      const size_t start = static_cast<size_t>(cell[feature.y] * gw + cell[feature.x]);
      runs.push_back(maps.words(feature.bin, offset[feature.x], offset[feature.y], start));
    }
    if (!sum_runs(runs, words, need, scores.data())) continue;
    const BestPosition best = best_position(score_bytes, span, gw, valid_w, need, kBestSimilarity * tp.count);
    if (best.score < 0) continue;
    TemplateMatch m;
    m.template_index = static_cast<int>(index);
    m.x = static_cast<int>(best.index % static_cast<size_t>(gw)) * t;
    m.y = static_cast<int>(best.index / static_cast<size_t>(gw)) * t;
    m.score = best.score;
    m.share = real(best.score) / real(kBestSimilarity * tp.count);
    if (m.share >= params.min_share && keep_best(m, params.max_candidates, list))
      std::fill(std::begin(need_above[static_cast<size_t>(tp.distance_index)]),
                std::end(need_above[static_cast<size_t>(tp.distance_index)]), -1);
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
