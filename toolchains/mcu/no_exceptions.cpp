// SPDX-License-Identifier: BSD-3-Clause
/// The C++ runtime's failure paths for a tree built without exceptions (-fno-exceptions). The
/// library's own operator new and std::__throw_* (the containers' and strings' length and range
/// errors) throw, and so link the whole unwinder, the exception classes and their strings: some
/// 10 KB of flash and the exception pool's heap in every image. These end the run with the
/// failure's line instead, as an uncaught exception would have. The __throw_* functions are where
/// libstdc++'s headers send those errors; ours, linked whole before the library, replace its own.
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "terminate: %s\n", what);
  std::abort();
}

}  // namespace

/// As the standard's operator new: the new handler (the command line's "out of memory" line) is
/// called while allocation fails; with none, the run ends.
void* operator new(std::size_t size) {
  for (;;) {
    if (void* block = std::malloc(size == 0 ? 1 : size)) return block;
    const std::new_handler handler = std::get_new_handler();
    if (!handler) fail("out of memory");
    handler();
  }
}

void* operator new[](std::size_t size) { return operator new(size); }

// The whole of libstdc++'s functexcept.o, so that the library's own copy is never linked.
namespace std {

void __throw_bad_exception() { fail("bad exception"); }
void __throw_bad_alloc() { fail("out of memory"); }
void __throw_bad_array_new_length() { fail("bad array new length"); }
void __throw_bad_cast() { fail("bad cast"); }
void __throw_bad_typeid() { fail("bad typeid"); }
void __throw_logic_error(const char* what) { fail(what); }
void __throw_domain_error(const char* what) { fail(what); }
void __throw_invalid_argument(const char* what) { fail(what); }
void __throw_length_error(const char* what) { fail(what); }
void __throw_out_of_range(const char* what) { fail(what); }
void __throw_runtime_error(const char* what) { fail(what); }
void __throw_range_error(const char* what) { fail(what); }
void __throw_overflow_error(const char* what) { fail(what); }
void __throw_underflow_error(const char* what) { fail(what); }

/// libstdc++'s own format (%s, %zu and %%), which the printf family reads (c99_formats.c).
void __throw_out_of_range_fmt(const char* format, ...) {
  std::fputs("terminate: ", stderr);
  va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
  std::fputc('\n', stderr);
  std::abort();
}

}  // namespace std
