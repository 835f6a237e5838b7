// SPDX-License-Identifier: BSD-3-Clause
/// Compares a tracking run with its double golden file, with the tolerance of each `real`.
#pragma once

#include <string>

#include "run_sequence.h"

namespace edgetrack_test {

/// Mean and largest camera position distance per frame against tests/tracker/golden/`name`,
/// checked with testlib against the configured type's tolerances.
void compare_with_golden(const std::string& name, const SequenceRun& run);

}  // namespace edgetrack_test
