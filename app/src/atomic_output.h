// SPDX-License-Identifier: BSD-3-Clause
/// Outputs are all or nothing: their names are checked before any work, and a file is written
/// under a temporary name and renamed to its own only once it is complete and closed.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "edgetrack/result.h"

namespace edgetrack_app {

/// The outputs a command was given, as (option, name) pairs: an Error when a name is empty or
/// two of them name the same file (through any spelling: "./a", "b/../a").
std::optional<edgetrack::Error> check_output_names(const std::vector<std::pair<std::string, std::string>>& outputs);

/// Writes `path` by calling `write` on `path + ".partial"`, which is renamed to `path` only when
/// `write` succeeded, and removed otherwise: a failed write leaves no file under `path`.
edgetrack::Result<bool> write_atomically(const std::string& path,
                                         const std::function<edgetrack::Result<bool>(const std::string&)>& write);

/// Makes `dir` ready for a run's overlay frames: created when missing, and emptied of an earlier
/// run's frames (overlayNNNN.png or .ppm, and the `marker` file), so that no stale frame sits
/// beside the new ones; a directory holding anything else is refused rather than mixed into.
std::optional<edgetrack::Error> prepare_overlay_directory(const std::string& dir, const std::string& marker);

}  // namespace edgetrack_app
