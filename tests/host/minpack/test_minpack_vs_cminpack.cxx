// SPDX-License-Identifier: BSD-3-Clause
// Our MINPACK (netlib::lmder, netlib::lmdif) in double against upstream MINPACK in C
// (cminpack) on the Moré–Garbow–Hillstrom problems from their standard starting points:
// same termination code, same numbers of iterations and function evaluations, and the same
// solution to 1e-9 relative. Settings are MINPACK's own test driver's (lmder1/lmdif1): ftol =
// xtol = sqrt(epsilon), gtol = 0, factor 100, mode 1.
#include <cminpack.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "mgh_problems.h"
#include "netlib/minpack.h"
#include "testlib/testlib_test.h"

namespace {

using Problem = mgh::Problem<double>;

struct Run {
  int info = 0;
  int nfev = 0;
  int njev = 0;
  std::vector<double> x;
};

struct Work {
  explicit Work(int m, int n) : fvec(m), fjac(m * n), diag(n), qtf(n), wa1(n), wa2(n), wa3(n), wa4(m), ipvt(n) {}
  std::vector<double> fvec, fjac, diag, qtf, wa1, wa2, wa3, wa4;
  std::vector<int> ipvt;
};

const double kTol = std::sqrt(std::numeric_limits<double>::epsilon());

Run ours_lmder(const Problem& p) {
  const int m = p.m(), n = p.n();
  Work w(m, n);
  Run run;
  run.x = p.start();
  run.info = netlib::lmder<double>(&mgh::lmder_callback<double>, const_cast<Problem*>(&p), m, n, run.x.data(),
                                   w.fvec.data(), w.fjac.data(), m, kTol, kTol, 0.0, 100 * (n + 1), w.diag.data(), 1,
                                   100.0, 0, &run.nfev, &run.njev, w.ipvt.data(), w.qtf.data(), w.wa1.data(),
                                   w.wa2.data(), w.wa3.data(), w.wa4.data());
  return run;
}

Run upstream_lmder(const Problem& p) {
  const int m = p.m(), n = p.n();
  Work w(m, n);
  Run run;
  run.x = p.start();
  run.info = lmder(&mgh::lmder_callback<double>, const_cast<Problem*>(&p), m, n, run.x.data(), w.fvec.data(),
                   w.fjac.data(), m, kTol, kTol, 0.0, 100 * (n + 1), w.diag.data(), 1, 100.0, 0, &run.nfev, &run.njev,
                   w.ipvt.data(), w.qtf.data(), w.wa1.data(), w.wa2.data(), w.wa3.data(), w.wa4.data());
  return run;
}

Run ours_lmdif(const Problem& p) {
  const int m = p.m(), n = p.n();
  Work w(m, n);
  Run run;
  run.x = p.start();
  run.info =
      netlib::lmdif<double>(&mgh::lmdif_callback<double>, const_cast<Problem*>(&p), m, n, run.x.data(), w.fvec.data(),
                            kTol, kTol, 0.0, 200 * (n + 1), 0.0, w.diag.data(), 1, 100.0, 0, &run.nfev, w.fjac.data(),
                            m, w.ipvt.data(), w.qtf.data(), w.wa1.data(), w.wa2.data(), w.wa3.data(), w.wa4.data());
  return run;
}

Run upstream_lmdif(const Problem& p) {
  const int m = p.m(), n = p.n();
  Work w(m, n);
  Run run;
  run.x = p.start();
  run.info = lmdif(&mgh::lmdif_callback<double>, const_cast<Problem*>(&p), m, n, run.x.data(), w.fvec.data(), kTol,
                   kTol, 0.0, 200 * (n + 1), 0.0, w.diag.data(), 1, 100.0, 0, &run.nfev, w.fjac.data(), m,
                   w.ipvt.data(), w.qtf.data(), w.wa1.data(), w.wa2.data(), w.wa3.data(), w.wa4.data());
  return run;
}

void compare(const std::string& what, const Run& ours, const Run& upstream) {
  TEST_EQUAL(what + ": same info code", ours.info, upstream.info);
  TEST_EQUAL(what + ": same function evaluations", ours.nfev, upstream.nfev);
  TEST_EQUAL(what + ": same Jacobian evaluations", ours.njev, upstream.njev);
  for (std::size_t j = 0; j < ours.x.size(); ++j) {
    TEST_NEAR_REL(what + ": same x[" + std::to_string(j) + "] to 1e-9 relative", ours.x[j], upstream.x[j], 1e-9);
  }
}

void test_minpack_vs_cminpack() {
  for (const auto& problem : mgh::all_problems<double>()) {
    compare(std::string("lmder on ") + problem->name(), ours_lmder(*problem), upstream_lmder(*problem));
    compare(std::string("lmdif on ") + problem->name(), ours_lmdif(*problem), upstream_lmdif(*problem));
  }
  const double x[4] = {3e-200, -4e-200, 1e200, 0};
  const double y[3] = {3, 4, 12};
  TEST_NEAR_REL("enorm equals cminpack's on huge and tiny components", netlib::enorm<double>(4, x), enorm(4, x), 1e-15);
  TEST_NEAR_REL("enorm equals cminpack's on plain components", netlib::enorm<double>(3, y), enorm(3, y), 1e-15);
}

}  // namespace

TESTMAIN(test_minpack_vs_cminpack)
