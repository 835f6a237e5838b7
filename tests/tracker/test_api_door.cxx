// SPDX-License-Identifier: BSD-3-Clause
/// The API checked at its door: Tracker::create, reset, set_params and track, fed extreme and
/// random cameras, models, poses, settings and frames, return an Error or a finite result every
/// time, never throw, overflow or allocate a camera's buffers past the caps.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

#include "edgetrack/edge_model.h"
#include "edgetrack/model_io.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "edgetrack/tracker_inputs.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// A fixed pseudo-random sequence (the same on every build and under QEMU).
class Draw {
 public:
  uint32_t next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<uint32_t>(state_ >> 33);
  }
  int between(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<uint32_t>(hi - lo + 1)); }
  /// A value a careless caller might pass: ordinary, zero, negative, huge, tiny or not finite.
  double extreme(double ordinary) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const double choices[] = {ordinary, ordinary * 2, 0, -ordinary, 1e300, -1e300, 1e-300, nan, inf, -inf, 1e6, 0.5};
    return choices[next() % (sizeof choices / sizeof choices[0])];
  }

 private:
  uint64_t state_ = 12345;
};

bool finite(const real& v) { return std::isfinite(static_cast<double>(v)); }
bool finite(const Se3& pose) {
  bool all = finite(pose.translation().x) && finite(pose.translation().y) && finite(pose.translation().z);
  for (const auto& row : pose.rotation().m)
    for (const real& v : row) all = all && finite(v);
  return all;
}

/// `value` into a real, as a caller would: fixed point saturates what it cannot hold.
real as_real(double value) {
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  if (!std::isfinite(value)) value = value > 0 ? 1e12 : value < 0 ? -1e12 : 0;
  if (std::fabs(value) > 1e12) value = value > 0 ? 1e12 : -1e12;
#endif
  return real(value);
}

/// The real settings a caller may set, each by its address.
std::vector<real*> real_settings(TrackerParams& p) {
  return {&p.me.threshold,          &p.me.mu1,
          &p.me.mu2,                &p.me.sample_step,
          &p.faces.angle_appear,    &p.faces.angle_disappear,
          &p.faces.near_distance,   &p.faces.far_distance,
          &p.faces.min_line_length, &p.faces.min_polygon_area,
          &p.pose.x_tolerance,      &p.pose.f_tolerance,
          &p.pose.g_tolerance,      &p.pose.rounds_settled_px,
          &p.pose.tukey_c,          &p.pose.tukey_floor,
          &p.motion.velocity_share, &p.motion.lost_damping,
          &p.motion.range_per_motion, &p.status.tracked_scale_px,
          &p.status.lost_range_share, &p.status.lost_scale_floor_px,
          &p.status.min_matched_share, &p.status.min_inlier_share,
          &p.status.max_pose_uncertainty_px, &p.status.lost_uncertainty_range_share,
          &p.status.edge_location_px};
}

/// Counts the outcomes; a finite result or an Error with a message is fine, anything else not.
struct Outcomes {
  int refused = 0, tracked = 0, bad = 0;
  void frame(const Result<FrameResult>& r) {
    if (!r.ok()) {
      refused += 1;
      bad += r.error().message.empty();
      return;
    }
    tracked += 1;
    const FrameResult& f = r.value();
    if (!finite(f.camera_from_model) || !finite(f.pose.residual_scale) || !finite(f.measures.pose_uncertainty_px)) {
      bad += 1;
      std::printf("  a frame gave a non-finite result\n");
    }
  }
};

}  // namespace

