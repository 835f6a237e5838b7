// SPDX-License-Identifier: BSD-3-Clause
// The printf family of the bare-metal tree (toolchains/mcu/c99_formats.c over newlib-nano): C99's
// length modifiers that nano does not read, 64-bit integers among them, print as C99 says, and the
// formats nano reads itself still do.
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace {

int failures = 0;

void expect(const char* got, const char* want, const char* format) {
  if (std::strcmp(got, want) == 0) return;
  std::printf("FAIL: \"%s\" printed \"%s\", expected \"%s\"\n", format, got, want);
  ++failures;
}

#define EXPECT_FORMAT(want, format, ...)                      \
  do {                                                        \
    char text[96];                                            \
    std::snprintf(text, sizeof text, format, __VA_ARGS__);    \
    expect(text, want, format);                               \
  } while (false)

}  // namespace

int main() {
  EXPECT_FORMAT("-9223372036854775808", "%lld", LLONG_MIN);
  EXPECT_FORMAT("18446744073709551615", "%llu", ULLONG_MAX);
  EXPECT_FORMAT("4294967296 next 7", "%llu next %d", 1ull << 32, 7);
  EXPECT_FORMAT("0x00ff00ff00ff", "%#014llx", 0xff00ff00ffull);
  EXPECT_FORMAT("FF00FF00FF", "%llX", 0xff00ff00ffull);
  EXPECT_FORMAT("0777", "%#llo", 0777ull);
  EXPECT_FORMAT("[   -00042]", "[%9.5lld]", -42ll);
  EXPECT_FORMAT("[+42      ]", "[%-+9lld]", 42ll);
  EXPECT_FORMAT("[-000000042]", "[%010jd]", std::intmax_t{-42});
  EXPECT_FORMAT("[]", "[%.0lld]", 0ll);
  EXPECT_FORMAT("[    12345]", "[%*lld]", 9, 12345ll);
  EXPECT_FORMAT("3 items, 2.50 each, -4 apart", "%zu items, %.2f each, %td apart", std::size_t{3}, 2.5,
                std::ptrdiff_t{-4});
  EXPECT_FORMAT("200 -56", "%hhu %hhd", 200, 200);
  EXPECT_FORMAT("zero 0.125 ok 100%", "zero %.3f %s 100%%", 0.125, "ok");
  EXPECT_FORMAT("1.23456789 -0.500", "%.9g %.3f", 1.234567891, -0.5);
  char small[6];
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-truncation"  // the truncation is what is checked
  const int n = std::snprintf(small, sizeof small, "%lld%s", 1234567ll, "tail");
#pragma GCC diagnostic pop
  expect(small, "12345", "%lld%s into 6 bytes");
  if (n != 11) {
    std::printf("FAIL: \"%%lld%%s\" into 6 bytes returned %d, expected 11\n", n);
    ++failures;
  }
  std::printf("c99 formats: %d failures\n", failures);
  return failures == 0 ? 0 : 1;
}
