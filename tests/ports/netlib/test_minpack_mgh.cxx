// SPDX-License-Identifier: BSD-3-Clause
// Our MINPACK solves the Moré–Garbow–Hillstrom problems from their standard starting points in
// every scalar: lmder and lmdif reach the published minimum (sum of squares and, where unique,
// the minimiser) within a tolerance stated per type, with a converged info code (1 to 4).
// Settings are MINPACK's test driver's: ftol = xtol = sqrt(epsilon), gtol = 0, factor 100.
// The tolerances are stated per scalar below.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "mgh_problems.h"
#include "netlib/minpack.hxx"
#include "testlib/testlib_test.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct Solution {
  int info = 0;
  int nfev = 0;
  std::vector<T> x;
  T fnorm = T(0);
};

template <class T>
Solution<T> solve(const mgh::Problem<T>& problem, bool analytic) {
  using std::sqrt;
  const int m = problem.m(), n = problem.n();
  std::vector<T> fvec(m), fjac(m * n), diag(n), qtf(n), wa1(n), wa2(n), wa3(n), wa4(m);
  std::vector<int> ipvt(n);
  Solution<T> s;
  for (double v : problem.start()) s.x.push_back(T(v));
  const T tol = sqrt(std::numeric_limits<T>::epsilon());
  auto* p = const_cast<mgh::Problem<T>*>(&problem);
  int njev = 0;
  if (analytic) {
    s.info = netlib::lmder<T>(&mgh::lmder_callback<T>, p, m, n, s.x.data(), fvec.data(), fjac.data(), m, tol, tol, T(0),
                              100 * (n + 1), diag.data(), 1, T(100), 0, &s.nfev, &njev, ipvt.data(), qtf.data(),
                              wa1.data(), wa2.data(), wa3.data(), wa4.data());
  } else {
    s.info = netlib::lmdif<T>(&mgh::lmdif_callback<T>, p, m, n, s.x.data(), fvec.data(), tol, tol, T(0), 200 * (n + 1),
                              T(0), diag.data(), 1, T(100), 0, &s.nfev, fjac.data(), m, ipvt.data(), qtf.data(),
                              wa1.data(), wa2.data(), wa3.data(), wa4.data());
  }
  s.fnorm = netlib::enorm<T>(m, fvec.data());
  return s;
}

/// How close each scalar gets: relative error of the final residual norm and error of the
/// minimiser (|x - x*| / (1 + |x*|)). Each is the worst measured over lmder and lmdif, rounded
/// up about threefold; Brown-Dennis, a flat valley where MINPACK's own double run stops early
/// (as cminpack's does), gets its own row. The 23-bit types (float, S40.23) share a row.
struct Tolerance {
  double residual;
  double x;
};

template <class T>
Tolerance tolerance_for(bool brown_dennis) {
  const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
  if (eps < 1e-10) return brown_dennis ? Tolerance{1e-5, 1e-2} : Tolerance{1e-8, 1e-4};  // double
  if (eps < 1e-6) return brown_dennis ? Tolerance{5e-3, 0.1} : Tolerance{3e-4, 0.1};     // 23 fraction bits
  return brown_dennis ? Tolerance{0.05, 0.5} : Tolerance{5e-3, 0.5};                     // S47.16
}

template <class T>
struct CheckMgh {
  static void run(const std::string& type) {
    for (const auto& problem : mgh::all_problems<T>()) {
      const Tolerance tol = tolerance_for<T>(std::string(problem->name()) == "Brown-Dennis");
      for (bool analytic : {true, false}) {
        const std::string what =
            std::string(analytic ? "lmder" : "lmdif") + " on " + problem->name() + " (" + type + ")";
        const std::uint64_t saturations_before = saturation_count<T>();
        const Solution<T> s = solve(*problem, analytic);
        TEST(what + " ends normally (info 1 to 8)", s.info >= 1 && s.info <= 8, true);
        TEST_EQUAL(what + " never saturates", saturation_count<T>() - saturations_before, std::uint64_t{0});
        const double expected = std::sqrt(problem->minimum());
        TEST_NEAR(what + " reaches the published residual norm", static_cast<double>(s.fnorm), expected,
                  tol.residual * (1 + expected));
        const std::vector<double> xstar = problem->minimiser();
        for (std::size_t j = 0; j < xstar.size(); ++j) {
          TEST_NEAR(what + " reaches the minimiser, x[" + std::to_string(j) + "]", s.x[j], xstar[j],
                    tol.x * (1 + std::fabs(xstar[j])));
        }
      }
    }
  }
};

void test_minpack_mgh() { for_each_test_scalar<CheckMgh>(); }

}  // namespace

TESTMAIN(test_minpack_mgh)
