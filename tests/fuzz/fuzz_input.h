// SPDX-License-Identifier: BSD-3-Clause
/// What every fuzz target shares: the parsers read files, so the fuzzer's bytes are written to
/// one scratch file per process (with the extension the parser dispatches on) and parsed from
/// there. A parser must return a value or an Error for any bytes; anything else (a crash, a
/// sanitizer report, an input slower than libFuzzer's -timeout) is a finding.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

namespace edgetrack_fuzz {

/// Removes the scratch file when the fuzzer exits.
struct ScratchFile {
  std::string path;
  ~ScratchFile() {
    if (!path.empty()) std::remove(path.c_str());
  }
};

/// Writes `data` to the process's scratch file ending in `extension` and returns its path.
inline std::string scratch_file(const uint8_t* data, size_t size, const char* extension) {
  static ScratchFile scratch{"/tmp/edgetrack-fuzz-" + std::to_string(getpid()) + "." + extension};
  const std::string& path = scratch.path;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) __builtin_trap();  // the fuzzing machine itself is broken
  if (size > 0) std::fwrite(data, 1, size, file);
  std::fclose(file);
  return path;
}

/// A parser's Error must say what went wrong: an empty message would give the user nothing.
template <class R>
void check_result(const R& result) {
  if (!result.ok() && result.error().message.empty()) __builtin_trap();
}

}  // namespace edgetrack_fuzz
