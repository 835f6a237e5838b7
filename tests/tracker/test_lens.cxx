// SPDX-License-Identifier: BSD-3-Clause
/// The camera's lens models (ViSP's kud/kdu radial model, OpenCV's radial-tangential one) and
/// the tracker's steps through them: the inverse undoes the lens, the lens's derivative matches
/// finite differences, control points lie on the distorted image of their edge with the curve's
/// own direction, Edge-ID keeps the visible ones, and the pose step recovers the true pose from
/// matches on the distorted edges (as fast as without a lens: its Jacobian includes the lens)
/// where the pinhole alone does not. Zero coefficients are the pinhole.
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_solver.h"
#include "edgetrack/scene_renderer.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

double d(const real& v) { return static_cast<double>(v); }

PinholeCamera visp_camera(double kud, double kdu) {
  PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  camera.lens.model = LensModel::kVisp;
  camera.lens.kud = real(kud);
  camera.lens.kdu = real(kdu);
  return camera;
}

PinholeCamera opencv_camera() {
  PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  camera.lens.model = LensModel::kOpenCv;
  camera.lens.k1 = real(-0.21);
  camera.lens.k2 = real(0.06);
  camera.lens.p1 = real(0.002);
  camera.lens.p2 = real(-0.0015);
  camera.lens.k3 = real(-0.01);
  return camera;
}

double position_error_mm(const Se3& a, const Se3& b) {
  const Vec3 e = a.inverse().translation() - b.inverse().translation();
  return 1000 * std::sqrt(d(e.x) * d(e.x) + d(e.y) * d(e.y) + d(e.z) * d(e.z));
}

/// The largest |inverse(distort(n)) - n| over a grid of normalised points within `radius`.
double worst_round_trip(const PinholeCamera& camera, double radius) {
  double worst = 0;
  for (int i = -8; i <= 8; ++i)
    for (int j = -8; j <= 8; ++j) {
      const Vec2 n{real(radius * i / 8), real(radius * j / 8)};
      const Vec2 back = camera.invert_distortion(camera.distort(n));
      worst = std::fmax(worst, std::fmax(std::fabs(d(back.x - n.x)), std::fabs(d(back.y - n.y))));
    }
  return worst;
}

/// The largest difference between lens_jacobian and central differences of distort.
double worst_jacobian_error(const PinholeCamera& camera, double radius, double h) {
  double worst = 0;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j) {
      const Vec2 n{real(radius * i / 6), real(radius * j / 6)};
      const LensJacobian jac = camera.lens_jacobian(n);
      const Vec2 dx = camera.distort(n + Vec2{real(h), real(0)}) - camera.distort(n - Vec2{real(h), real(0)});
      const Vec2 dy = camera.distort(n + Vec2{real(0), real(h)}) - camera.distort(n - Vec2{real(0), real(h)});
      const double fd[4] = {d(dx.x) / (2 * h), d(dy.x) / (2 * h), d(dx.y) / (2 * h), d(dy.y) / (2 * h)};
      const double an[4] = {d(jac.xx), d(jac.xy), d(jac.yx), d(jac.yy)};
      for (int k = 0; k < 4; ++k) worst = std::fmax(worst, std::fabs(fd[k] - an[k]));
    }
  return worst;
}

/// The largest distance (pixels) between the image through the lens of the straight normalised
/// segment a-b and the polyline of the chord_pieces(a, b, tolerance) pieces of equal parameter
/// that Edge-ID draws and the sampling measures, from 64 points on each piece.
double worst_chord_error(const PinholeCamera& camera, const Vec2& a, const Vec2& b, double tolerance) {
  const int pieces = camera.chord_pieces(a, b, real(tolerance), 64);
  const auto pixel = [&](double t) {
    const Vec2 n{real(d(a.x) + t * (d(b.x) - d(a.x))), real(d(a.y) + t * (d(b.y) - d(a.y)))};
    const Vec2 p = camera.to_pixel(camera.distort(n));
    return std::pair<double, double>(d(p.x), d(p.y));
  };
  double worst = 0;
  for (int k = 0; k < pieces; ++k) {
    const auto p = pixel(double(k) / pieces), q = pixel(double(k + 1) / pieces);
    const double cx = q.first - p.first, cy = q.second - p.second, length = std::hypot(cx, cy);
    for (int i = 1; i < 64; ++i) {
      const auto c = pixel((k + i / 64.0) / pieces);
      const double off = length > 0 ? std::fabs(cx * (c.second - p.second) - cy * (c.first - p.first)) / length
                                    : std::hypot(c.first - p.first, c.second - p.second);
      worst = std::fmax(worst, off);
    }
  }
  return worst;
}

