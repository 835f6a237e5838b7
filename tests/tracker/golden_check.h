// SPDX-License-Identifier: BSD-3-Clause
/// Compares a tracking run with its double golden file, with the tolerance of each `real`.
#pragma once

#include <string>

#include "run_sequence.h"

namespace edgetrack_test {

/// Mean and largest camera position distance per frame against tests/tracker/golden/`name`,
/// checked with testlib against the configured type's tolerances; and, when the run took the
/// golden run's steps (not another solver's), its full poses (compare_poses_with_golden).
void compare_with_golden(const std::string& name, const SequenceRun& run, bool golden_steps = true);

/// In the double builds (host, QEMU on any ARM): every frame's pose within 1e-9 m and 1e-9 rad
/// of the host double run in tests/tracker/golden/`poses_name`. Other types: nothing to check.
void compare_poses_with_golden(const std::string& poses_name, const SequenceRun& run);

}  // namespace edgetrack_test
