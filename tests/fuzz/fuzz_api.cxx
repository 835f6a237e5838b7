// SPDX-License-Identifier: BSD-3-Clause
// The library's door (tracker.h): Tracker::create on a fuzzed camera, start pose and settings,
// then track, set_params and reset on fuzzed frames, settings and poses. Every call must return
// an Error with a message or a finite result; the frames' pixels are the fuzzer's bytes, so the
// moving edges and the pose solve run on arbitrary images too.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <limits>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/tracker.h"

using edgetrack::FrameView;
using edgetrack::PixelLayout;
using edgetrack::Se3;
using edgetrack::TrackerParams;
using edgetrack::Vec3;

namespace {

/// A value the fuzzer picks: the default, one of the values careless callers pass, or any double.
double pick(FuzzedDataProvider& in, double ordinary) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const double choices[] = {ordinary, ordinary * 2, ordinary / 2, 0, -ordinary, 1e300, -1e300, 1e-300, nan, inf, 1e6};
  const unsigned which = in.ConsumeIntegralInRange<unsigned>(0, sizeof choices / sizeof choices[0]);
  return which < sizeof choices / sizeof choices[0] ? choices[which] : in.ConsumeFloatingPoint<double>();
}

bool all_finite(const real& v) { return std::isfinite(static_cast<double>(v)); }

bool all_finite(const Se3& pose) {
  bool all = all_finite(pose.translation().x) && all_finite(pose.translation().y) && all_finite(pose.translation().z);
  for (const auto& row : pose.rotation().m)
    for (const real& v : row) all = all && all_finite(v);
  return all;
}

/// `value` into a real as a caller would convert it: fixed point saturates what it cannot hold.
real as_real(double value) {
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  if (!std::isfinite(value) || std::fabs(value) > 1e12) value = value > 0 ? 1e12 : value < 0 ? -1e12 : 0;
#endif
  return real(value);
}

/// Some of the settings, each left alone or fuzzed.
TrackerParams fuzzed_params(FuzzedDataProvider& in) {
  TrackerParams p;
  real* reals[] = {&p.me.threshold,         &p.me.mu1,           &p.me.mu2,
                   &p.me.sample_step,       &p.faces.angle_appear, &p.faces.near_distance,
                   &p.faces.min_line_length, &p.pose.x_tolerance, &p.pose.tukey_c,
                   &p.motion.velocity_share, &p.status.tracked_scale_px, &p.status.min_matched_share};
  for (real* field : reals)
    if (in.ConsumeBool()) *field = as_real(pick(in, static_cast<double>(*field)));
  if (in.ConsumeBool()) p.me.range = in.ConsumeIntegralInRange<unsigned>(0, 64);
  if (in.ConsumeBool()) p.me.mask_size = in.ConsumeIntegralInRange<unsigned>(0, 24);
  if (in.ConsumeBool()) p.me.mask_number = in.ConsumeIntegralInRange<unsigned>(0, 400);
  if (in.ConsumeBool()) p.hypotheses = in.ConsumeIntegralInRange<int>(-1, 8);
  if (in.ConsumeBool()) p.border = in.ConsumeIntegralInRange<int>(-5, 400);
  if (in.ConsumeBool()) p.pose.max_evaluations = in.ConsumeIntegralInRange<int>(-1, 60);
  return p;
}

Se3 fuzzed_pose(FuzzedDataProvider& in) {
  const Vec3 t{as_real(pick(in, 0.01)), as_real(pick(in, -0.01)), as_real(pick(in, 0.4))};
  const Vec3 tu{as_real(pick(in, 0.3)), as_real(pick(in, 0.4)), as_real(pick(in, 0.1))};
  return Se3::from_theta_u(t, tu);
}

/// A frame of the camera's size or another, in a layout of the enum or outside it, its pixels
/// the fuzzer's bytes (repeated to fill the rows the view claims).
FrameView fuzzed_frame(FuzzedDataProvider& in, int width, int height, std::vector<uint8_t>& pixels) {
  FrameView frame;
  frame.layout = static_cast<PixelLayout>(in.ConsumeIntegralInRange<int>(-1, 7));
  frame.width = in.ConsumeBool() ? width : in.ConsumeIntegralInRange<int>(-2, 400);
  frame.height = in.ConsumeBool() ? height : in.ConsumeIntegralInRange<int>(-2, 300);
  const int bytes = frame.layout == PixelLayout::kRgb565 ? 2
                    : frame.layout == PixelLayout::kRgb24 || frame.layout == PixelLayout::kBgr24 ? 3 : 1;
  frame.row_bytes = in.ConsumeBool() ? frame.width * bytes : in.ConsumeIntegralInRange<int>(-8, 2000);
  const std::vector<uint8_t> seed = in.ConsumeBytes<uint8_t>(in.ConsumeIntegralInRange<size_t>(1, 4096));
  pixels.clear();
  if (frame.row_bytes > 0 && frame.height > 0) {
    pixels.resize(static_cast<size_t>(frame.row_bytes) * static_cast<size_t>(frame.height));
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = seed.empty() ? uint8_t(128) : seed[i % seed.size()];
  }
  frame.pixels = pixels.empty() ? nullptr : pixels.data();
  return frame;
}

template <class R>
void check(const R& result) {
  if (!result.ok() && result.error().message.empty()) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const edgetrack::Result<edgetrack::EdgeModel> model =
      edgetrack::load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  if (!model.ok()) __builtin_trap();  // the model itself is missing
  FuzzedDataProvider in(data, size);
  edgetrack::PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  if (in.ConsumeBool()) {
    camera.px = as_real(pick(in, 220));
    camera.py = as_real(pick(in, 220));
    camera.u0 = as_real(pick(in, 160));
    camera.v0 = as_real(pick(in, 120));
  }
  if (in.ConsumeBool()) {
    camera.width = in.ConsumeIntegralInRange<int>(-1, 400);
    camera.height = in.ConsumeIntegralInRange<int>(-1, 300);
  }
  auto tracker = edgetrack::Tracker::create(model.value(), camera, fuzzed_pose(in), fuzzed_params(in));
  check(tracker);
  if (!tracker.ok()) return 0;
  std::vector<uint8_t> pixels;
  for (int step = 0; step < 4 && in.remaining_bytes() > 0; ++step) {
    switch (in.ConsumeIntegralInRange<int>(0, 3)) {
      case 0:
        if (auto refused = tracker.value().set_params(fuzzed_params(in)); refused && refused->message.empty())
          __builtin_trap();
        break;
      case 1:
        tracker.value().reset(fuzzed_pose(in));
        break;
      default: {
        const auto result = tracker.value().track(fuzzed_frame(in, camera.width, camera.height, pixels));
        check(result);
        if (result.ok() && (!all_finite(result.value().camera_from_model) || !all_finite(result.value().pose.residual_scale)))
          __builtin_trap();  // a non-finite pose passed off as a result
      }
    }
  }
  if (!all_finite(tracker.value().camera_from_model())) __builtin_trap();
  return 0;
}
