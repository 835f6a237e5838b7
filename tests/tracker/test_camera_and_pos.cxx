// SPDX-License-Identifier: BSD-3-Clause
/// Projection follows ViSP's pinhole model, and .pos files read and write ViSP's pose vector
/// (the camera's XML is test_visp_config's).
#include <fstream>
#include <string>

#include "edgetrack/pinhole_camera.h"
#include "edgetrack/pose_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

static void test_camera_and_pos() {
  const std::string visp = EDGETRACK_VISP_IMAGES;
  const std::string out = EDGETRACK_TEST_OUTPUT;
  const std::string name = real_name();
  const double tol = name == "s47_16" ? 1e-4 : 1e-6;
  // Pixels carry the type's resolution times the focal length: about 3e-3 px for S47.16.
  const double pixel_tol = name == "s47_16" ? 1e-2 : name == "s40_23" ? 1e-3 : name == "float" ? 1e-4 : 1e-9;

  const PinholeCamera qvga{real(300), real(300), real(160), real(120), 320, 240};
  const Vec2 p = qvga.project({real(0.03), real(-0.015), real(0.15)});
  TEST_NEAR("u = u0 + px X / Z", p.x, 160 + 300 * 0.2, pixel_tol);
  TEST_NEAR("v = v0 + py Y / Z", p.y, 120 - 300 * 0.1, pixel_tol);
  const Vec3 back = qvga.unproject(p, real(0.15));
  TEST_NEAR("unproject inverts project (X)", back.x, 0.03, tol);
  TEST_NEAR("unproject inverts project (Y)", back.y, -0.015, tol);
  const PinholeCamera twice = qvga.scaled(2);
  const Vec2 p2 = twice.project({real(0.03), real(-0.015), real(0.15)});
  TEST_NEAR("a camera scaled by 2 sees the same ray at 2 (u + 0.5) - 0.5", p2.x, 2 * (220 + 0.5) - 0.5, 2 * pixel_tol);

  const Result<Se3> pose = read_pos(visp + "/mbt/cube.0.pos");
  TEST("mbt/cube.0.pos reads", pose.ok(), true);
  if (pose.ok()) {
    TEST_NEAR("its tz is 0.5071128378 m", pose.value().translation().z, 0.5071128378, tol);
    TEST_NEAR("its thetaU comes back (x)", pose.value().theta_u().x, 2.100485509, 2e2 * tol);
    TEST_NEAR("its thetaU comes back (z)", pose.value().theta_u().z, -0.4560126437, 2e2 * tol);
    const std::string written = out + "/written.pos";
    TEST("write_pos succeeds", write_pos(written, pose.value()).ok(), true);
    const Result<Se3> again = read_pos(written);
    TEST("a written .pos reads back", again.ok(), true);
    if (again.ok()) {
      TEST_NEAR("the written translation comes back", again.value().translation().x, 0.02231950571, tol);
      TEST_NEAR("the written rotation comes back", again.value().rotation().m[0][1],
                static_cast<double>(pose.value().rotation().m[0][1]), 2e2 * tol);
    }
  }
  std::ofstream(out + "/short.pos") << "0.1 0.2 0.3\n0 0\n";
  const Result<Se3> short_pos = read_pos(out + "/short.pos");
  TEST("a .pos with five numbers is an error", short_pos.ok(), false);
  TEST("writing into a missing directory is an error", write_pos(out + "/no/such/dir/x.pos", Se3()).ok(), false);
}

TESTMAIN(test_camera_and_pos)
