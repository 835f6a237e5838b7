// SPDX-License-Identifier: BSD-3-Clause
/// The `edgetrack` executable: dispatches to its subcommands.
#include <cstdio>
#include <cstring>

#include "commands.h"
#include "real/real_config.h"
#include "guarded.h"

int main(int argc, char** argv) {
  using edgetrack_app::Command;
  std::vector<Command> commands = edgetrack_app::tracking_commands();
  for (const Command& c : edgetrack_app::detection_commands()) commands.push_back(c);
  commands.push_back(
      {"eval", "compare tracked poses with ground truth; plots like the paper's Fig. 4 and 5", edgetrack_app::eval_main});
  for (const Command& c : edgetrack_app::host_commands()) commands.push_back(c);
  for (const Command& c : edgetrack_app::comparison_commands()) commands.push_back(c);
  if (argc >= 2 && std::strcmp(argv[1], "--version") == 0) {
    std::printf("edgetrack %s (real = %s)\n", EDGETRACK_VERSION, EDGETRACK_REAL_NAME);
    return 0;
  }
  if (argc >= 2) {
    for (const Command& c : commands)
      if (std::strcmp(argv[1], c.name) == 0) return edgetrack_app::run_guarded(c.name, c.run, argc - 1, argv + 1);
  }
  const bool asked = argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "help") == 0);
  std::FILE* out = asked ? stdout : stderr;
  if (argc >= 2 && !asked) std::fprintf(stderr, "edgetrack: unknown command '%s'\n", argv[1]);
  std::fprintf(out, "usage: edgetrack COMMAND [options]   (edgetrack COMMAND --help for its options)\n"
                    "       edgetrack --version\n");
  for (const Command& c : commands) std::fprintf(out, "  %-9s %s\n", c.name, c.summary);
  return asked ? 0 : 2;
}
