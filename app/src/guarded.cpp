// SPDX-License-Identifier: BSD-3-Clause
/// Turning exceptions that escape a command into one line and a failure status.
#include "guarded.h"

#include <cstdlib>
#include <exception>
#include <new>

namespace edgetrack_app {

#if defined(__cpp_exceptions)
int run_guarded(const char* command, int (*run)(int argc, char** argv), int argc, char** argv, std::FILE* err) {
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fprintf(err, "edgetrack %s: out of memory (an input asks for more than this machine has)\n", command);
  } catch (const std::exception& e) {
    std::fprintf(err, "edgetrack %s: internal error: %s\n", command, e.what());
  } catch (...) {
    std::fprintf(err, "edgetrack %s: internal error of an unknown kind\n", command);
  }
  return 1;
}
#else
// Without exceptions (the bare-metal firmware) the one error that escapes is an allocation that
// fails: operator new calls the new handler, which ends the run with the same line.
namespace {
const char* guarded_command = "";
std::FILE* guarded_err = nullptr;

void out_of_memory() {
  std::fprintf(guarded_err, "edgetrack %s: out of memory (an input asks for more than this machine has)\n",
               guarded_command);
  std::exit(1);
}
}  // namespace

int run_guarded(const char* command, int (*run)(int argc, char** argv), int argc, char** argv, std::FILE* err) {
  guarded_command = command;
  guarded_err = err;
  std::set_new_handler(out_of_memory);
  return run(argc, argv);
}
#endif

}  // namespace edgetrack_app
