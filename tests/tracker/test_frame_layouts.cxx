// SPDX-License-Identifier: BSD-3-Clause
/// The tracker reads every camera layout in place: one generated sequence given as RGB565 (packed
/// and with padded rows) and,
/// built from the same grey values, as RGB24, BGR24, RGBA32, BGRA32, grey8 and NV21/I420 (padded rows and
/// packed ones, the chroma planes filled with noise) gives bit-identical poses and matches every
/// frame, on demand and over the whole frame; every vector kernel choice converts random colours
/// to vpImageConvert's grey; packed grey planes are read with no conversion;
/// and views that cannot be tracked are refused with a message, leaving the tracker as it was.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "edgetrack/grey_conversion.h"
#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "real/vector_kernels.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpImageConvert.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// One layout of the test: its frame's bytes, rebuilt each frame, and its tracker.
struct LayoutCase {
  const char* label;
  PixelLayout layout;
  int padding;  ///< bytes added to each row
  GreyScaling grey;
  std::vector<uint8_t> bytes;
  FrameView view;
};

/// Writes the RGB565 frame, or its grey values `grey`, into the case's layout, with its
/// padding, and chroma bytes that must not matter after the Y plane.
void build_frame(const Rgb565Frame& rgb565, const std::vector<unsigned char>& grey, uint32_t seed, LayoutCase& c) {
  const int width = rgb565.width, height = rgb565.height;
  const int row_bytes = width * bytes_per_pixel(c.layout) + c.padding;
  const size_t plane = static_cast<size_t>(row_bytes) * height;
  const bool yuv = c.layout == PixelLayout::kNv21 || c.layout == PixelLayout::kI420;
  c.bytes.assign(plane + (yuv ? plane / 2 : 0), 0);
  for (size_t i = 0; i < c.bytes.size(); ++i) c.bytes[i] = static_cast<uint8_t>((seed + i) * 2654435761u >> 24);
  for (int y = 0; y < height; ++y) {
    uint8_t* row = c.bytes.data() + static_cast<size_t>(y) * row_bytes;
    const unsigned char* g = grey.data() + static_cast<size_t>(y) * width;
    if (c.layout == PixelLayout::kRgb565) std::memcpy(row, &rgb565.pixels[static_cast<size_t>(y) * width], 2 * width);
    else if (bytes_per_pixel(c.layout) == 1) std::memcpy(row, g, width);
    else {
      const int step = bytes_per_pixel(c.layout);  // a fourth byte (alpha) keeps its noise
      for (int x = 0; x < width; ++x) row[step * x] = row[step * x + 1] = row[step * x + 2] = g[x];
    }
  }
  c.view = FrameView{c.bytes.data(), width, height, row_bytes, c.layout};
}

bool same_matches(const std::vector<EdgeMatch>& a, const std::vector<EdgeMatch>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k].found.x != b[k].found.x || a[k].found.y != b[k].found.y || a[k].outlier != b[k].outlier) return false;
  return true;
}

