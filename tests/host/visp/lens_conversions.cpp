// SPDX-License-Identifier: BSD-3-Clause
/// Meter-to-pixel and pixel-to-meter conversions with and without ViSP's distortion on a grid of
/// points, printed one number per line; built against Debian's ViSP (vpMeterPixelConversion,
/// vpPixelMeterConversion) with LENS_UPSTREAM, and against edgetrack's camera (PinholeCamera's
/// lens) without. transforms_compare.sh compares the two outputs.
#include <cstdio>

#ifdef LENS_UPSTREAM
#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#else
#include "edgetrack/pinhole_camera.h"
#endif

namespace {

constexpr double kPx = 600, kPy = 590, kU0 = 321.5, kV0 = 239.25, kKud = -0.25, kKdu = 0.28;

/// (u, v) of normalised (x, y), and (x, y) of pixel (u, v), through the lens or not.
void meter_to_pixel(bool distorted, double x, double y, double& u, double& v);
void pixel_to_meter(bool distorted, double u, double v, double& x, double& y);

#ifdef LENS_UPSTREAM
vpCameraParameters camera(bool distorted) {
  vpCameraParameters cam;
  if (distorted) cam.initPersProjWithDistortion(kPx, kPy, kU0, kV0, kKud, kKdu);
  else cam.initPersProjWithoutDistortion(kPx, kPy, kU0, kV0);
  return cam;
}
void meter_to_pixel(bool distorted, double x, double y, double& u, double& v) {
  vpMeterPixelConversion::convertPoint(camera(distorted), x, y, u, v);
}
void pixel_to_meter(bool distorted, double u, double v, double& x, double& y) {
  vpPixelMeterConversion::convertPoint(camera(distorted), u, v, x, y);
}
#else
edgetrack::PinholeCamera camera(bool distorted) {
  edgetrack::PinholeCamera cam(real(kPx), real(kPy), real(kU0), real(kV0), 640, 480);
  if (distorted) {
    cam.lens.model = edgetrack::LensModel::kVisp;
    cam.lens.kud = real(kKud);
    cam.lens.kdu = real(kKdu);
  }
  return cam;
}
void meter_to_pixel(bool distorted, double x, double y, double& u, double& v) {
  // Through project: the point at depth 1 in front of the camera.
  const edgetrack::Vec2 p = camera(distorted).project(edgetrack::Vec3{real(x), real(y), real(1)});
  u = static_cast<double>(p.x);
  v = static_cast<double>(p.y);
}
void pixel_to_meter(bool distorted, double u, double v, double& x, double& y) {
  const edgetrack::Vec3 p = camera(distorted).unproject(edgetrack::Vec2{real(u), real(v)}, real(1));
  x = static_cast<double>(p.x);
  y = static_cast<double>(p.y);
}
#endif

}  // namespace

int main() {
  for (int distorted = 0; distorted <= 1; ++distorted) {
    for (int i = -6; i <= 6; ++i)
      for (int j = -5; j <= 5; ++j) {
        double u = 0, v = 0;
        meter_to_pixel(distorted, 0.1 * i, 0.1 * j, u, v);
        std::printf("u %d %.12f\nv %d %.12f\n", distorted, u, distorted, v);
      }
    for (int u = 0; u <= 640; u += 40)
      for (int v = 0; v <= 480; v += 40) {
        double x = 0, y = 0;
        pixel_to_meter(distorted, u, v, x, y);
        std::printf("x %d %.12f\ny %d %.12f\n", distorted, x, distorted, y);
      }
  }
  return 0;
}