static void test_api_door() {
  const Result<EdgeModel> model = load_model(model_path(Scene::kCube));
  TEST("the model loads", model.ok(), true);
  if (!model.ok()) return;
  const PinholeCamera camera = qvga_camera();
  const Se3 start = true_poses(Scene::kCube, 1)[0];
  SceneRenderer renderer(camera, SceneStyle{});
  Rgb565Frame image;
  renderer.render(model.value(), start, 7u, image);
  const FrameView good = rgb565_view(image);
  [[maybe_unused]] const double nan = std::numeric_limits<double>::quiet_NaN();

  // Named cases of #32, each refused.
  auto refused = [&](const PinholeCamera& c, const Se3& pose, const TrackerParams& params) {
    const Result<Tracker> made = Tracker::create(model.value(), c, pose, params);
    if (made.ok()) return false;
    std::printf("  refused: %s\n", made.error().text().c_str());
    return !made.error().message.empty();
  };
  const TrackerParams defaults;
  PinholeCamera c = camera;
  c.px = real(0);
  TEST("px of 0 is refused", refused(c, start, defaults), true);
  c.px = real(-600);
  TEST("a negative px is refused", refused(c, start, defaults), true);
  c = camera;
  c.u0 = as_real(1e300);
  TEST("u0 of 1e300 is refused", refused(c, start, defaults), true);
  c = camera;
  c.lens.model = LensModel::kVisp;
  c.lens.kud = as_real(1e300);
  TEST("a lens coefficient of 1e300 is refused", refused(c, start, defaults), true);
  c = camera;
  c.lens.model = static_cast<LensModel>(7);
  TEST("a lens model outside LensModel is refused", refused(c, start, defaults), true);
  c = camera;
  c.width = c.height = 46341;
  TEST("a camera of 46341 x 46341 is refused, not allocated", refused(c, start, defaults), true);
  c = camera;
  c.width = 16385;
  TEST("a side over 16384 is refused", refused(c, start, defaults), true);
#if !defined(EDGETRACK_REAL_S47_16) && !defined(EDGETRACK_REAL_S40_23)
  c = camera;
  c.py = real(nan);
  TEST("a NaN py is refused", refused(c, start, defaults), true);
  for (const char* name : {"mu1", "angle_appear", "min_line_length"}) {
    TrackerParams p;
    real& field = name[0] == 'm' && name[1] == 'u' ? p.me.mu1 : name[0] == 'a' ? p.faces.angle_appear : p.faces.min_line_length;
    field = real(nan);
    std::printf("NaN %s:\n", name);
    TEST("a NaN setting is refused", refused(camera, start, p), true);
  }
  const Se3 nan_pose(Mat33::identity(), Vec3{real(0), real(nan), real(0.5)});
  TEST("a NaN initial pose is refused", refused(camera, nan_pose, defaults), true);
  EdgeModel nan_model = model.value();
  nan_model.vertices[0].x = real(nan);
  TEST("a model with a NaN vertex is refused", Tracker::create(nan_model, camera, start, defaults).ok(), false);
  Polygons polygons;
  polygons.vertices = {Vec3{real(0), real(0), real(0)}, Vec3{real(1), real(0), real(0)}, Vec3{real(nan), real(1), real(0)}};
  polygons.faces = {{0, 1, 2}};
  TEST("build_edge_model refuses a NaN vertex", build_edge_model(polygons, EdgeRules{}, "nan.cao").ok(), false);
#endif
  Mat33 stretched = Mat33::identity();
  stretched.m[0][0] = real(2);
  TEST("a rotation that is not one is refused", refused(camera, Se3(stretched, start.translation()), defaults), true);
  TEST("a pose 1e6 m away is refused",
       refused(camera, Se3(Mat33::identity(), Vec3{real(0), real(0), as_real(1e6)}), defaults), true);
  TrackerParams wide;
  wide.me.range = 4000000000u;
  TEST("a range of 4e9 pixels is refused", refused(camera, start, wide), true);

  Result<Tracker> tracker = Tracker::create(model.value(), camera, start, defaults);
  TEST("the defaults are taken", tracker.ok(), true);
  if (!tracker.ok()) return;
  FrameView odd = good;
  odd.layout = static_cast<PixelLayout>(17);
  Result<FrameResult> unknown = tracker.value().track(odd);
  TEST("an unknown PixelLayout is refused", unknown.ok(), false);
#if !defined(EDGETRACK_REAL_S47_16) && !defined(EDGETRACK_REAL_S40_23)
  TEST("reset refuses a NaN pose", tracker.value().reset(nan_pose), false);
#endif
  TrackerParams bad_mu = defaults;
  bad_mu.me.mu1 = real(2);
  TEST("set_params refuses what create refuses", tracker.value().set_params(bad_mu).has_value(), true);
  TEST("and keeps the settings it had", tracker.value().params().me.mu1 == defaults.me.mu1, true);

  TrackerParams wider = defaults;
  wider.me.range = 9;
  TEST("set_params takes valid settings between frames", tracker.value().set_params(wider).has_value(), false);
  const Result<FrameResult> after = tracker.value().track(good);
  TEST("and the next frame searches with them", after.ok() && after.value().measures.range >= 9u, true);

  // A camera without an image size takes the first frame's: the same poses as a sized one.
  PinholeCamera unsized = camera;
  unsized.width = unsized.height = 0;
  Result<Tracker> from_frame = Tracker::create(model.value(), unsized, start, defaults);
  Result<Tracker> sized = Tracker::create(model.value(), camera, start, defaults);
  TEST("a 0x0 camera is taken", from_frame.ok() && sized.ok(), true);
  if (from_frame.ok() && sized.ok()) {
    const Result<FrameResult> a = from_frame.value().track(good), b = sized.value().track(good);
    TEST("and tracks its first frame as a camera of that size",
         a.ok() && b.ok() && same_bits(a.value().camera_from_model, b.value().camera_from_model), true);
    FrameView smaller = good;
    smaller.width -= 2;
    TEST("then refuses a frame of another size", from_frame.value().track(smaller).ok(), false);
  }

  // Random settings: each real setting given an extreme value, each count a random one.
  Draw draw;
  Outcomes outcomes;
  int created = 0;
  const int rounds = 120;
  for (int round = 0; round < rounds; ++round) {
    TrackerParams p;
    std::vector<real*> reals = real_settings(p);
    real* field = reals[draw.next() % reals.size()];
    *field = as_real(draw.extreme(static_cast<double>(*field)));
    if (draw.next() % 3 == 0) p.me.range = static_cast<unsigned>(draw.between(0, 40));
    if (draw.next() % 4 == 0) p.me.mask_size = static_cast<unsigned>(draw.between(0, 20));
    if (draw.next() % 4 == 0) p.me.mask_number = static_cast<unsigned>(draw.between(0, 200));
    if (draw.next() % 4 == 0) p.hypotheses = draw.between(-1, 6);
    if (draw.next() % 4 == 0) p.border = draw.between(-5, 400);
    if (draw.next() % 5 == 0) p.pose.max_evaluations = draw.between(-1, 50);
    if (draw.next() % 5 == 0) p.motion.max_range_factor = draw.between(-1, 20);
    PinholeCamera cam = camera;
    if (draw.next() % 4 == 0) cam.px = as_real(draw.extreme(600));
    if (draw.next() % 4 == 0) cam.v0 = as_real(draw.extreme(120));
    Se3 pose = start;
    if (draw.next() % 4 == 0) {
      const Vec3 t = start.translation();
      pose = Se3(start.rotation(), Vec3{t.x, t.y, as_real(draw.extreme(static_cast<double>(t.z)))});
    }
    Result<Tracker> made = Tracker::create(model.value(), cam, pose, p);
    if (!made.ok()) {
      outcomes.refused += 1;
      outcomes.bad += made.error().message.empty();
      continue;
    }
    created += 1;
    for (int k = 0; k < 2; ++k) outcomes.frame(made.value().track(good));
  }
  // Random frames: layouts (some outside the enum), sizes, strides and null pixels, each buffer
  // as large as the view says.
  for (int round = 0; round < rounds; ++round) {
    FrameView frame;
    frame.layout = static_cast<PixelLayout>(draw.between(-1, 7));
    frame.width = draw.next() % 3 == 0 ? draw.between(-2, 400) : camera.width;
    frame.height = draw.next() % 3 == 0 ? draw.between(-2, 300) : camera.height;
    const int bytes = frame.layout == PixelLayout::kRgb565 ? 2 : frame.layout == PixelLayout::kRgb24 ||
                                                                     frame.layout == PixelLayout::kBgr24 ? 3 : 1;
    frame.row_bytes = draw.next() % 4 == 0 ? draw.between(-8, 2000) : frame.width * bytes + draw.between(0, 9);
    std::vector<uint8_t> pixels;
    if (frame.row_bytes > 0 && frame.height > 0)
      pixels.assign(static_cast<size_t>(frame.row_bytes) * static_cast<size_t>(frame.height) * 2,
                    static_cast<uint8_t>(draw.next()));
    frame.pixels = pixels.empty() || draw.next() % 8 == 0 ? nullptr : pixels.data();
    outcomes.frame(tracker.value().track(frame));
  }
  std::printf("%s: %d settings created a tracker, %d refused; %d frames tracked, %d refused; %d bad outcomes\n",
              real_name(), created, rounds - created, outcomes.tracked, outcomes.refused, outcomes.bad);
  TEST("some random settings and frames are tracked, some refused (the test is not vacuous)",
       created > 0 && created < rounds && outcomes.tracked > 2 * created, true);
  TEST_EQUAL("every outcome is an Error with a message or a finite result", outcomes.bad, 0);
}

TESTMAIN(test_api_door)