/// The worst chord error over segments across the QVGA image: lines at every angle through a
/// grid of centres, as long as the image is wide.
double worst_chord_error_over_image(const PinholeCamera& camera, double tolerance) {
  double worst = 0;
  for (int cx = -2; cx <= 2; ++cx)
    for (int cy = -2; cy <= 2; ++cy)
      for (int angle = 0; angle < 12; ++angle) {
        const double c = std::cos(angle * 3.14159265358979 / 12), s = std::sin(angle * 3.14159265358979 / 12);
        const double mx = 0.12 * cx, my = 0.1 * cy, half = 0.35;
        const Vec2 a{real(mx - half * c), real(my - half * s)}, b{real(mx + half * c), real(my + half * s)};
        worst = std::fmax(worst, worst_chord_error(camera, a, b, tolerance));
      }
  return worst;
}

}  // namespace

static void test_lens_chord_pieces() {
  const std::string name = real_name();
  // The pieces keep the curve within the tolerance where it is a parabola across the chord; along
  // a long line the lens bends more towards the image's edge (1 - 6 k a^2 at a from the foot of
  // the perpendicular from the centre), so the outer pieces exceed it: 0.551 px measured for
  // kud = -0.25 on lines of 0.7 (154 px) reaching r = 0.6; fixed point rounds the bend within
  // 0.003 px (S47.16).
  for (const double kud : {-0.25, 0.12}) {
    const PinholeCamera camera = visp_camera(kud, 0);
    const double worst = worst_chord_error_over_image(camera, 0.5);
    std::printf("%s kud %+.2f: the polylines of chord_pieces(0.5 px) stay within %.3f px of the curve\n", name.c_str(),
                kud, worst);
    TEST("the pieces chord_pieces gives for 0.5 px keep the lens's curve within 0.56 px of them", worst <= 0.56, true);
  }
  const PinholeCamera opencv = opencv_camera();
  TEST("and so for OpenCV's model", worst_chord_error_over_image(opencv, 0.5) <= 0.56, true);
  TEST("a pinhole needs one piece", visp_camera(0, 0).chord_pieces(Vec2{real(-0.4), real(0.3)},
                                                                  Vec2{real(0.4), real(0.3)}, real(0.5), 64),
       1);
  const Vec2 a{real(-0.4), real(0.3)}, b{real(0.4), real(0.3)};
  TEST("a line bent by the lens needs more than one",
       visp_camera(-0.25, 0).chord_pieces(a, b, real(0.5), 64) > 1, true);
  // bend_within, chord_pieces's shortcut to one piece, only where the image's middle lies within
  // the tolerance of the ends' chord: segments of 0.01 to 0.4 at every angle across the image.
  for (const double kud : {-0.25, 0.12}) {
    const PinholeCamera camera = visp_camera(kud, 0);
    int within = 0, wrong = 0;
    for (int cx = -3; cx <= 3; ++cx)
      for (int cy = -3; cy <= 3; ++cy)
        for (int angle = 0; angle < 8; ++angle)
          for (const double half : {0.005, 0.02, 0.05, 0.1, 0.2}) {
            const double c = std::cos(angle * 3.14159265358979 / 8), s = std::sin(angle * 3.14159265358979 / 8);
            const double mx = 0.12 * cx, my = 0.1 * cy;
            const Vec2 p{real(mx - half * c), real(my - half * s)}, q{real(mx + half * c), real(my + half * s)};
            if (!camera.bend_within(p, q, real(0.5))) continue;
            ++within;
            const Vec2 dp = camera.distort(p), dq = camera.distort(q), dm = camera.distort(real(0.5) * (p + q));
            const double f = d(camera.px), chord_x = f * (d(dq.x) - d(dp.x)), chord_y = f * (d(dq.y) - d(dp.y));
            const double mid_x = f * (d(dm.x) - d(dp.x)), mid_y = f * (d(dm.y) - d(dp.y));
            const double bend = std::fabs(chord_x * mid_y - chord_y * mid_x) / std::hypot(chord_x, chord_y);
            if (bend > 0.5) ++wrong;
          }
    std::printf("%s kud %+.2f: bend_within(0.5 px) settled %d of 1960 segments\n", name.c_str(), kud, within);
    TEST("bend_within settles short segments to one piece", within > 0, true);
    TEST("and none whose image bends more than the tolerance", wrong, 0);
  }
}

