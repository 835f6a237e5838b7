// SPDX-License-Identifier: BSD-3-Clause
/// Android's camera frames are tracked in place: YUV_420_888 as Camera2 and CameraX hand it
/// (three planes, padded row strides, chroma pixel stride 2 as most phones give it and 1 as
/// others do) and NV12, built from the grey values of a generated sequence with chroma noise
/// that changes every frame, give the grey8 run's poses bit for bit, read through the Y plane
/// only (packed planes with no conversion); broken plane descriptions are refused with a message.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpImageConvert.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// One Android layout of the test: how its planes lie, its bytes (rebuilt each frame), its view.
struct AndroidCase {
  const char* label;
  PixelLayout layout;   ///< kYuv420_888 or kNv12
  int y_padding;        ///< bytes after each Y row
  int pixel_stride;     ///< YUV_420_888's chroma pixel stride, 1 or 2
  int chroma_padding;   ///< bytes after each chroma row
};

/// Noise that differs per byte and per frame: chroma the tracker must never let matter.
uint8_t noise(uint32_t seed, size_t i) { return static_cast<uint8_t>((seed + i) * 2654435761u >> 24); }

/// The case's frame of grey values `grey`: the Y plane, then the chroma plane(s) full of noise.
FrameView build_frame(const AndroidCase& c, const std::vector<unsigned char>& grey, int width, int height, uint32_t seed,
                      std::vector<uint8_t>& bytes) {
  const int y_row = width + c.y_padding;
  const int samples = (width + 1) / 2, chroma_rows = (height + 1) / 2;
  const int pixel_stride = c.layout == PixelLayout::kNv12 ? 2 : c.pixel_stride;
  const int chroma_row = samples * pixel_stride + c.chroma_padding;
  const size_t y_bytes = static_cast<size_t>(y_row) * height;
  const size_t chroma_bytes = static_cast<size_t>(chroma_row) * chroma_rows;
  // Interleaved: one plane holds U and V; planar: two planes.
  bytes.resize(y_bytes + (pixel_stride == 2 ? chroma_bytes : 2 * chroma_bytes));
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = noise(seed, i);
  for (int y = 0; y < height; ++y)
    std::memcpy(bytes.data() + static_cast<size_t>(y) * y_row, grey.data() + static_cast<size_t>(y) * width, width);
  if (c.layout == PixelLayout::kNv12) return FrameView{bytes.data(), width, height, y_row, PixelLayout::kNv12};
  Yuv420Planes planes;
  planes.y = bytes.data();
  planes.y_row_bytes = y_row;
  // Android's semi-planar YUV_420_888 is NV21 underneath: the V plane starts one byte before U.
  planes.v = bytes.data() + y_bytes;
  planes.u = pixel_stride == 2 ? bytes.data() + y_bytes + 1 : bytes.data() + y_bytes + chroma_bytes;
  planes.uv_row_bytes = chroma_row;
  planes.uv_pixel_stride = pixel_stride;
  const Result<FrameView> view = yuv_420_888_frame(planes, width, height);
  TEST("Android's plane description is taken", view.ok(), true);
  return view.ok() ? view.value() : FrameView{};
}

