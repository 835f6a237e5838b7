// SPDX-License-Identifier: BSD-3-Clause
/// The pinhole camera.
#include "edgetrack/pinhole_camera.h"

namespace edgetrack {

PinholeCamera PinholeCamera::scaled(int factor) const {
  // Pixel centres sit at integer coordinates, so pixel (0, 0) covers [-0.5, 0.5): in an image
  // `factor` times larger, the same ray lands at factor * (u + 0.5) - 0.5.
  const real shift = real(factor - 1) / 2;
  return {px * factor, py * factor, u0 * factor + shift, v0 * factor + shift, width * factor, height * factor};
}

}  // namespace edgetrack
