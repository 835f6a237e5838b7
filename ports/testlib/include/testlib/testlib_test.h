// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/testlib/testlib_test.h: the test bookkeeping and the TEST macros.
/// Counts are kept per process; testlib_test_summary() returns the exit status.
#pragma once

#include <sstream>
#include <string>

void testlib_test_start(const char* name = nullptr);
void testlib_test_begin(const char* msg);
void testlib_test_begin(const std::string& msg);
void testlib_test_perform(bool success);
int testlib_test_summary();

void testlib_test_assert(const std::string& msg, bool expr);
void testlib_test_assert_near(const std::string& msg, double expr, double target = 0, double tol = 1e-12);
void testlib_test_assert_near_relative(const std::string& msg, double expr, double target = 0,
                                       double tol = 1e-12);
void testlib_test_assert_far(const std::string& msg, double expr, double target = 0, double tol = 1e-12);
/// Prints `expected` and `got` on failure, as upstream's TEST_EQUAL does.
void testlib_test_assert_equal(const std::string& msg, bool equal, const std::string& expected,
                               const std::string& got);

namespace testlib_detail {
template <class T>
std::string to_text(const T& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}
}  // namespace testlib_detail

/// Starts a test program; `s` names it in the summary.
#define START(s) testlib_test_start(s)
/// Checks that `p == v`, printing `s` as the test's description.
#define TEST(s, p, v)          \
  do {                         \
    testlib_test_begin(s);     \
    testlib_test_perform((p) == (v)); \
  } while (false)
/// Checks `p == v` and prints both values when they differ.
#define TEST_EQUAL(s, p, v)                                                               \
  do {                                                                                    \
    const auto& testlib_p_ = (p);                                                         \
    const auto& testlib_v_ = (v);                                                         \
    testlib_test_assert_equal(s, testlib_p_ == testlib_v_, testlib_detail::to_text(testlib_v_), \
                              testlib_detail::to_text(testlib_p_));                       \
  } while (false)
/// Checks |p - v| <= t; p and v may be any type that converts explicitly to double.
#define TEST_NEAR(s, p, v, t) \
  testlib_test_assert_near(s, static_cast<double>(p), static_cast<double>(v), static_cast<double>(t))
/// Checks |p - v| <= t * max(|p|, |v|).
#define TEST_NEAR_REL(s, p, v, t)                                                   \
  testlib_test_assert_near_relative(s, static_cast<double>(p), static_cast<double>(v), \
                                    static_cast<double>(t))
/// Checks |p - v| > t.
#define TEST_FAR(s, p, v, t) \
  testlib_test_assert_far(s, static_cast<double>(p), static_cast<double>(v), static_cast<double>(t))

/// Defines `testname_main`, the entry point a driver registers; its body is `testname()`.
#define TESTMAIN(testname)                     \
  int testname##_main(int, char*[]) {          \
    testlib_test_start(#testname);             \
    testname();                                \
    return testlib_test_summary();             \
  }
/// Like TESTMAIN, for test functions that take the command line.
#define TESTMAIN_ARGS(testname)                \
  int testname##_main(int argc, char* argv[]) { \
    testlib_test_start(#testname);             \
    testname(argc, argv);                      \
    return testlib_test_summary();             \
  }
