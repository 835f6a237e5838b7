// SPDX-License-Identifier: BSD-3-Clause
/// The tree links newlib-nano (toolchains/cortex-m3.cmake), whose printf reads only the h, l and L
/// length modifiers: "%zu" prints "zu" and shifts every later argument, and a 64-bit integer
/// ("%lld", PRIu64, "%jd") cannot be printed at all. The printf family is linked through these
/// wrappers (-Wl,--wrap, CMakeLists.txt). A format that uses none of C99's other modifiers goes to
/// nano as it is; one that does is printed one conversion at a time: z and t (size_t, ptrdiff_t: 32
/// bits here, int's size) and hh by nano without the modifier, ll and j (64 bits) by this file.
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int __real_vfprintf(FILE* stream, const char* format, va_list args);
int __real_vsnprintf(char* buffer, size_t size, const char* format, va_list args);

/// Where the output goes: a stream, or a buffer of `size` bytes that is kept terminated.
typedef struct {
  FILE* stream;
  char* buffer;
  size_t size;
  int count;  // characters of the whole output, as printf returns it
} Sink;

static void emit(Sink* sink, const char* format, ...) {
  va_list args;
  va_start(args, format);
  int n;
  if (sink->stream) {
    n = __real_vfprintf(sink->stream, format, args);
  } else {
    const size_t used = (size_t)sink->count;
    n = used < sink->size ? __real_vsnprintf(sink->buffer + used, sink->size - used, format, args)
                          : __real_vsnprintf(NULL, 0, format, args);
  }
  va_end(args);
  if (n > 0) sink->count += n;
}

static void pad(Sink* sink, char c, int n) {
  static const char zeros[] = "0000000000000000";
  for (; n > 0; n -= 16) {
    const int k = n < 16 ? n : 16;
    if (c == '0') emit(sink, "%.*s", k, zeros);
    else emit(sink, "%*s", k, "");
  }
}

/// One conversion's parts, its width and precision already read (a '*' from the arguments).
typedef struct {
  char flags[8];
  int width;      // -1: none
  int precision;  // -1: none
  char length[3];
  char conversion;
} Spec;

/// The conversion `spec` with the given length modifier, in printf's own syntax.
static const char* spec_text(const Spec* spec, const char* length, char* out, size_t size) {
  char width[16] = "", precision[16] = "";
  if (spec->width >= 0) snprintf(width, sizeof width, "%d", spec->width);
  if (spec->precision >= 0) snprintf(precision, sizeof precision, ".%d", spec->precision);
  snprintf(out, size, "%%%s%s%s%s%c", spec->flags, width, precision, length, spec->conversion);
  return out;
}

/// A 64-bit integer conversion (d, i, u, o, x, X) as C99 prints it.
static void emit_64(Sink* sink, const Spec* spec, unsigned long long magnitude, int negative) {
  const char c = spec->conversion;
  const unsigned base = c == 'o' ? 8 : (c == 'x' || c == 'X') ? 16 : 10;
  const char* digit_set = c == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
  const int is_signed = c == 'd' || c == 'i';
  char digits[24];
  int n = 0;
  for (unsigned long long v = magnitude; v != 0; v /= base) digits[n++] = digit_set[v % base];
  const int precision = spec->precision >= 0 ? spec->precision : 1;
  int zeros = precision > n ? precision - n : 0;
  char prefix[3] = "";
  if (is_signed && negative) strcpy(prefix, "-");
  else if (is_signed && strchr(spec->flags, '+')) strcpy(prefix, "+");
  else if (is_signed && strchr(spec->flags, ' ')) strcpy(prefix, " ");
  if (strchr(spec->flags, '#') && magnitude != 0) {
    if (base == 16) strcpy(prefix, c == 'X' ? "0X" : "0x");
    if (base == 8 && zeros == 0) zeros = 1;
  }
  const int length = (int)strlen(prefix) + zeros + n;
  const int fill = spec->width > length ? spec->width - length : 0;
  const int left = strchr(spec->flags, '-') != NULL;
  const int zero_fill = !left && spec->precision < 0 && strchr(spec->flags, '0') != NULL;
  if (!left && !zero_fill) pad(sink, ' ', fill);
  emit(sink, "%s", prefix);
  if (zero_fill) pad(sink, '0', fill);
  pad(sink, '0', zeros);
  char text[24];
  for (int i = 0; i < n; ++i) text[i] = digits[n - 1 - i];
  emit(sink, "%.*s", n, text);
  if (left) pad(sink, ' ', fill);
}

