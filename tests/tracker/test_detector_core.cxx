// SPDX-License-Identifier: BSD-3-Clause
/// The detector's portable core on known inputs: the orientation bins of known gradients, the
/// quantised orientations of step edges, spreading over T x T, the similarity table and the
/// linearised memory's layout, a hand-made template found where it was drawn, the viewpoint
/// sphere, the templates made from the cube (bounded, well spread, within 4 MB), and the
/// detector's parameter limits.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "edgetrack/detector/detector.h"
#include "edgetrack/detector/gradient_orientations.h"
#include "edgetrack/detector/response_maps.h"
#include "edgetrack/detector/template_matching.h"
#include "edgetrack/detector/template_set.h"
#include "edgetrack/detector/viewpoints.h"
#include "edgetrack/model_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// A grey image of `background` with the rectangle [x0, x1) x [y0, y1) at `inside`.
std::vector<uint8_t> rectangle_image(int w, int h, int x0, int y0, int x1, int y1, uint8_t background, uint8_t inside) {
  std::vector<uint8_t> grey(static_cast<size_t>(w) * h, background);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) grey[static_cast<size_t>(y) * w + x] = inside;
  return grey;
}

int count_bits(const OrientationImage& image, uint8_t mask) {
  int n = 0;
  for (uint8_t b : image.bits) n += (b & mask) != 0;
  return n;
}

void test_bins() {
  TEST_EQUAL("+x is bin 0", orientation_bin(100, 0), 0);
  TEST_EQUAL("-x is bin 0 too (modulo 180 degrees)", orientation_bin(-100, 0), 0);
  TEST_EQUAL("9.1 degrees is bin 0", orientation_bin(100, 16), 0);
  TEST_EQUAL("16.7 degrees is bin 1", orientation_bin(10, 3), 1);
  TEST_EQUAL("26.6 degrees is bin 1", orientation_bin(10, 5), 1);
  TEST_EQUAL("45 degrees is bin 2", orientation_bin(10, 10), 2);
  TEST_EQUAL("84 degrees is bin 4", orientation_bin(10, 95), 4);
  TEST_EQUAL("+y (90 degrees, image down) is bin 4", orientation_bin(0, 50), 4);
  TEST_EQUAL("-y is bin 4 too", orientation_bin(0, -50), 4);
  TEST_EQUAL("135 degrees is bin 6", orientation_bin(-10, 10), 6);
  TEST_EQUAL("-45 degrees is 135: bin 6", orientation_bin(10, -10), 6);
  TEST_EQUAL("163 degrees is bin 7", orientation_bin(-100, 30), 7);
  TEST_EQUAL("171 degrees is bin 0 (modulo 180 degrees)", orientation_bin(-100, 16), 0);
}

void test_quantised_step_edges() {
  const int w = 40, h = 30;
  OrientationParams params;
  std::vector<uint8_t> scratch;
  OrientationImage out;
  // A vertical step edge: the gradient is along x, bin 0, in the columns beside the step only.
  std::vector<uint8_t> grey = rectangle_image(w, h, 20, 0, w, h, 50, 200);
  quantise_orientations(grey.data(), w, h, params, scratch, out);
  int on_edge = 0, elsewhere = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t b = out.bits[static_cast<size_t>(y) * w + x];
      if (x == 19 || x == 20) on_edge += b == 1;
      else elsewhere += b != 0;
    }
  TEST_EQUAL("a vertical step gives bin 0 on both columns beside it (rows clear of the border)", on_edge, 2 * (h - 4));
  TEST_EQUAL("and nothing elsewhere", elsewhere, 0);
  // A horizontal step: bin 4.
  grey = rectangle_image(w, h, 0, 15, w, h, 200, 60);
  quantise_orientations(grey.data(), w, h, params, scratch, out);
  TEST_EQUAL("a horizontal step gives bin 4 only", count_bits(out, 0xff), count_bits(out, 1u << 4));
  TEST("and gives it along the step", count_bits(out, 1u << 4) >= 2 * (w - 4), true);
  // A step of 10 grey levels (Sobel magnitude 40) is under the threshold.
  grey = rectangle_image(w, h, 20, 0, w, h, 100, 110);
  quantise_orientations(grey.data(), w, h, params, scratch, out);
  TEST_EQUAL("a weak step gives no orientation", count_bits(out, 0xff), 0);
  // One bright pixel: strong gradients around it, but no bin dominates a 3x3 neighbourhood.
  grey = rectangle_image(w, h, 20, 15, 21, 16, 80, 250);
  quantise_orientations(grey.data(), w, h, params, scratch, out);
  TEST_EQUAL("an isolated pixel is rejected by the 3x3 dominance rule", count_bits(out, 0xff), 0);
}

