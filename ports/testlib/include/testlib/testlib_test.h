// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/testlib/testlib_test.h: the test bookkeeping and the TEST macros.
/// Counts are kept per process; testlib_test_summary() returns the exit status.
#pragma once

#ifdef testlib_test_h_
#error "edgetrack's drop-in testlib/testlib_test.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>
#include <sstream>
#include <string>
#include <type_traits>

inline namespace edgetrack_ports {

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
/// The complex forms compare |expr - target| (relative: to max(|expr|, |target|)).
void testlib_test_assert_near(const std::string& msg, std::complex<double> expr, std::complex<double> target,
                              double tol = 1e-12);
void testlib_test_assert_near_relative(const std::string& msg, std::complex<double> expr,
                                       std::complex<double> target, double tol = 1e-12);
void testlib_test_assert_far(const std::string& msg, std::complex<double> expr, std::complex<double> target,
                             double tol = 1e-12);
/// Checks expr == target and prints both when they differ.
void testlib_test_assert_equal(const std::string& msg, long expr, long target);
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
template <class T>
struct is_complex : std::false_type {};
template <class T>
struct is_complex<std::complex<T>> : std::true_type {};
/// What TEST_NEAR compares: std::complex<double> for complex values, otherwise double (so
/// fixed-point values, which convert only explicitly, work too).
template <class T>
auto near_value(const T& x) {
  if constexpr (is_complex<T>::value) {
    return std::complex<double>(static_cast<double>(x.real()), static_cast<double>(x.imag()));
  } else {
    return static_cast<double>(x);
  }
}
/// Runs `check` on p and v as doubles, or as complex<double> when either is complex; each
/// argument is evaluated once, by the macro's caller.
template <class A, class B, class Check>
void compare(const std::string& msg, const A& a, const B& b, double tol, Check check) {
  if constexpr (is_complex<A>::value || is_complex<B>::value) {
    check(msg, std::complex<double>(near_value(a)), std::complex<double>(near_value(b)), tol);
  } else {
    check(msg, near_value(a), near_value(b), tol);
  }
}
}  // namespace testlib_detail

// Upstream's short names for the assertion functions.
#define Assert testlib_test_assert
#define AssertNear testlib_test_assert_near
#define AssertFar testlib_test_assert_far

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
/// Checks |p - v| <= t; p and v may be complex or any type that converts explicitly to double.
#define TEST_NEAR(s, p, v, t)                                                         \
  testlib_detail::compare(s, (p), (v), static_cast<double>(t), [](const auto&... args) { \
    testlib_test_assert_near(args...);                                                \
  })
/// Checks |p - v| <= t * max(|p|, |v|).
#define TEST_NEAR_REL(s, p, v, t)                                                     \
  testlib_detail::compare(s, (p), (v), static_cast<double>(t), [](const auto&... args) { \
    testlib_test_assert_near_relative(args...);                                       \
  })
/// Checks |p - v| > t.
#define TEST_FAR(s, p, v, t)                                                          \
  testlib_detail::compare(s, (p), (v), static_cast<double>(t), [](const auto&... args) { \
    testlib_test_assert_far(args...);                                                 \
  })

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

/// Runs statement x, then checks p == v.
#define TEST_RUN(s, x, p, v)          \
  do {                                \
    testlib_test_begin(s);            \
    x;                                \
    testlib_test_perform((p) == (v)); \
  } while (false)
/// Ends a test function with the summary's status.
#define SUMMARY() return testlib_test_summary()
/// Starts a test named after function x, runs it and returns the summary.
#define RUN_TEST_FUNC(x)  \
  testlib_test_start(#x); \
  x();                    \
  return testlib_test_summary()
/// Opens the definition of testname_main (the body calls START and ends with SUMMARY()).
#define MAIN(testname) int testname##_main(int, char*[])
#define MAIN_ARGS(testname) int testname##_main(int argc, char* argv[])
/// As TESTMAIN, for a stand-alone program whose entry point is testname itself.
#define TEST_MAIN(testname)   \
  int testname(int, char*[]) { \
    START(#testname);          \
    testname();                \
    SUMMARY();                 \
  }
#define TEST_MAIN_ARGS(testname)         \
  int testname(int argc, char* argv[]) { \
    START(#testname);                    \
    testname(argc, argv);                \
    SUMMARY();                           \
  }
/// main() of a one-test program without a driver.
#define TESTLIB_DEFINE_MAIN(testname) \
  int main() {                        \
    START(#testname);                 \
    testname();                       \
    return testlib_test_summary();    \
  }
#define TESTLIB_DEFINE_MAIN_ARGS(testname) \
  int main(int argc, char* argv[]) {       \
    START(#testname);                      \
    testname(argc, argv);                  \
    SUMMARY();                             \
  }

}  // inline namespace edgetrack_ports
