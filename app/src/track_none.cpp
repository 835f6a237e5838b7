// SPDX-License-Identifier: BSD-3-Clause
/// The application in a checkout without the tracker's frame loop (edgetrack/tracker.h): it
/// has no `track` command; synth, eval and edgeid work as usual.
#include "commands.h"

namespace edgetrack_app {

std::vector<Command> tracking_commands() { return {}; }

}  // namespace edgetrack_app