void same_poses_in_every_layout(int frames) {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(Scene::kCube, frames);
  std::vector<LayoutCase> cases = {
      {"RGB565, padded rows", PixelLayout::kRgb565, 10, GreyScaling::kOnDemand, {}, {}},
      {"RGB24, padded rows", PixelLayout::kRgb24, 7, GreyScaling::kOnDemand, {}, {}},
      {"BGR24, padded rows", PixelLayout::kBgr24, 12, GreyScaling::kOnDemand, {}, {}},
      {"RGBA32, padded rows", PixelLayout::kRgba32, 9, GreyScaling::kOnDemand, {}, {}},
      {"BGRA32, packed", PixelLayout::kBgra32, 0, GreyScaling::kOnDemand, {}, {}},
      {"grey8, padded rows", PixelLayout::kGrey8, 13, GreyScaling::kOnDemand, {}, {}},
      {"grey8, packed", PixelLayout::kGrey8, 0, GreyScaling::kOnDemand, {}, {}},
      {"NV21, packed", PixelLayout::kNv21, 0, GreyScaling::kOnDemand, {}, {}},
      {"I420, padded rows", PixelLayout::kI420, 64, GreyScaling::kOnDemand, {}, {}},
      {"RGB24, padded rows, whole frame", PixelLayout::kRgb24, 5, GreyScaling::kWholeFrame, {}, {}},
      {"I420, padded rows, whole frame", PixelLayout::kI420, 32, GreyScaling::kWholeFrame, {}, {}},
      {"NV21, packed, whole frame", PixelLayout::kNv21, 0, GreyScaling::kWholeFrame, {}, {}},
      {"BGRA32, padded rows, whole frame", PixelLayout::kBgra32, 4, GreyScaling::kWholeFrame, {}, {}},
  };
  const Result<Tracker> made = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  TEST("the RGB565 tracker starts", made.ok(), true);
  if (!made.ok()) return;
  Tracker reference = made.value();
  std::vector<Tracker> trackers;
  for (const LayoutCase& c : cases) {
    TrackerParams params;
    params.grey = c.grey;
    trackers.push_back(Tracker::create(model.value(), camera, truth[0], params).value());
  }
  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame frame;
  std::vector<unsigned char> grey(static_cast<size_t>(camera.width) * camera.height);
  std::vector<int> same(cases.size(), 0), tracked(cases.size(), 0), converted(cases.size(), 0);
  int matches = 0;
  for (int k = 0; k < frames; ++k) {
    renderer.render(model.value(), truth[k], static_cast<uint32_t>(500 + k), frame);
    for (size_t i = 0; i < grey.size(); ++i) grey[i] = vpImageConvert::rgb565ToGrey(frame.pixels[i]);
    const FrameResult expected = reference.track(rgb565_view(frame)).value();
    matches += static_cast<int>(reference.matches().size());
    for (size_t c = 0; c < cases.size(); ++c) {
      build_frame(frame, grey, static_cast<uint32_t>(k * 31 + c), cases[c]);
      const Result<FrameResult> got = trackers[c].track(cases[c].view);
      if (!got.ok()) continue;
      ++tracked[c];
      same[c] += same_bits(got.value().camera_from_model, expected.camera_from_model) &&
                 same_matches(trackers[c].matches(), reference.matches());
      converted[c] += got.value().grey_pixels > 0;
    }
  }
  TEST("the moving edges find matches (the comparison is not vacuous)", matches > 30 * frames, true);
  // Free the last frame read in place: a tracker that read it keeps nothing pointing into it, so
  // copying it is safe (the ASan tree checks) and the copy tracks on.
  const size_t packed_grey = 6;
  std::vector<uint8_t>().swap(cases[packed_grey].bytes);
  Tracker copy = trackers[packed_grey];
  renderer.render(model.value(), truth[frames - 1], 77u, frame);
  for (size_t i = 0; i < grey.size(); ++i) grey[i] = vpImageConvert::rgb565ToGrey(frame.pixels[i]);
  build_frame(frame, grey, 1u, cases[packed_grey]);
  const Result<FrameResult> from_copy = copy.track(cases[packed_grey].view),
                            from_original = trackers[packed_grey].track(cases[packed_grey].view);
  TEST("a copy of a tracker that read frames in place tracks as the original does",
       from_copy.ok() && from_original.ok() &&
           same_bits(from_copy.value().camera_from_model, from_original.value().camera_from_model),
       true);
  for (size_t c = 0; c < cases.size(); ++c) {
    const std::string label = cases[c].label;
    TEST_EQUAL((label + ": every frame is accepted").c_str(), tracked[c], frames);
    TEST_EQUAL((label + ": poses and matches bit-identical to RGB565's, every frame").c_str(), same[c], frames);
    const bool in_place = bytes_per_pixel(cases[c].layout) == 1 && cases[c].padding == 0;
    TEST_EQUAL((label + (in_place ? ": read in place, no pixel converted" : ": the grey step converts pixels")).c_str(),
               converted[c], in_place ? 0 : frames);
  }
}

/// Whether `frame` is refused with a message holding `words`, the tracker unchanged.
void refused(Tracker& tracker, const FrameView& frame, const char* what, const char* words) {
  const Se3 before = tracker.camera_from_model();
  const Result<FrameResult> got = tracker.track(frame);
  TEST((std::string(what) + " is refused").c_str(), got.ok(), false);
  if (got.ok()) return;
  std::printf("  %s: %s\n", what, got.error().message.c_str());
  TEST((std::string(what) + ": the message says why").c_str(), got.error().message.find(words) != std::string::npos,
       true);
  TEST((std::string(what) + ": the tracker is unchanged").c_str(), same_bits(tracker.camera_from_model(), before),
       true);
}

