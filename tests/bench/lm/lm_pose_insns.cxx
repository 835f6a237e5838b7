// SPDX-License-Identifier: BSD-3-Clause
/// Instruction counts of the pose solve on the configured `real`, for
/// toolchains/qemu/count-insns.sh (tests/bench/lm/results.sh runs it on the ARM builds).
///
///   lm_pose_insns [problems=20]   one count window per vnl_levenberg_marquardt solve (construction and
///                                 minimize) of the first
///                                 N seeded pose problems (set-up stays outside the windows);
///                                 one line per solve; exits non-zero if one fails or saturates.
///   lm_pose_insns parts           one window per building block on problem 1: residuals,
///                                 Jacobian, qrfac, lmpar, qrsolv, enorm of the 60 residuals.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "count_markers.h"
#include "netlib/minpack.h"
#include "pose_problem.h"
#include "pose_problem.hxx"
#include "real/real.h"
#include "vnl/algo/vnl_levenberg_marquardt.h"

namespace {

int solves(int count) {
  int failures = 0;
  std::uint64_t total_saturations = 0;
  for (int i = 0; i < count; ++i) {
    const pose_problem::Problem problem = pose_problem::generate(static_cast<std::uint32_t>(i + 1));
    pose_problem::Residuals<real> f(problem);
    const std::uint64_t before = fixedpoint::saturation_count();
    // The window holds what a tracker does per frame: build the minimiser, start, minimise.
    edgetrack_count_begin();
    vnl_levenberg_marquardt_of<real> lm(f);
    vnl_vector<real> x = f.start();
    const bool converged = lm.minimize(x);
    edgetrack_count_end();
    const std::uint64_t saturations = fixedpoint::saturation_count() - before;
    total_saturations += saturations;
    if (!converged || saturations != 0) ++failures;
    std::printf("solve %d real %s converged %d iterations %d evaluations %d saturations %llu\n", i + 1, real_name(),
                converged ? 1 : 0, lm.get_num_jacobian_evaluations(), lm.get_num_evaluations(),
                static_cast<unsigned long long>(saturations));
  }
  std::printf("failures %d saturations %llu\n", failures, static_cast<unsigned long long>(total_saturations));
  return failures == 0 ? 0 : 1;
}

/// The building blocks of one LM iteration, each in its own window, in this order.
int parts() {
  const pose_problem::Problem problem = pose_problem::generate(1);
  const pose_problem::Residuals<real> f(problem);
  const int m = static_cast<int>(problem.points.size()), n = 6;
  const vnl_vector<real> x = f.start();
  std::vector<real> fvec(m), fjac(m * n), rdiag(n), acnorm(n), wa(n), qtb(n), diag(n), step(n), sdiag(n), wa1(n),
      wa2(n);
  std::vector<int> ipvt(n);
  const netlib::minpack_machine<real> machine = netlib::minpack_machine_constants<real>();
  edgetrack_count_begin();
  f.residuals(x.data_block(), fvec.data());
  edgetrack_count_end();
  edgetrack_count_begin();
  f.jacobian(x.data_block(), fjac.data(), m);
  edgetrack_count_end();
  edgetrack_count_begin();
  netlib::qrfac<real>(m, n, fjac.data(), m, true, ipvt.data(), rdiag.data(), acnorm.data(), wa.data(), machine);
  edgetrack_count_end();
  for (int j = 0; j < n; ++j) {
    fjac[j + j * m] = rdiag[j];
    qtb[j] = real(1);
    diag[j] = acnorm[j];
  }
  // A step bound well inside the Gauss-Newton step, so lmpar iterates on par as in a failed step.
  static constexpr real kDelta = real(1e-3);
  real par(0);
  edgetrack_count_begin();
  netlib::lmpar<real>(n, fjac.data(), m, ipvt.data(), diag.data(), qtb.data(), kDelta, &par, step.data(), sdiag.data(),
                      wa1.data(), wa2.data(), machine);
  edgetrack_count_end();
  edgetrack_count_begin();
  netlib::qrsolv<real>(n, fjac.data(), m, ipvt.data(), diag.data(), qtb.data(), step.data(), sdiag.data(), wa1.data(),
                       machine);
  edgetrack_count_end();
  edgetrack_count_begin();
  const real norm = netlib::enorm<real>(m, fvec.data(), machine);
  edgetrack_count_end();
  std::printf("parts residuals jacobian qrfac lmpar qrsolv enorm\n");
  std::printf("check par %.6g norm %.6g\n", static_cast<double>(par), static_cast<double>(norm));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "parts") == 0) return parts();
  return solves(argc > 1 ? std::atoi(argv[1]) : 20);
}
