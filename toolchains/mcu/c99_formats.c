// SPDX-License-Identifier: BSD-3-Clause
/// Debian's newlib is built without C99's printf length modifiers: "%zu" prints "zu" and shifts
/// every later argument (a test's %f then printed hundreds of digits and overran its stack). The
/// printf family is linked through these wrappers (-Wl,--wrap, CMakeLists.txt), which rewrite z and
/// t (size_t, ptrdiff_t: 32 bits here, int's size) to nothing and j (intmax_t) to ll, which newlib
/// reads, then call newlib's own function.
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

enum { kFormatBytes = 512 };

/// `format` with its z, t and j modifiers rewritten into `out`; `format` itself when it has none
/// or is too long to copy.
static const char* newlib_format(const char* format, char* out) {
  if (!strpbrk(format, "ztj")) return format;
  size_t n = 0;
  for (const char* p = format; *p; ++p) {
    if (n + 3 >= kFormatBytes) return format;
    out[n++] = *p;
    if (*p != '%') continue;
    if (p[1] == '%') {  // "%%": a percent sign, not a conversion
      out[n++] = *++p;
      continue;
    }
    for (++p; *p && strchr("-+ #0123456789.*", *p); ++p) out[n++] = *p;  // flags, width, precision
    if (*p == 'j') {
      out[n++] = 'l';
      out[n++] = 'l';
    } else if (*p != 'z' && *p != 't') {
      --p;  // not a modifier of ours: copied by the loop
    }
  }
  out[n] = '\0';
  return out;
}

int __real_vfprintf(FILE* stream, const char* format, va_list args);
int __real_vsnprintf(char* buffer, size_t size, const char* format, va_list args);
int __real_vsprintf(char* buffer, const char* format, va_list args);

int __wrap_vfprintf(FILE* stream, const char* format, va_list args) {
  char rewritten[kFormatBytes];
  return __real_vfprintf(stream, newlib_format(format, rewritten), args);
}

int __wrap_vsnprintf(char* buffer, size_t size, const char* format, va_list args) {
  char rewritten[kFormatBytes];
  return __real_vsnprintf(buffer, size, newlib_format(format, rewritten), args);
}

int __wrap_vsprintf(char* buffer, const char* format, va_list args) {
  char rewritten[kFormatBytes];
  return __real_vsprintf(buffer, newlib_format(format, rewritten), args);
}

int __wrap_vprintf(const char* format, va_list args) { return __wrap_vfprintf(stdout, format, args); }

int __wrap_printf(const char* format, ...) {
  va_list args;
  va_start(args, format);
  const int n = __wrap_vfprintf(stdout, format, args);
  va_end(args);
  return n;
}

int __wrap_fprintf(FILE* stream, const char* format, ...) {
  va_list args;
  va_start(args, format);
  const int n = __wrap_vfprintf(stream, format, args);
  va_end(args);
  return n;
}

int __wrap_snprintf(char* buffer, size_t size, const char* format, ...) {
  va_list args;
  va_start(args, format);
  const int n = __wrap_vsnprintf(buffer, size, format, args);
  va_end(args);
  return n;
}

int __wrap_sprintf(char* buffer, const char* format, ...) {
  va_list args;
  va_start(args, format);
  const int n = __wrap_vsprintf(buffer, format, args);
  va_end(args);
  return n;
}
