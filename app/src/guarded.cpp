// SPDX-License-Identifier: BSD-3-Clause
/// Turning exceptions that escape a command into one line and a failure status.
#include "guarded.h"

#include <exception>
#include <new>

namespace edgetrack_app {

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

}  // namespace edgetrack_app
