// SPDX-License-Identifier: BSD-3-Clause
/// Builds without ViSP's mbt module (the ARM target, or a host without libvisp-dev) have no
/// `edgetrack compare`.
#include "commands.h"

namespace edgetrack_app {

std::vector<Command> comparison_commands() { return {}; }

}  // namespace edgetrack_app
