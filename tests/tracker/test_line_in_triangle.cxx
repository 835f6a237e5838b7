// SPDX-License-Identifier: BSD-3-Clause
/// Edge-ID rasterises surfaces at its lines' pixels only (raster.h, line_in_triangle): for random
/// triangles, clip rectangles and lines (the triangles' own edges among them), it visits exactly the pixels of draw_line that
/// fill_triangle plots, in draw_line's order, with fill_triangle's w there; and the per-pixel
/// covers/depth_at agree with fill_triangle on the whole box, 32- and 64-bit edge functions alike;
/// most_above_line (Edge-ID's test that a triangle cannot hide a line) bounds the triangle's w over
/// the line's at each of those pixels.
#include <algorithm>
#include <random>
#include <vector>

#include "edgetrack/raster.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

constexpr int kWidth = 320, kHeight = 240;

struct Drawn {
  int x, y;
  int32_t w;
};

bool operator==(const Drawn& a, const Drawn& b) { return a.x == b.x && a.y == b.y && a.w == b.w; }

ScreenVertex random_vertex(std::mt19937& rng, int reach_pixels) {
  std::uniform_int_distribution<int32_t> at(-reach_pixels * 16, (kWidth + reach_pixels) * 16);
  std::uniform_int_distribution<int32_t> w(1 << 14, 1 << 24);
  return {at(rng), at(rng) * kHeight / kWidth, w(rng)};
}

}  // namespace

static void test_line_in_triangle() {
  std::mt19937 rng(11);
  std::vector<int32_t> filled(static_cast<size_t>(kWidth) * kHeight);
  std::vector<uint8_t> plotted(filled.size());
  int triangles = 0, wide = 0, pixels_agree = 0, lines = 0, lines_agree = 0, pixels_on_lines = 0;
  int pixels_bounded = 0, own_edges_below_tolerance = 0;
  bool bounds_hold = true;
  for (int trial = 0; trial < 240; ++trial) {
    // Every eighth triangle reaches far off screen, where its edge functions need 64 bits.
    const int reach = trial % 8 == 0 ? 1200 : 40;
    const ScreenVertex a = random_vertex(rng, reach), b = random_vertex(rng, reach), c = random_vertex(rng, reach);
    std::uniform_int_distribution<int> cx(0, kWidth - 1), cy(0, kHeight - 1);
    PixelRect clip{0, 0, kWidth - 1, kHeight - 1};
    if (trial % 3 == 1) {
      clip = {cx(rng), cy(rng), cx(rng), cy(rng)};
      if (clip.x0 > clip.x1) std::swap(clip.x0, clip.x1);
      if (clip.y0 > clip.y1) std::swap(clip.y0, clip.y1);
    }
    PixelTriangle t;
    if (!setup_triangle(a, b, c, clip, t)) continue;
    ++triangles;
    wide += !t.narrow;
    std::fill(plotted.begin(), plotted.end(), uint8_t(0));
    fill_triangle(t, [&](int x, int y, int32_t w) {
      const size_t i = static_cast<size_t>(y) * kWidth + x;
      filled[i] = w;
      plotted[i] = 1;
    });
    bool agree = true;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const size_t i = static_cast<size_t>(y) * kWidth + x;
        agree &= covers(t, x, y) == (plotted[i] != 0) && (!plotted[i] || depth_at(t, x, y) == filled[i]);
      }
    pixels_agree += agree;
    // Random lines, and the triangle's own edges (Edge-ID's usual case: an edge on its face).
    for (int l = 0; l < 6; ++l) {
      const ScreenVertex p = l == 4 ? a : l == 5 ? b : random_vertex(rng, 0);
      const ScreenVertex q = l == 4 ? b : l == 5 ? c : random_vertex(rng, 0);
      std::vector<Drawn> expected, visited;
      draw_line(p, q, kWidth, kHeight, [&](int x, int y, int32_t) {
        const size_t i = static_cast<size_t>(y) * kWidth + x;
        if (plotted[i]) expected.push_back({x, y, filled[i]});
      });
      const LineWalk line = walk_line(p, q);
      line_in_triangle(line, t, [&](int x, int y, int32_t w) { visited.push_back({x, y, w}); });
      // most_above_line bounds the triangle's w over the line's own at every pixel they share.
      int k0 = 0, k1 = line.count - 1;
      if (steps_in_box(line, t.box, k0, k1)) {
        const int64_t most = most_above_line(line, t, k0, k1);
        size_t next = 0;  // visited is in draw_line's order
        draw_line(line, kWidth, kHeight, [&](int x, int y, int32_t w_line) {
          if (next == visited.size() || visited[next].x != x || visited[next].y != y) return;
          ++pixels_bounded;
          bounds_hold &= int64_t(visited[next++].w) - w_line <= most;
        });
        const int32_t w_end = static_cast<int32_t>(std::min((line.w + int64_t(k0) * line.w_step) >> 16,
                                                            (line.w + int64_t(k1) * line.w_step) >> 16));
        if (l >= 4) own_edges_below_tolerance += most <= (w_end >> 7);
      }
      ++lines;
      lines_agree += visited == expected;
      pixels_on_lines += static_cast<int>(expected.size());
    }
  }
  TEST("most random triangles are drawn", triangles >= 150, true);
  TEST("some need 64-bit edge functions", wide >= 5, true);
  TEST_EQUAL("covers and depth_at agree with fill_triangle at every pixel", pixels_agree, triangles);
  TEST_EQUAL("line_in_triangle visits the line's filled pixels with their w", lines_agree, lines);
  TEST("the lines cross the triangles (the comparison is not vacuous)", pixels_on_lines > 10 * lines, true);
  TEST("most_above_line bounds the triangle's w over the line's at every shared pixel", bounds_hold, true);
  TEST_EQUAL("the bound was checked at every pixel line_in_triangle visits", pixels_bounded, pixels_on_lines);
  TEST("some edges lie within Edge-ID's depth tolerance of their own triangle by the bound",
       own_edges_below_tolerance > 0, true);
}

TESTMAIN(test_line_in_triangle)