/// Reads the conversion at `p` (just past its '%') into `spec`; returns the character after it.
static const char* read_spec(const char* p, Spec* spec, va_list* args) {
  size_t f = 0;
  for (; *p && strchr("-+ #0", *p); ++p)
    if (f + 1 < sizeof spec->flags) spec->flags[f++] = *p;
  spec->flags[f] = '\0';
  spec->width = -1;
  if (*p == '*') {
    spec->width = va_arg(*args, int);
    if (spec->width < 0) {  // a negative width argument is the '-' flag
      spec->width = -spec->width;
      if (f + 1 < sizeof spec->flags) spec->flags[f++] = '-', spec->flags[f] = '\0';
    }
    ++p;
  } else if (*p >= '0' && *p <= '9') {
    for (spec->width = 0; *p >= '0' && *p <= '9'; ++p) spec->width = spec->width * 10 + (*p - '0');
  }
  spec->precision = -1;
  if (*p == '.') {
    ++p;
    if (*p == '*') {
      spec->precision = va_arg(*args, int);
      ++p;
    } else {
      for (spec->precision = 0; *p >= '0' && *p <= '9'; ++p) spec->precision = spec->precision * 10 + (*p - '0');
    }
  }
  size_t l = 0;
  for (; *p && strchr("hljztLq", *p) && l + 1 < sizeof spec->length; ++p) spec->length[l++] = *p;
  spec->length[l] = '\0';
  spec->conversion = *p ? *p++ : '\0';
  return p;
}

/// The whole `format`, one conversion at a time.
static void emit_pieces(Sink* sink, const char* format, va_list* args) {
  char text[48];
  for (const char* p = format; *p;) {
    if (*p != '%') {
      const char* end = strchr(p, '%');
      const int n = end ? (int)(end - p) : (int)strlen(p);
      emit(sink, "%.*s", n, p);
      p += n;
      continue;
    }
    if (p[1] == '%') {
      emit(sink, "%%");
      p += 2;
      continue;
    }
    Spec spec;
    p = read_spec(p + 1, &spec, args);
    const char c = spec.conversion;
    const int wide = !strcmp(spec.length, "ll") || !strcmp(spec.length, "j") || !strcmp(spec.length, "q");
    if (strchr("diouxX", c) && c != '\0') {
      if (wide && (c == 'd' || c == 'i')) {
        const long long v = va_arg(*args, long long);
        emit_64(sink, &spec, v < 0 ? 0ull - (unsigned long long)v : (unsigned long long)v, v < 0);
      } else if (wide) {
        emit_64(sink, &spec, va_arg(*args, unsigned long long), 0);
      } else if (!strcmp(spec.length, "hh")) {
        const int v = va_arg(*args, int);
        emit(sink, spec_text(&spec, "", text, sizeof text), (c == 'd' || c == 'i') ? (int)(signed char)v : (int)(unsigned char)v);
      } else {
        const char* length = !strcmp(spec.length, "h") ? "h" : !strcmp(spec.length, "l") ? "l" : "";
        emit(sink, spec_text(&spec, length, text, sizeof text), va_arg(*args, long));
      }
    } else if (c != '\0' && strchr("fFeEgGaA", c)) {
      emit(sink, spec_text(&spec, "", text, sizeof text), va_arg(*args, double));
    } else if (c == 's') {
      emit(sink, spec_text(&spec, "", text, sizeof text), va_arg(*args, const char*));
    } else if (c == 'c') {
      emit(sink, spec_text(&spec, "", text, sizeof text), va_arg(*args, int));
    } else if (c == 'p') {
      emit(sink, spec_text(&spec, "", text, sizeof text), va_arg(*args, void*));
    } else if (c == 'n') {
      *va_arg(*args, int*) = sink->count;
    } else if (c != '\0') {  // not a conversion C99 knows: printed as written
      emit(sink, "%%%s%c", spec.flags, c);
    }
  }
}

/// Whether nano can print `format` itself: none of C99's modifiers it lacks (a letter z, t, j or q
/// or "ll" or "hh" anywhere, literal text included, takes the slower path, with the same output).
static int nano_reads(const char* format) {
  return !strpbrk(format, "ztjq") && !strstr(format, "ll") && !strstr(format, "hh");
}

static int print(Sink* sink, const char* format, va_list args) {
  va_list copy;
  va_copy(copy, args);
  emit_pieces(sink, format, &copy);
  va_end(copy);
  return sink->count;
}

int __wrap_vfprintf(FILE* stream, const char* format, va_list args) {
  if (nano_reads(format)) return __real_vfprintf(stream, format, args);
  Sink sink = {stream, NULL, 0, 0};
  return print(&sink, format, args);
}

int __wrap_vsnprintf(char* buffer, size_t size, const char* format, va_list args) {
  if (nano_reads(format)) return __real_vsnprintf(buffer, size, format, args);
  if (size > 0) buffer[0] = '\0';
  Sink sink = {NULL, buffer, size, 0};
  return print(&sink, format, args);
}

int __wrap_vsprintf(char* buffer, const char* format, va_list args) {
  return __wrap_vsnprintf(buffer, INT_MAX, format, args);
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
