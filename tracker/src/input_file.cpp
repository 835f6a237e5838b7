// SPDX-License-Identifier: BSD-3-Clause
/// Bounded reading of input files.
#include "edgetrack/input_file.h"

#include <cstdio>

#if defined(EDGETRACK_NO_PATH_RESOLUTION)
#include <sys/stat.h>
#else
#include <filesystem>
#include <system_error>
#endif

namespace edgetrack {
namespace {

/// The refusal of a file of `size` bytes when more than max_bytes.
Result<std::size_t> within(const std::string& path, std::uintmax_t size, std::size_t max_bytes) {
  if (size > max_bytes)
    return Error{path, 0, "is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
                              " an input of this kind may have"};
  return static_cast<std::size_t>(size);
}

#if defined(EDGETRACK_NO_PATH_RESOLUTION)
// The bare-metal firmware's files come by semihosting, which has no directories or links to
// resolve; stat() and a lexical normal form stand in for std::filesystem, whose paths, errors and
// streams would be most of a microcontroller's flash.

Result<std::size_t> checked_size(const std::string& path, std::size_t max_bytes) {
  struct stat status;
  if (stat(path.c_str(), &status) != 0) return Error{path, 0, "no such file"};
  if (S_ISDIR(status.st_mode)) return Error{path, 0, "is a directory, not a file"};
  if (!S_ISREG(status.st_mode)) return Error{path, 0, "is not a regular file (a device or a pipe?)"};
  return within(path, static_cast<std::uintmax_t>(status.st_size), max_bytes);
}

/// `path` with empty and "." elements taken out and each "name/.." folded, as
/// std::filesystem::path::lexically_normal does for a file's path.
std::string lexically_normal(const std::string& path) {
  const bool absolute = !path.empty() && path[0] == '/';
  std::vector<std::string> names;
  for (size_t start = 0; start <= path.size();) {
    size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    const std::string name = path.substr(start, end - start);
    start = end + 1;
    if (name.empty() || name == ".") continue;
    if (name == ".." && !names.empty() && names.back() != "..") {
      names.pop_back();
    } else if (!(name == ".." && absolute && names.empty())) {
      names.push_back(name);
    }
  }
  std::string normal = absolute ? "/" : "";
  for (size_t i = 0; i < names.size(); ++i) normal += (i > 0 ? "/" : "") + names[i];
  return normal.empty() ? "." : normal;
}
#else
/// An Error when `path` is not a regular file of at most max_bytes; its size otherwise.
Result<std::size_t> checked_size(const std::string& path, std::size_t max_bytes) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) {
    const std::string why = error && error != std::errc::no_such_file_or_directory ? ": " + error.message() : "";
    return Error{path, 0, "no such file" + why};
  }
  if (std::filesystem::is_directory(status)) return Error{path, 0, "is a directory, not a file"};
  if (!std::filesystem::is_regular_file(status)) return Error{path, 0, "is not a regular file (a device or a pipe?)"};
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return Error{path, 0, "cannot read its size: " + error.message()};
  return within(path, size, max_bytes);
}
#endif

template <class Bytes>
Result<Bytes> read_whole(const std::string& path, std::size_t max_bytes) {
  auto size = checked_size(path, max_bytes);
  if (!size.ok()) return size.error();
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return Error{path, 0, "cannot open the file"};
  Bytes bytes(size.value(), 0);
  const std::size_t got = bytes.empty() ? 0 : std::fread(&bytes[0], 1, bytes.size(), file);
  // One more byte read shows a file that grew after its size was taken.
  const bool grew = std::fgetc(file) != EOF;
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed || got != bytes.size()) return Error{path, 0, "read failed"};
  if (grew) return Error{path, 0, "the file changed while it was read"};
  return bytes;
}

}  // namespace

Result<std::vector<uint8_t>> read_input_file(const std::string& path, std::size_t max_bytes) {
  return read_whole<std::vector<uint8_t>>(path, max_bytes);
}

Result<std::string> read_input_text(const std::string& path, std::size_t max_bytes) {
  return read_whole<std::string>(path, max_bytes);
}

Result<InputFileIdentity> input_file_identity(const std::string& path, std::size_t max_bytes) {
  auto size = checked_size(path, max_bytes);
  if (!size.ok()) return size.error();
#if defined(EDGETRACK_NO_PATH_RESOLUTION)
  // A file is known by its path with "." and ".." taken out.
  return InputFileIdentity{lexically_normal(path), size.value()};
#else
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::canonical(path, error);
  if (error) return Error{path, 0, "cannot resolve its path: " + error.message()};
  return InputFileIdentity{canonical.string(), size.value()};
#endif
}

}  // namespace edgetrack
