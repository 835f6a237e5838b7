// SPDX-License-Identifier: BSD-3-Clause
// Mirrors VXL's core/testlib/testlib_test.cxx: counts, messages and the summary.
#include "testlib/testlib_test.h"

#include <cmath>
#include <cstdio>

inline namespace edgetrack_ports {

namespace {
// The one piece of process-wide state testlib needs: the running tally of one test program.
struct Tally {
  int performed = 0;
  int failed = 0;
  std::string name;
};
Tally tally;
}  // namespace

void testlib_test_start(const char* name) {
  tally = Tally{};
  tally.name = name ? name : "";
  if (name) std::printf("-----------------------------------------------------------------------------\n"
                        "Start Testing %s:\n"
                        "-----------------------------------------------------------------------------\n",
                        name);
  std::fflush(stdout);
}

void testlib_test_begin(const char* msg) {
  std::printf(" Test %03d: %-62s --> ", tally.performed + 1, msg ? msg : "");
  std::fflush(stdout);
}

void testlib_test_begin(const std::string& msg) { testlib_test_begin(msg.c_str()); }

void testlib_test_perform(bool success) {
  ++tally.performed;
  if (success) {
    std::printf("  PASSED\n");
  } else {
    ++tally.failed;
    std::printf("**FAILED**\n");
  }
  std::fflush(stdout);
}

int testlib_test_summary() {
  std::printf("-----------------------------------------------------------------------------\n");
  if (tally.performed == 0) {
    // A test program that checks nothing is a broken test, not a passing one.
    std::printf("%s: no test was performed\n", tally.name.c_str());
    return 1;
  }
  if (tally.failed == 0)
    std::printf("All %d tests succeeded in %s\n", tally.performed, tally.name.c_str());
  else
    std::printf("%d of %d tests FAILED in %s\n", tally.failed, tally.performed, tally.name.c_str());
  std::printf("-----------------------------------------------------------------------------\n");
  std::fflush(stdout);
  return tally.failed == 0 ? 0 : 1;
}

void testlib_test_assert(const std::string& msg, bool expr) {
  testlib_test_begin(msg);
  testlib_test_perform(expr);
}

void testlib_test_assert_near(const std::string& msg, double expr, double target, double tol) {
  testlib_test_begin(msg);
  const double diff = std::fabs(expr - target);
  if (target != 0 && diff != 0) std::printf("(%.17g vs %.17g, |diff| %g) ", expr, target, diff);
  testlib_test_perform(diff <= tol);  // NaN fails
}

void testlib_test_assert_near_relative(const std::string& msg, double expr, double target, double tol) {
  testlib_test_begin(msg);
  const double scale = std::fmax(std::fabs(expr), std::fabs(target));
  const double diff = std::fabs(expr - target);
  if (diff != 0) std::printf("(%.17g vs %.17g, rel %g) ", expr, target, scale > 0 ? diff / scale : diff);
  testlib_test_perform(diff <= tol * (scale > 0 ? scale : 1));
}

void testlib_test_assert_far(const std::string& msg, double expr, double target, double tol) {
  testlib_test_begin(msg);
  testlib_test_perform(std::fabs(expr - target) > tol);
}

void testlib_test_assert_equal(const std::string& msg, bool equal, const std::string& expected,
                               const std::string& got) {
  testlib_test_begin(msg);
  if (!equal) std::printf("(expected %s, got %s) ", expected.c_str(), got.c_str());
  testlib_test_perform(equal);
}

void testlib_test_assert_near(const std::string& msg, std::complex<double> expr, std::complex<double> target,
                              double tol) {
  testlib_test_begin(msg);
  const double diff = std::abs(expr - target);
  if (target != 0.0 && diff != 0) std::printf("(|diff| %g) ", diff);
  testlib_test_perform(diff <= tol);
}

void testlib_test_assert_near_relative(const std::string& msg, std::complex<double> expr,
                                       std::complex<double> target, double tol) {
  testlib_test_begin(msg);
  const double scale = std::fmax(std::abs(expr), std::abs(target));
  const double diff = std::abs(expr - target);
  if (diff != 0) std::printf("(rel %g) ", scale > 0 ? diff / scale : diff);
  testlib_test_perform(diff <= tol * (scale > 0 ? scale : 1));
}

void testlib_test_assert_far(const std::string& msg, std::complex<double> expr, std::complex<double> target,
                             double tol) {
  testlib_test_begin(msg);
  testlib_test_perform(std::abs(expr - target) > tol);
}

void testlib_test_assert_equal(const std::string& msg, long expr, long target) {
  testlib_test_begin(msg);
  if (expr != target) std::printf("(expected %ld, got %ld) ", target, expr);
  testlib_test_perform(expr == target);
}

}  // inline namespace edgetrack_ports
