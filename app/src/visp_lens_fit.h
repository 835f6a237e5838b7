// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's one-coefficient lens given its forward coefficient: the back coefficient kdu that
/// vpPixelMeterConversion applies, fitted to the exact inverse of vpMeterPixelConversion's kud.
#pragma once

#include "edgetrack/pinhole_camera.h"

namespace edgetrack_app {

/// ViSP's kdu for `camera` (ViSP's lens, kud set): the least-squares fit of x = x_d (1 + kdu r_d^2)
/// to the exact inverse of x_d = x (1 + kud r^2) at a 17 x 17 grid of the image's pixels, corners
/// and edges included (a point beyond the lens's fold is left out). One unknown: the normal
/// equation is one division.
double fitted_kdu(const edgetrack::PinholeCamera& camera);

}  // namespace edgetrack_app
