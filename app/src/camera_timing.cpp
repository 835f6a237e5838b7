// SPDX-License-Identifier: BSD-3-Clause
#include "camera_timing.h"

#include <algorithm>
#include <cmath>

using edgetrack::Se3;
using edgetrack::Twist;

namespace edgetrack_app {
namespace {

/// The integral of the unit hat max(0, 1 - |u|) from -infinity to u.
double hat_area_below(double u) {
  if (u <= -1) return 0;
  if (u <= 0) return 0.5 * (u + 1) * (u + 1);
  if (u <= 1) return 1 - 0.5 * (1 - u) * (1 - u);
  return 1;
}

}  // namespace

Se3 pose_at_time(const std::vector<Se3>& poses, double t) {
  const double whole = std::floor(t);
  if (t == whole && whole >= 0 && whole < static_cast<double>(poses.size())) return poses[static_cast<size_t>(whole)];
  if (poses.size() < 2) return poses.front();
  const int last_step = static_cast<int>(poses.size()) - 2;
  const int before = std::clamp(static_cast<int>(whole), 0, last_step);
  const Se3& a = poses[static_cast<size_t>(before)];
  const Twist step = (a.inverse() * poses[static_cast<size_t>(before) + 1]).log();
  const real f(t - before);
  return a * Se3::exp({f * step.v, f * step.w});
}

ExposurePlan plan_exposure(const SensorTiming& timing, int height, double motion_px) {
  ExposurePlan plan;
  const double span = timing.shutter + timing.readout;
  if (span <= 0) {
    plan.times = {0.0};
    plan.weights.assign(static_cast<size_t>(height), 1.0);
    return plan;
  }
  const double steps = std::ceil(span * std::max(motion_px, 0.0) / ExposurePlan::kMaxRenderStepPx);
  const int intervals = static_cast<int>(std::clamp(steps, 1.0, double(ExposurePlan::kMaxRenders - 1)));
  const double dt = span / intervals;
  for (int j = 0; j <= intervals; ++j) plan.times.push_back(-span / 2 + j * dt);
  plan.weights.reserve(static_cast<size_t>(height) * plan.times.size());
  for (int y = 0; y < height; ++y) {
    const double read = timing.readout * ((y + 0.5) / height - 0.5);
    for (const double t : plan.times) {
      if (timing.shutter <= 0) {
        plan.weights.push_back(std::max(0.0, 1 - std::fabs(read - t) / dt));
      } else {  // the hat's share of the row's exposure window
        const double begin = read - timing.shutter / 2, end = read + timing.shutter / 2;
        plan.weights.push_back(dt * (hat_area_below((end - t) / dt) - hat_area_below((begin - t) / dt)) /
                               timing.shutter);
      }
    }
  }
  return plan;
}

RgbImage expose(const ExposurePlan& plan, const std::function<RgbImage(double offset)>& render_at) {
  if (plan.times.size() == 1) return render_at(plan.times[0]);
  std::vector<double> sum;
  RgbImage frame;
  for (size_t j = 0; j < plan.times.size(); ++j) {
    const RgbImage render = render_at(plan.times[j]);
    if (j == 0) {
      frame = make_image(render.width, render.height);
      sum.assign(render.rgb.size(), 0.0);
    }
    const size_t row_bytes = static_cast<size_t>(render.width) * 3;
    for (int y = 0; y < render.height; ++y) {
      const double w = plan.weight(y, j);
      if (w == 0) continue;
      const size_t first = static_cast<size_t>(y) * row_bytes;
      for (size_t i = first; i < first + row_bytes; ++i) sum[i] += w * render.rgb[i];
    }
  }
  for (size_t i = 0; i < sum.size(); ++i)
    frame.rgb[i] = static_cast<uint8_t>(std::clamp(std::lround(sum[i]), 0L, 255L));
  return frame;
}

}  // namespace edgetrack_app
