// SPDX-License-Identifier: BSD-3-Clause
/// The golden-file comparison shared by the tracking tests.
#include "golden_check.h"

#include <cmath>
#include <cstdio>

#include "golden.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace edgetrack_test {
namespace {

/// Tolerances against the double golden run, per type: the double builds (host and QEMU) must
/// reproduce it. S40.23: within 0.1 mm in every frame (the claim), mean a tenth of that.
/// What keeps it there: the moving edges' sub-pixel match moves continuously with the control
/// point (a site's whole pixel jumps when rounding moves its truncated path) and three robust
/// rounds in the pose step (one left the pose leaning on gross mismatches). Measured (one-step
/// robust rounds, LM in millimetres): largest 0.021 mm (cube) and 0.026 mm (toy), mean 0.0014
/// mm; on the five times faster sequences 0.011 and 0.015 mm, mean 0.0012 and 0.0014 mm.
/// Rare single-point events remain (two competing edges within the search range, a point on an
/// occluding contour, a pixel the renderer rounds differently): over 64 runs with other noise
/// seeds and trajectory phases, with robust rounds run to convergence, one of them moved a
/// frame by more than 0.1 mm (up to 0.15 mm) in 3 runs; not re-run with one-step rounds.
void tolerances(double& max_mm, double& mean_mm) {
  const std::string name = real_name();
  if (name == "double") {
    max_mm = 0.01;
    mean_mm = 0.001;
  } else if (name == "s40_23") {
    max_mm = 0.1;
    mean_mm = 0.01;
  } else {  // float and S47.16 carry fewer digits; only a loose agreement is claimed
    max_mm = 5;
    mean_mm = 1;
  }
}

double distance_mm(const Vec3& a, const Vec3& b) {
  const double dx = static_cast<double>(a.x - b.x), dy = static_cast<double>(a.y - b.y),
               dz = static_cast<double>(a.z - b.z);
  return 1000 * std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace

/// Compares a run with the double golden file: mean and largest distance per frame, mm.
void compare_with_golden(const std::string& name, const SequenceRun& run) {
  double max_tolerance_mm = 0, mean_tolerance_mm = 0;
  tolerances(max_tolerance_mm, mean_tolerance_mm);
  const std::vector<Vec3> golden = read_golden(std::string(EDGETRACK_GOLDEN_DIR) + "/" + name);
  TEST_EQUAL("the golden file has one position per frame", golden.size(), run.frames.size());
  if (golden.size() != run.frames.size()) return;
  double worst = 0, sum = 0;
  for (size_t k = 0; k < golden.size(); ++k) {
    const double d = distance_mm(camera_position(run.frames[k].camera_from_model), golden[k]);
    worst = std::fmax(worst, d);
    sum += d;
  }
  std::printf("%s vs double golden: mean %.4f mm, largest %.4f mm\n", real_name(), sum / golden.size(), worst);
  TEST_NEAR((std::string("camera positions stay near the double run, mean (") + real_name() + ", mm)").c_str(),
            sum / golden.size(), 0, mean_tolerance_mm);
  TEST_NEAR((std::string("camera positions stay near the double run, every frame (") + real_name() + ", mm)").c_str(),
            worst, 0, max_tolerance_mm);
}

}  // namespace edgetrack_test
