// SPDX-License-Identifier: BSD-3-Clause
/// Reading an input file whole, after checking that it is a regular file of bounded size: a
/// directory, a device (/dev/zero), a FIFO or a file too large to be what it claims is refused
/// with a message naming it, before anything is allocated for its contents.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "edgetrack/result.h"

namespace edgetrack {

/// Text inputs (models, poses, XML, points, CSV): larger than this is not a model or a list.
constexpr std::size_t kMaxTextFileBytes = std::size_t(64) << 20;
/// Image inputs: a 16384 x 4096 PPM with 16-bit samples, or any ASCII frame of the largest
/// allowed size at under 4 characters per sample.
constexpr std::size_t kMaxImageFileBytes = std::size_t(512) << 20;

/// The bytes of `path`, or an Error naming it: missing, not a regular file, over `max_bytes`,
/// or unreadable.
Result<std::vector<uint8_t>> read_input_file(const std::string& path, std::size_t max_bytes);

/// The same as text.
Result<std::string> read_input_text(const std::string& path, std::size_t max_bytes = kMaxTextFileBytes);

/// What an input file is before it is read: its size, and one name for it whatever path
/// reaches it (symbolic links, "." and ".." resolved), so that a reader of includes recognises a
/// file it has already read.
struct InputFileIdentity {
  std::string canonical_path;
  std::size_t size = 0;
};

/// The identity of `path`, or the same Error read_input_file would give for it.
Result<InputFileIdentity> input_file_identity(const std::string& path, std::size_t max_bytes = kMaxTextFileBytes);

}  // namespace edgetrack