void same_poses_as_grey8(int frames) {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(Scene::kCube, frames);
  const std::vector<AndroidCase> cases = {
      {"YUV_420_888, pixel stride 2, rows padded to 384 bytes", PixelLayout::kYuv420_888, 64, 2, 64},
      {"YUV_420_888, pixel stride 1, padded rows", PixelLayout::kYuv420_888, 32, 1, 16},
      {"YUV_420_888, pixel stride 2, packed", PixelLayout::kYuv420_888, 0, 2, 0},
      {"NV12, padded rows", PixelLayout::kNv12, 16, 2, 0},
      {"NV12, packed", PixelLayout::kNv12, 0, 2, 0},
  };
  const Result<Tracker> made = Tracker::create(model.value(), camera, truth[0], TrackerParams{});
  TEST("the grey8 tracker starts", made.ok(), true);
  if (!made.ok()) return;
  Tracker reference = made.value();
  std::vector<Tracker> trackers(cases.size(), reference);
  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame frame;
  std::vector<unsigned char> grey(static_cast<size_t>(camera.width) * camera.height);
  std::vector<uint8_t> bytes;
  std::vector<int> same(cases.size(), 0), converted(cases.size(), 0);
  int matched = 0;
  for (int k = 0; k < frames; ++k) {
    renderer.render(model.value(), truth[k], static_cast<uint32_t>(900 + k), frame);
    for (size_t i = 0; i < grey.size(); ++i) grey[i] = vpImageConvert::rgb565ToGrey(frame.pixels[i]);
    const FrameResult expected =
        reference.track(packed_frame(grey.data(), camera.width, camera.height, PixelLayout::kGrey8)).value();
    matched += expected.points_matched;
    for (size_t c = 0; c < cases.size(); ++c) {
      const FrameView view = build_frame(cases[c], grey, camera.width, camera.height, static_cast<uint32_t>(k * 7 + c), bytes);
      const Result<FrameResult> got = trackers[c].track(view);
      if (!got.ok()) continue;
      same[c] += same_bits(got.value().camera_from_model, expected.camera_from_model) &&
                 got.value().points_matched == expected.points_matched;
      converted[c] += got.value().grey_pixels > 0;
    }
  }
  TEST("the moving edges match points (the comparison is not vacuous)", matched > 30 * frames, true);
  for (size_t c = 0; c < cases.size(); ++c) {
    const std::string label = cases[c].label;
    TEST_EQUAL((label + ": poses and matched points bit-identical to grey8's, every frame").c_str(), same[c], frames);
    const bool in_place = cases[c].y_padding == 0;
    TEST_EQUAL((label + (in_place ? ": the Y plane read in place, no pixel converted" : ": the Y rows are copied")).c_str(),
               converted[c], in_place ? 0 : frames);
  }
}

/// Whether `planes` are refused with a message naming the layout and holding `words`.
void refused(const Yuv420Planes& planes, const char* what, const char* words) {
  const Result<FrameView> view = yuv_420_888_frame(planes, 320, 240);
  TEST((std::string(what) + " is refused").c_str(), view.ok(), false);
  if (view.ok()) return;
  const std::string& message = view.error().message;
  std::printf("  %s: %s\n", what, message.c_str());
  TEST((std::string(what) + ": the message names the layout and says why").c_str(),
       message.find("YUV_420_888") != std::string::npos && message.find(words) != std::string::npos, true);
}

void broken_planes_are_refused() {
  std::vector<uint8_t> bytes(320 * 240 * 2, 128);
  Yuv420Planes good;
  good.y = bytes.data();
  good.y_row_bytes = 320;
  good.v = bytes.data() + 320 * 240;
  good.u = bytes.data() + 320 * 240 + 1;
  good.uv_row_bytes = 320;
  good.uv_pixel_stride = 2;
  TEST("Android's usual description is taken", yuv_420_888_frame(good, 320, 240).ok(), true);
  Yuv420Planes planes = good;
  planes.uv_pixel_stride = 3;
  refused(planes, "a chroma pixel stride of 3", "pixel stride is 3");
  planes = good;
  planes.uv_pixel_stride = 0;
  refused(planes, "a chroma pixel stride of 0", "pixel stride is 0");
  planes = good;
  planes.u = nullptr;
  refused(planes, "a missing U plane", "null");
  planes = good;
  planes.uv_row_bytes = 318;
  refused(planes, "interleaved chroma rows of 318 bytes for 160 samples", "less than the 319 bytes");
  planes = good;
  planes.uv_pixel_stride = 1;
  planes.uv_row_bytes = 160;
  TEST("planar chroma rows of 160 bytes for 160 samples are taken", yuv_420_888_frame(planes, 320, 240).ok(), true);

  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  if (!model.ok()) return;
  Result<Tracker> tracker = Tracker::create(model.value(), qvga_camera(), true_poses(Scene::kCube, 1)[0], TrackerParams{});
  if (!tracker.ok()) return;
  planes = good;
  planes.y_row_bytes = 319;
  const Se3 before = tracker.value().camera_from_model();
  const Result<FrameResult> got = tracker.value().track(yuv_420_888_frame(planes, 320, 240).value());
  TEST("a Y plane whose rows are shorter than the width is refused by track", got.ok(), false);
  if (!got.ok())
    TEST("and the message names the layout", got.error().message.find("YUV_420_888") != std::string::npos, true);
  TEST("the tracker is unchanged",
       same_bits(tracker.value().camera_from_model(), before), true);
}

}  // namespace

static void test_android_frames() {
  same_poses_as_grey8(8);
  broken_planes_are_refused();
}

TESTMAIN(test_android_frames)