static void test_lens() {
  const std::string name = real_name();
  const bool floating = name == "double" || name == "float";
  // Resolutions: S40.23 1.2e-7, S47.16 1.5e-5 on coordinates near 1.
  const double round_trip_tol = name == "double" ? 1e-12 : name == "s40_23" ? 2e-6 : name == "float" ? 2e-6 : 2e-4;
  const double h = floating && name == "double" ? 1e-6 : 1e-2;  // fixed point: a step far above the resolution
  // Central differences err by h^2 / 6 f''' (|f'''| <= 6 |k| here) plus the rounding over 2h.
  const double jacobian_tol = name == "double" ? 1e-8 : name == "s47_16" ? 5e-3 : 5e-4;

  const PinholeCamera barrel = visp_camera(-0.25, 0.28);
  const PinholeCamera cushion = visp_camera(0.12, -0.11);
  const PinholeCamera opencv = opencv_camera();
  TEST("a lens with coefficients is distorted", barrel.distorted() && opencv.distorted(), true);
  TEST("a ViSP or OpenCV lens with zero coefficients is the pinhole",
       !visp_camera(0, 0).distorted() && !PinholeCamera{}.distorted(), true);
  {
    PinholeCamera zero = opencv;
    zero.lens = LensDistortion{};
    zero.lens.model = LensModel::kOpenCv;
    const Vec3 p{real(0.03), real(-0.02), real(0.15)};
    const Vec2 a = zero.project(p), b = zero.pinhole().project(p);
    TEST("zero coefficients project exactly as the pinhole", a.x == b.x && a.y == b.y, true);
  }
  // Within r = 0.9 (the QVGA corners at px = 220 are at r = 0.91).
  TEST_NEAR("ViSP kud = -0.25: inverting the lens undoes it", worst_round_trip(barrel, 0.6), 0, round_trip_tol);
  TEST_NEAR("ViSP kud = +0.12: inverting the lens undoes it", worst_round_trip(cushion, 0.6), 0, round_trip_tol);
  TEST_NEAR("OpenCV k1 k2 p1 p2 k3: inverting the lens undoes it", worst_round_trip(opencv, 0.6), 0, round_trip_tol);
  {
    // project then unproject at the point's depth: the same point (OpenCV's inverse is exact).
    const Vec3 p{real(0.04), real(-0.03), real(0.15)};
    const Vec3 back = opencv.unproject(opencv.project(p), p.z);
    TEST_NEAR("OpenCV: unproject(project(P), Z) is P (m)", std::fabs(d(back.x - p.x)) + std::fabs(d(back.y - p.y)), 0,
              300 * round_trip_tol);
    // ViSP's kdu is the calibration's own approximate inverse: unproject follows it, as
    // vpPixelMeterConversion does, x = x_d (1 + kdu r_d^2).
    const Vec2 pixel{real(290), real(40)};
    const Vec3 ray = barrel.unproject(pixel, real(1));
    const double xd = (290 - 160) / 220.0, yd = (40 - 120) / 220.0, f = 1 + 0.28 * (xd * xd + yd * yd);
    TEST_NEAR("ViSP: unproject applies kdu as vpPixelMeterConversion does (x)", d(ray.x), xd * f, 300 * round_trip_tol);
    TEST_NEAR("ViSP: unproject applies kdu as vpPixelMeterConversion does (y)", d(ray.y), yd * f, 300 * round_trip_tol);
  }
  TEST_NEAR("ViSP kud = -0.25: the lens's derivative matches central differences",
            worst_jacobian_error(barrel, 0.6, h), 0, jacobian_tol);
  TEST_NEAR("OpenCV: the lens's derivative matches central differences", worst_jacobian_error(opencv, 0.6, h), 0,
            jacobian_tol);
  TEST("scaling and downscaling keep the lens", barrel.scaled(2).lens.kud == barrel.lens.kud, true);

  const Result<EdgeModel> loaded = load_model(std::string(EDGETRACK_DATA_DIR) + "/models/cube60.cao");
  TEST("the cube loads", loaded.ok(), true);
  if (!loaded.ok()) return;
  const EdgeModel& cube = loaded.value();
  // Off centre, so that the lens bends the edges by several pixels.
  const Se3 truth(rotation_exp({real(0.5), real(-0.6), real(0.15)}), {real(0.03), real(0.02), real(0.16)});
  const Se3 start(rotation_exp({real(0.012), real(-0.01), real(0.008)}) * truth.rotation(),
                  truth.translation() + Vec3{real(0.002), real(-0.001), real(0.002)});

  // Control points on the curve: each pixel is its 3D point's projection through the lens, and
  // the direction is the curve's, by finite differences along the 3D edge.
  const std::vector<ControlPoint> sampled = sample_control_points(cube, barrel, truth, {});
  double worst_off_curve = 0, worst_direction = 0;
  double largest_bend = 0;  // how far the curve runs from its chord at the points
  for (const ControlPoint& p : sampled) {
    const Vec2 on_curve = barrel.project(truth * p.point_in_model);
    worst_off_curve = std::fmax(worst_off_curve, std::fabs(d(on_curve.x - p.pixel.x)) + std::fabs(d(on_curve.y - p.pixel.y)));
    const Edge& e = cube.edges[static_cast<size_t>(p.edge)];
    const Vec3 a = cube.vertices[e.a], b = cube.vertices[e.b];
    const Vec3 step = real(0.02) * (b - a);  // 1.2 mm: wide against S47.16's 0.015 mm resolution
    const Vec2 ahead = barrel.project(truth * (p.point_in_model + step));
    const Vec2 behind = barrel.project(truth * (p.point_in_model - step));
    const Vec2 tangent = ahead - behind;
    const double length = std::hypot(d(tangent.x), d(tangent.y));
    // |sin| of the angle between the sampled direction and the curve's tangent.
    worst_direction = std::fmax(worst_direction, std::fabs(d(tangent.x) * d(p.direction.y) - d(tangent.y) * d(p.direction.x)) / length);
    const Vec2 ea = barrel.project(truth * a), eb = barrel.project(truth * b);
    const Vec2 chord = eb - ea;
    const double chord_length = std::hypot(d(chord.x), d(chord.y));
    largest_bend = std::fmax(largest_bend, std::fabs(d(chord.x) * d(p.pixel.y - ea.y) - d(chord.y) * d(p.pixel.x - ea.x)) / chord_length);
  }
  std::printf("%zu control points through kud = -0.25; farthest from its edge's chord: %.2f px\n", sampled.size(),
              largest_bend);
  TEST("the lens bends the sampled edges by more than half a pixel from their chords", largest_bend > 0.5, true);
  std::printf("farthest off the curve: %.4g px; largest |sin| to the curve's direction: %.4g\n", worst_off_curve,
              worst_direction);
  TEST_NEAR("every control point lies on the distorted edge (px)", worst_off_curve, 0, name == "s47_16" ? 0.1 : 1e-3);
  TEST_NEAR("and its direction is the curve's (sin of the angle)", worst_direction, 0, name == "s47_16" ? 0.02 : 2e-3);

  // Edge-ID through the lens: the points a ray cast finds visible are kept (the hidden ones by
  // more than a pixel are dropped).
  EdgeIdBuffer ids(barrel);
  ids.render(cube, truth);
  const std::vector<ControlPoint> visible = keep_visible(sampled, ids);
  int truly_visible = 0, kept_visible = 0, kept_hidden = 0;
  for (const ControlPoint& p : sampled) {
    const bool seen = point_visible(cube, truth, p.point_in_model, real(0.02));
    truly_visible += seen;
    bool kept = false;
    for (const ControlPoint& v : visible) kept = kept || (v.edge == p.edge && v.pixel.x == p.pixel.x && v.pixel.y == p.pixel.y);
    kept_visible += seen && kept;
    kept_hidden += !seen && kept;
  }
  std::printf("Edge-ID through the lens: %d of %d visible points kept, %d hidden kept\n", kept_visible, truly_visible,
              kept_hidden);
  TEST("Edge-ID through the lens keeps at least 95 % of the visible points", kept_visible * 100 >= 95 * truly_visible,
       true);
  TEST("and no hidden one", kept_hidden <= 1, true);

  // The pose step: matches on the distorted true edges, control points from the start pose.
  EdgeIdBuffer start_ids(barrel);
  start_ids.render(cube, start);
  const std::vector<ControlPoint> points = keep_visible(sample_control_points(cube, barrel, start, {}), start_ids);
  std::vector<EdgeMatch> matches;
  for (const ControlPoint& p : points) {
    EdgeMatch m;
    m.point = p;
    m.found = barrel.project(truth * p.point_in_model);
    matches.push_back(m);
  }
  const PoseParams params;
  std::vector<EdgeMatch> with_lens = matches, without_lens = matches;
  const PoseSolution solved = solve_pose(with_lens, barrel, start, params);
  const PoseSolution pinhole = solve_pose(without_lens, barrel.pinhole(), start, params);
  const double tol_mm = name == "s47_16" ? 1.0 : name == "double" ? 1e-4 : 0.02;
  std::printf("pose through the lens: %.5f mm in %d LM iterations; ignoring the lens: %.3f mm\n",
              position_error_mm(solved.camera_from_model, truth), solved.iterations,
              position_error_mm(pinhole.camera_from_model, truth));
  TEST("through the lens the pose is solved", solved.solved, true);
  TEST_NEAR("and the camera position comes back (mm)", position_error_mm(solved.camera_from_model, truth), 0, tol_mm);
  TEST("the Jacobian through the lens converges within 12 LM iterations plus 1 per robust solve",
       solved.iterations <= 12 + params.robust_rounds, true);
  TEST("ignoring the lens, the same matches give a pose more than 1 mm off",
       position_error_mm(pinhole.camera_from_model, truth) > 1, true);
}

TESTMAIN(test_lens)
TESTMAIN(test_lens_chord_pieces)