void test_spreading() {
  OrientationImage in;
  in.width = 12;
  in.height = 10;
  in.bits.assign(120, 0);
  in.bits[5 * 12 + 6] = 1u << 3;
  in.bits[5 * 12 + 7] = 1u << 5;
  std::vector<uint8_t> scratch;
  OrientationImage out;
  spread_orientations(in, 4, scratch, out);
  int with_3 = 0, inside = 0;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 12; ++x) {
      const bool has = (out.bits[static_cast<size_t>(y) * 12 + x] & (1u << 3)) != 0;
      with_3 += has;
      inside += has && x >= 3 && x <= 6 && y >= 2 && y <= 5;
    }
  TEST_EQUAL("a bit spreads over the 4 x 4 pixels up and left of it", with_3, 16);
  TEST_EQUAL("exactly those", inside, 16);
  TEST_EQUAL("two bits OR together where both reach", out.bits[4 * 12 + 5], (1u << 3) | (1u << 5));
  TEST_EQUAL("a pixel right of the bit does not get it", out.bits[5 * 12 + 7] & (1u << 3), 0u);
}

void test_response_maps() {
  TEST_EQUAL("the same bin scores 4", similarity(2, 1u << 2), 4);
  TEST_EQUAL("a neighbouring bin scores 1", similarity(2, 1u << 3), 1);
  TEST_EQUAL("bins 0 and 7 are neighbours (modulo 180 degrees)", similarity(0, 1u << 7), 1);
  TEST_EQUAL("two bins away scores 0", similarity(2, 1u << 4), 0);
  TEST_EQUAL("the best bin of a set counts", similarity(2, (1u << 3) | (1u << 2)), 4);
  OrientationImage spread;
  spread.width = 16;
  spread.height = 12;
  for (int i = 0; i < 16 * 12; ++i) spread.bits.push_back(static_cast<uint8_t>((i * 37) & 0xff));
  ResponseMaps maps;
  maps.compute(spread, 4);
  TEST_EQUAL("the grid is 4 x 3", maps.grid_width() * 10 + maps.grid_height(), 43);
  // Checked on the first maps, and again after maps of an image scoring 4 everywhere were made
  // in the same buffers: nothing of those may remain, past the cells included.
  OrientationImage full = spread;
  for (uint8_t& b : full.bits) b = 0xff;
  for (const bool reused : {false, true}) {
    if (reused) {
      maps.compute(full, 4);
      maps.compute(spread, 4);
    }
    int wrong = 0;
    for (int bin = 0; bin < kOrientationBins; ++bin)
      for (int dy = 0; dy < 4; ++dy)
        for (int dx = 0; dx < 4; ++dx)
          for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 4; ++i)
              wrong += maps.linear(bin, dx, dy)[j * 4 + i] != similarity(bin, spread.bits[(dy + 4 * j) * 16 + dx + 4 * i]);
    TEST_EQUAL("linearised memory holds pixel (dx + T i, dy + T j) at j * grid width + i", wrong, 0);
    int misread = 0, past = 0;
    for (size_t start = 0; start < 12; ++start) {
      const uint8_t* as_bytes = reinterpret_cast<const uint8_t*>(maps.words(5, 1, 2, start));
      for (size_t j = 0; start + j < 12; ++j) misread += as_bytes[j] != maps.linear(5, 1, 2)[start + j];
      for (size_t j = 12 - start; j < 4 * kRunPadWords; ++j) past += as_bytes[j] != 0;
    }
    TEST_EQUAL("a run read as aligned words from any start holds the same bytes", misread, 0);
    TEST_EQUAL("and zeros past the cells, for the matching's blocks of words", past, 0);
  }
}

/// A square outline template: features on its four sides with their normals' bins.
TemplateSet square_template(int side) {
  TemplateSet set;
  set.distance_count = 1;
  Template t;
  t.width = side;
  t.height = side;
  for (int k = 0; k < side; k += 4) {
    set.features.push_back({static_cast<uint8_t>(k), 0, 4});
    set.features.push_back({static_cast<uint8_t>(k), static_cast<uint8_t>(side - 1), 4});
    set.features.push_back({0, static_cast<uint8_t>(k), 0});
    set.features.push_back({static_cast<uint8_t>(side - 1), static_cast<uint8_t>(k), 0});
  }
  t.count = static_cast<int>(set.features.size());
  set.templates.push_back(t);
  return set;
}