void bad_views_are_refused() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  Result<Tracker> tracker = Tracker::create(model.value(), camera, true_poses(Scene::kCube, 1)[0], TrackerParams{});
  TEST("the tracker starts", tracker.ok(), true);
  if (!tracker.ok()) return;
  const int w = camera.width, h = camera.height;
  std::vector<uint8_t> bytes(static_cast<size_t>(w + 8) * 3 * (h + 8), 128);
  Tracker& t = tracker.value();
  refused(t, FrameView{nullptr, w, h, w * 2, PixelLayout::kRgb565}, "a null pointer", "null pointer");
  refused(t, FrameView{bytes.data(), w + 2, h, (w + 2) * 2, PixelLayout::kRgb565}, "a frame wider than the camera's",
          "the camera's images are 320x240");
  refused(t, FrameView{bytes.data(), w, h - 1, w, PixelLayout::kGrey8}, "a frame shorter than the camera's",
          "320x239");
  refused(t, FrameView{bytes.data(), w, h, w * 3 - 1, PixelLayout::kBgr24}, "BGR24 rows shorter than a row of pixels",
          "less than the 960 bytes");
  refused(t, FrameView{bytes.data(), w, h, w - 1, PixelLayout::kNv21}, "an NV21 Y stride under the width", "NV21");
  refused(t, FrameView{bytes.data(), w, h, w * 4 - 1, PixelLayout::kRgba32}, "RGBA32 rows shorter than a row of pixels",
          "less than the 1280 bytes");
  refused(t, FrameView{bytes.data(), w, h, w * 2 + 1, PixelLayout::kRgb565}, "an odd RGB565 stride", "2-byte");
  refused(t, FrameView{bytes.data() + 1, w, h, w * 2, PixelLayout::kRgb565}, "an odd RGB565 pointer", "2-byte");
  TEST("a good view of the same bytes is then tracked", t.track(FrameView{bytes.data(), w, h, w + 3, PixelLayout::kGrey8}).ok(),
       true);
}

/// The colour layouts weigh each channel as its name says: one pixel of distinct red, green and
/// blue converts to vpImageConvert's grey of that colour in RGB24, BGR24, RGBA32 and BGRA32.
void channels_in_their_order() {
  const uint8_t r = 200, g = 60, b = 10, a = 255;
  const unsigned char want = vpImageConvert::rgbToGrey(r, g, b);
  const struct {
    PixelLayout layout;
    std::vector<uint8_t> pixel;
  } pixels[] = {{PixelLayout::kRgb24, {r, g, b}},
                {PixelLayout::kBgr24, {b, g, r}},
                {PixelLayout::kRgba32, {r, g, b, a}},
                {PixelLayout::kBgra32, {b, g, r, a}}};
  for (const auto& p : pixels) {
    vpImage<unsigned char> grey(1, 1, 0);
    convert_to_grey(packed_frame(p.pixel.data(), 1, 1, p.layout), PixelBox{0, 0, 1, 1}, grey);
    TEST_EQUAL((std::string(layout_name(p.layout)) + ": the grey of one coloured pixel").c_str(), int(grey[0][0]),
               int(want));
  }
  TEST("the colour is not grey already (the test tells channels apart)", want != vpImageConvert::rgbToGrey(b, g, r),
       true);
}

/// A box of random colours, wider than the widest vectors and not a multiple of them, in rows
/// with padding, converts in every colour layout and with every vector kernel choice to
/// vpImageConvert's grey of each pixel, and leaves the pixels outside the box as they were.
void every_kernel_gives_each_pixels_grey() {
  const int width = 83, height = 6, padding = 5;
  const PixelBox box{1, 3, 5, 80};  // top, left, bottom, right
  const vector_kernels::Choice choices[] = {vector_kernels::Choice::kWidest, vector_kernels::Choice::kBaseline,
                                            vector_kernels::Choice::kScalar};
  for (PixelLayout layout : {PixelLayout::kRgb24, PixelLayout::kBgr24, PixelLayout::kRgba32, PixelLayout::kBgra32}) {
    const int step = bytes_per_pixel(layout), row_bytes = width * step + padding;
    std::vector<uint8_t> bytes(static_cast<size_t>(row_bytes) * height);
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>((i + 7) * 2654435761u >> 24);
    const bool blue_first = layout == PixelLayout::kBgr24 || layout == PixelLayout::kBgra32;
    for (vector_kernels::Choice choice : choices) {
      vector_kernels::choose(choice);
      vpImage<unsigned char> grey(static_cast<unsigned>(height), static_cast<unsigned>(width), 7);
      convert_to_grey(FrameView{bytes.data(), width, height, row_bytes, layout}, box, grey);
      int wrong = 0;
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          const uint8_t* p = bytes.data() + static_cast<size_t>(y) * row_bytes + step * x;
          const bool inside = y >= box.top && y < box.bottom && x >= box.left && x < box.right;
          const unsigned char want = !inside      ? 7
                                     : blue_first ? vpImageConvert::rgbToGrey(p[2], p[1], p[0])
                                                  : vpImageConvert::rgbToGrey(p[0], p[1], p[2]);
          if (grey[y][x] != want) ++wrong;
        }
      TEST_EQUAL((std::string(layout_name(layout)) + ", kernel choice " + std::to_string(static_cast<int>(choice)) +
                  ": pixels whose grey differs from vpImageConvert's").c_str(),
                 wrong, 0);
    }
  }
  vector_kernels::choose(vector_kernels::Choice::kWidest);
}

}  // namespace

static void test_frame_layouts() {
  channels_in_their_order();
  every_kernel_gives_each_pixels_grey();
  same_poses_in_every_layout(12);
  bad_views_are_refused();
}

TESTMAIN(test_frame_layouts)
