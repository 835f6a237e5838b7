// SPDX-License-Identifier: BSD-3-Clause
/// The kdu fit of visp_lens_fit.h.
#include "visp_lens_fit.h"

#include <cmath>

namespace edgetrack_app {

double fitted_kdu(const edgetrack::PinholeCamera& camera) {
  double along = 0, square = 0;
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i <= 16; ++i) {
      const edgetrack::Vec2 d = camera.to_normalised({real(camera.width * i / 16.0), real(camera.height * j / 16.0)});
      const edgetrack::Vec2 n = camera.invert_distortion(d);
      const edgetrack::Vec2 miss = camera.distort(n) - d;
      if (std::fabs(static_cast<double>(miss.x)) + std::fabs(static_cast<double>(miss.y)) > 1e-6) continue;  // beyond the fold
      const double xd = static_cast<double>(d.x), yd = static_cast<double>(d.y), r2 = xd * xd + yd * yd;
      along += xd * r2 * (static_cast<double>(n.x) - xd) + yd * r2 * (static_cast<double>(n.y) - yd);
      square += (xd * r2) * (xd * r2) + (yd * r2) * (yd * r2);
    }
  return square > 0 ? along / square : 0;
}

}  // namespace edgetrack_app