/// The response maps of `grey` with the default orientation settings, spread over t x t.
void compute_maps(const std::vector<uint8_t>& grey, int w, int h, int t, ResponseMaps& maps) {
  std::vector<uint8_t> scratch;
  OrientationImage q, spread;
  quantise_orientations(grey.data(), w, h, OrientationParams{}, scratch, q);
  spread_orientations(q, t, scratch, spread);
  maps.compute(spread, t);
}

void test_template_found_in_place() {
  const int w = 160, h = 120, t = 4;
  // A bright square whose outline pixels (the template's features) are at 48..71 x 28..51.
  const std::vector<uint8_t> grey = rectangle_image(w, h, 48, 28, 72, 52, 60, 190);
  ResponseMaps maps;
  compute_maps(grey, w, h, t, maps);
  const TemplateSet set = square_template(24);
  std::vector<uint32_t> scores;
  std::vector<const uint32_t*> runs;
  std::vector<std::vector<TemplateMatch>> per_distance;
  std::vector<TemplateMatch> matches;
  match_templates(set, maps, MatchParams{}, scores, runs, per_distance, matches);
  TEST_EQUAL("the template is found once", matches.size(), size_t(1));
  if (matches.empty()) return;
  std::printf("square found at %d,%d, share %.3f\n", matches[0].x, matches[0].y, static_cast<double>(matches[0].share));
  // The grid position within T - 1 pixels up and left of the drawn corner (47 or 48 is the edge).
  TEST("found within one grid step of where it was drawn",
       matches[0].x >= 48 - t && matches[0].x <= 48 && matches[0].y >= 28 - t && matches[0].y <= 28, true);
  TEST("with nearly every feature on its orientation", matches[0].share >= real(0.9), true);
}

/// The best grid position and score of template `tp` by a direct sum over every position.
TemplateMatch direct_best(const TemplateSet& set, const ResponseMaps& maps, size_t index) {
  const Template& tp = set.templates[index];
  const int t = maps.step(), gw = maps.grid_width(), gh = maps.grid_height();
  TemplateMatch best;
  best.score = -1;
  for (int j = 0; j < gh - (tp.height - 1) / t; ++j)
    for (int i = 0; i < gw - (tp.width - 1) / t; ++i) {
      int score = 0;
      for (int f = tp.first; f < tp.first + tp.count; ++f) {
        const TemplateFeature& a = set.features[static_cast<size_t>(f)];
        score += maps.linear(a.bin, a.x % t, a.y % t)[static_cast<size_t>(j + a.y / t) * gw + i + a.x / t];
      }
      if (score > best.score) {
        best.score = score;
        best.x = i * t;
        best.y = j * t;
      }
    }
  return best;
}

