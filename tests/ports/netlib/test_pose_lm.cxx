// SPDX-License-Identifier: BSD-3-Clause
// The pose problems are well posed and vnl_levenberg_marquardt solves them: the analytic
// Jacobian matches central differences, the residual at the true pose is the injected noise,
// and from starts 5 degrees / 5 mm off, LM in every scalar recovers the true pose to within
// what 0.3 px of noise allows, without saturating.
#include <cmath>
#include <string>

#include "pose_problem.h"
#include "pose_problem.hxx"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_levenberg_marquardt.h"
#include "vnl/algo/vnl_levenberg_marquardt.hxx"
#include "vnl_test_types.h"

namespace {

constexpr int kProblems = 4;

void check_problem_set_up() {
  const pose_problem::Problem p = pose_problem::generate(1);
  TEST_EQUAL("a pose problem has 60 control points", p.points.size(), std::size_t{60});
  TEST("the start is within 5 degrees of the truth", pose_problem::rotation_error_deg(p.start, p.truth) <= 5.0, true);
  TEST("the start is within 5 mm of the truth", pose_problem::translation_error_mm(p.start, p.truth) <= 5.0, true);
  TEST_NEAR("the cube is 150 mm away", p.truth.translation[2], 0.15, 1e-12);

  pose_problem::Residuals<double> f(p);
  vnl_vector<double> x = f.start();
  x[0] = 0.01;
  x[1] = -0.02;
  x[2] = 0.015;
  vnl_matrix<double> J(60, 6);
  f.gradf(x, J);
  double worst = 0;
  for (unsigned j = 0; j < 6; ++j) {
    const double h = 1e-7;
    vnl_vector<double> plus = x, minus = x, fp(60), fm(60);
    plus[j] += h;
    minus[j] -= h;
    f.f(plus, fp);
    f.f(minus, fm);
    for (unsigned i = 0; i < 60; ++i) {
      worst = std::fmax(worst, std::fabs(J(i, j) - (fp[i] - fm[i]) / (2 * h)) / (1 + std::fabs(J(i, j))));
    }
  }
  TEST_NEAR("the analytic Jacobian matches central differences", worst, 0.0, 1e-5);

  // At the true pose the residuals are the injected noise: RMS near 0.3 px.
  const vnl_matrix_fixed<double, 3, 3> delta = p.truth.rotation * p.start.rotation.transpose();
  const vnl_vector_fixed<double, 3> w = vnl_rotation_thetau(delta);
  vnl_vector<double> truth(6), fx(60);
  for (unsigned k = 0; k < 3; ++k) {
    truth[k] = w[k];
    truth[3 + k] = p.truth.translation[k] * p.units_per_metre;
  }
  f.f(truth, fx);
  TEST_NEAR("the residual RMS at the true pose is the 0.3 px noise", fx.rms(), 0.3, 0.1);
}

template <class T>
struct CheckPose {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    for (int seed = 1; seed <= kProblems; ++seed) {
      const std::string at = " on problem " + std::to_string(seed) + in;
      const pose_problem::Problem p = pose_problem::generate(static_cast<std::uint32_t>(seed));
      pose_problem::Residuals<T> f(p);
      vnl_levenberg_marquardt_of<T> lm(f);
      vnl_vector<T> x = f.start();
      const std::uint64_t saturations_before = saturation_count<T>();
      const bool converged = lm.minimize(x);
      TEST("LM converges" + at, converged, true);
      TEST_EQUAL("LM never saturates" + at, saturation_count<T>() - saturations_before, std::uint64_t{0});
      double xd[6];
      for (int k = 0; k < 6; ++k) xd[k] = static_cast<double>(x[k]);
      const pose_problem::Pose pose = pose_problem::pose_from_parameters(p, xd);
      TEST_NEAR("LM recovers the rotation within 0.2 degrees" + at, pose_problem::rotation_error_deg(pose, p.truth), 0,
                0.2);
      TEST_NEAR("LM recovers the translation within 1 mm" + at, pose_problem::translation_error_mm(pose, p.truth), 0,
                1.0);
      TEST_NEAR("the end RMS residual is the noise level" + at, lm.get_end_error(), 0.3, 0.1);
    }
  }
};

void test_pose_lm() {
  check_problem_set_up();
  for_each_test_scalar<CheckPose>();
}

}  // namespace

TESTMAIN(test_pose_lm)
