// SPDX-License-Identifier: BSD-3-Clause
/// The last line of defence of the executable: whatever a command throws becomes one line on
/// stderr and exit status 1, so no exception (std::bad_alloc, std::filesystem_error, ...)
/// leaves main as an abort with a core dump.
#pragma once

#include <cstdio>

namespace edgetrack_app {

/// Runs `run(argc, argv)` and returns its exit status; if it throws, prints
/// "edgetrack <command>: internal error: <what>" to `err` and returns 1.
int run_guarded(const char* command, int (*run)(int argc, char** argv), int argc, char** argv,
                std::FILE* err = stderr);

}  // namespace edgetrack_app