/// Matching every cube template on a cluttered image, with match shares that let the matching
/// pass over low words (0.6, 0.3) and one that makes it look at every position (0: 32 features
/// reach 128 over a threshold of 0), gives each kept template the direct sum's best position and
/// score.
void test_matching_equals_direct_sums() {
  const Result<EdgeModel> model = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  if (!model.ok()) return;
  TemplateParams params;
  params.views.subdivisions = 0;
  params.views.in_plane_steps = 4;
  const PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  const Result<TemplateSet> set = make_template_set(model.value(), camera, params);
  if (!set.ok()) return;
  const int w = 160, h = 120, t = 4;
  std::vector<uint8_t> grey(static_cast<size_t>(w) * h);
  uint32_t state = 12345;
  for (uint8_t& g : grey) g = static_cast<uint8_t>(100 + ((state = state * 1103515245u + 12345u) >> 28));
  for (int k = 0; k < 12; ++k) {
    state = state * 1103515245u + 12345u;
    const int x0 = static_cast<int>(state >> 25) % (w - 30), y0 = static_cast<int>(state >> 9) % (h - 30);
    for (int y = y0; y < y0 + 10 + k * 2 && y < h; ++y)
      for (int x = x0; x < x0 + 30 - k && x < w; ++x)
        grey[static_cast<size_t>(y) * w + x] = static_cast<uint8_t>(30 + 17 * k);
  }
  ResponseMaps maps;
  compute_maps(grey, w, h, t, maps);
  std::vector<uint32_t> scores;
  std::vector<const uint32_t*> runs;
  std::vector<std::vector<TemplateMatch>> per_distance;
  std::vector<TemplateMatch> matches;
  for (const real share : {real(0.6), real(0.3), real(0)}) {
    MatchParams match_params;
    match_params.min_share = share;
    match_params.max_candidates = 100;
    match_templates(set.value(), maps, match_params, scores, runs, per_distance, matches);
    int differ = 0, expected = 0;
    for (size_t index = 0; index < set.value().templates.size(); ++index) {
      const TemplateMatch direct = direct_best(set.value(), maps, index);
      const int count = set.value().templates[index].count;
      if (real(direct.score) / real(kBestSimilarity * count) < share) continue;
      ++expected;
      bool same = false;
      for (const TemplateMatch& m : matches)
        same = same || (m.template_index == static_cast<int>(index) && m.score == direct.score &&
                        m.x == direct.x && m.y == direct.y);
      differ += !same;
    }
    std::printf("share %.1f: %d of %zu templates kept, %zu matches\n", static_cast<double>(share), expected,
                set.value().templates.size(), matches.size());
    TEST("some templates reach the share", expected > 0, true);
    TEST_EQUAL("matching keeps exactly the templates the direct sums do", static_cast<int>(matches.size()), expected);
    TEST_EQUAL("each at the direct sums' first best position and score", differ, 0);
  }
  // With few kept per distance, a template's sums stop where it could not enter its distance's
  // full list: the lists are still the direct sums' best per distance (share, then index).
  std::vector<TemplateMatch> direct;
  for (size_t index = 0; index < set.value().templates.size(); ++index) {
    TemplateMatch m = direct_best(set.value(), maps, index);
    m.template_index = static_cast<int>(index);
    m.share = real(m.score) / real(kBestSimilarity * set.value().templates[index].count);
    direct.push_back(m);
  }
  auto better = [](const TemplateMatch& a, const TemplateMatch& b) {
    return a.share > b.share || (a.share == b.share && a.template_index < b.template_index);
  };
  std::stable_sort(direct.begin(), direct.end(), better);
  for (const int kept : {1, 3}) {
    MatchParams match_params;
    match_params.min_share = real(0.3);
    match_params.max_candidates = kept;
    match_templates(set.value(), maps, match_params, scores, runs, per_distance, matches);
    std::vector<TemplateMatch> expected;
    std::vector<int> per(static_cast<size_t>(set.value().distance_count), 0);
    for (const TemplateMatch& m : direct) {
      int& n = per[static_cast<size_t>(set.value().templates[static_cast<size_t>(m.template_index)].distance_index)];
      if (m.share >= match_params.min_share && n < kept) ++n, expected.push_back(m);
    }
    int differ = static_cast<int>(matches.size() != expected.size());
    for (size_t k = 0; k < matches.size() && k < expected.size(); ++k)
      differ += matches[k].template_index != expected[k].template_index || matches[k].score != expected[k].score ||
                matches[k].x != expected[k].x || matches[k].y != expected[k].y;
    std::printf("%d per distance: %zu matches over %d distances\n", kept, matches.size(), set.value().distance_count);
    TEST("more templates than kept at some distance", direct.size() > expected.size(), true);
    TEST_EQUAL("the matches are the direct sums' best per distance, in order", differ, 0);
  }
}

void test_viewpoints() {
  TEST_EQUAL("the icosahedron has 12 vertices", sphere_directions(0).size(), size_t(12));
  TEST_EQUAL("subdivided once: 42", sphere_directions(1).size(), size_t(42));
  TEST_EQUAL("twice: 162", sphere_directions(2).size(), size_t(162));
  double worst = 0;
  for (const Vec3& d : sphere_directions(2)) worst = std::fmax(worst, std::fabs(static_cast<double>(norm(d)) - 1));
  TEST_NEAR("every direction is a unit vector", worst, 0.0, 1e-4);
  const Vec3 centre{real(0.01), real(-0.02), real(0.03)};
  const Se3 pose = view_pose(normalized(Vec3{real(1), real(2), real(2)}), real(0.7), real(0.2), centre);
  const Vec3 c = pose * centre;
  TEST_NEAR("a view puts the model's centre on the optical axis", std::fabs(static_cast<double>(c.x)) +
                                                                      std::fabs(static_cast<double>(c.y)), 0.0, 1e-5);
  TEST_NEAR("at the view's distance", c.z, 0.2, 1e-5);
  const Vec3 eye = pose.inverse().translation() - centre;
  TEST_NEAR("seen from the view's direction", dot(normalized(eye), normalized(Vec3{real(1), real(2), real(2)})), 1.0,
            1e-4);
}

