// SPDX-License-Identifier: BSD-3-Clause
/// Rolling-shutter frames composed row by row from renders at the rows' read times.
#include "rolling_shutter_render.h"

#include <algorithm>
#include <cmath>

using namespace edgetrack;

namespace edgetrack_test {

void render_rolling_shutter(SceneRenderer& renderer, const EdgeModel& model, const std::vector<Se3>& poses, int k,
                            double readout, int renders, uint32_t noise_seed, Rgb565Frame& frame) {
  const int last = static_cast<int>(poses.size()) - 1;
  // The motion per frame after the frame and before it (camera frame: later = exp(twist) earlier).
  const Twist after = (poses[std::min(k + 1, last)] * poses[std::min(k + 1, last) - 1].inverse()).log();
  const Twist before = (poses[std::max(k, 1)] * poses[std::max(k, 1) - 1].inverse()).log();
  Rgb565Frame render;
  for (int j = 0; j < renders; ++j) {
    const double t = readout * (static_cast<double>(j) / (renders - 1) - 0.5);
    const Twist& twist = t >= 0 ? after : before;
    const real s = real(t);
    const Se3 pose = Se3::exp(Twist{s * twist.v, s * twist.w}) * poses[static_cast<size_t>(k)];
    renderer.render(model, pose, noise_seed, render);
    if (j == 0) frame = render;
    // Rows whose read time is nearest this render's.
    for (int y = 0; y < render.height; ++y) {
      const double row_t = readout * ((y + 0.5) / render.height - 0.5);
      const int nearest = static_cast<int>(std::lround((row_t / readout + 0.5) * (renders - 1)));
      if (nearest != j) continue;
      std::copy_n(render.pixels.begin() + static_cast<std::ptrdiff_t>(y) * render.width, render.width,
                  frame.pixels.begin() + static_cast<std::ptrdiff_t>(y) * render.width);
    }
  }
}

}  // namespace edgetrack_test