void test_cube_templates() {
  const Result<EdgeModel> model = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("the cube loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  TemplateParams params;
  params.views.subdivisions = 0;
  params.views.in_plane_steps = 4;
  const Result<TemplateSet> set = make_template_set(model.value(), camera, params);
  TEST("templates are made", set.ok(), true);
  if (!set.ok()) return;
  const TemplateSet& s = set.value();
  std::printf("%zu templates, %d distances, %zu bytes\n", s.templates.size(), s.distance_count, s.memory_bytes());
  TEST_EQUAL("every view of the cube shows enough edges: 12 directions x 4 turns x the distances", s.templates.size(),
             size_t(48 * s.distance_count));
  const PinholeCamera small = s.matching_camera();
  int bad = 0, crowded = 0, narrow = 0;
  for (const Template& t : s.templates) {
    bad += t.count < params.min_features || t.count > params.features;
    for (int f = t.first; f < t.first + t.count; ++f) {
      const TemplateFeature& a = s.features[static_cast<size_t>(f)];
      bad += a.x >= t.width || a.y >= t.height || a.bin >= kOrientationBins;
      // Well spread: no two features within 2 pixels (farthest-point selection over edges
      // sampled every 2 pixels keeps them apart).
      for (int g = f + 1; g < t.first + t.count; ++g) {
        const TemplateFeature& b = s.features[static_cast<size_t>(g)];
        const int dx = a.x - b.x, dy = a.y - b.y;
        crowded += dx * dx + dy * dy < 4;
      }
    }
    // And over the whole object: the features' box spans most of the projected cube's.
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const Vec3& v : model.value().vertices) {
      const Vec2 p = small.project(template_pose(t, s.extent) * v);
      x0 = std::fmin(x0, static_cast<double>(p.x));
      x1 = std::fmax(x1, static_cast<double>(p.x));
      y0 = std::fmin(y0, static_cast<double>(p.y));
      y1 = std::fmax(y1, static_cast<double>(p.y));
    }
    narrow += t.width < 0.8 * (x1 - x0) || t.height < 0.8 * (y1 - y0);
  }
  TEST_EQUAL("every template has between min_features and features features, inside its box", bad, 0);
  TEST_EQUAL("no two features of a template within 2 pixels", crowded, 0);
  TEST_EQUAL("every template's features span at least 80 % of the projected cube", narrow, 0);
  TemplateParams dense;
  dense.views.subdivisions = 2;
  dense.views.in_plane_steps = 24;
  const size_t per_template = sizeof(Template) + sizeof(TemplateFeature) * static_cast<size_t>(dense.features);
  std::printf("a dense set (162 directions x 24 turns x %d distances) would take %.2f MB\n", s.distance_count,
              static_cast<double>(per_template * 162 * 24 * static_cast<size_t>(s.distance_count)) / (1 << 20));
  TEST("a template with its features takes under 256 bytes", per_template < 256, true);
}

void test_detector_params() {
  TEST("the default detector parameters are accepted", check_detector_params(DetectorParams{}).ok(), true);
  auto refused = [](void (*change)(DetectorParams&)) {
    DetectorParams p;
    change(p);
    return !check_detector_params(p).ok();
  };
  TEST("a refining sample step under 2 px is refused",
       refused([](DetectorParams& p) { p.refine_sample_step = real(1); }), true);
  TEST("a screening sample step over 50 px is refused",
       refused([](DetectorParams& p) { p.screen_sample_step = real(60); }), true);
  TEST("negative robust rounds are refused",
       refused([](DetectorParams& p) { p.screen_robust_rounds = -1; }), true);
  TEST("a suppressed angle over 180 degrees is refused",
       refused([](DetectorParams& p) { p.suppress_deg = real(200); }), true);
  TEST("a negative suppressed distance is refused",
       refused([](DetectorParams& p) { p.suppress_radii = real(-1); }), true);
  TEST("a negative settled move is refused",
       refused([](DetectorParams& p) { p.settled_px = real(-1); }), true);
  TEST("a restart tilt over 90 degrees is refused",
       refused([](DetectorParams& p) { p.restart_tilt_deg = real(100); }), true);
  TEST("no restarts (a tilt of 0) are accepted",
       refused([](DetectorParams& p) { p.restart_tilt_deg = real(0); }), false);
  TEST("a confident kept share under the least kept share is refused",
       refused([](DetectorParams& p) { p.confident_kept_share = p.min_kept_share - real(0.1); }), true);
  TEST("a confident kept share equal to the least kept share is accepted",
       refused([](DetectorParams& p) { p.confident_kept_share = p.min_kept_share; }), false);
}

}  // namespace

static void test_detector_core() {
  test_bins();
  test_quantised_step_edges();
  test_spreading();
  test_response_maps();
  test_template_found_in_place();
  test_matching_equals_direct_sums();
  test_viewpoints();
  test_cube_templates();
  test_detector_params();
}

TESTMAIN(test_detector_core)
