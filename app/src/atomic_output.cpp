// SPDX-License-Identifier: BSD-3-Clause
/// Output names checked up front, and files renamed into place once complete.
#include "atomic_output.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

std::optional<Error> check_output_names(const std::vector<std::pair<std::string, std::string>>& outputs) {
  std::vector<std::string> files;
  for (const auto& [option, name] : outputs) {
    if (name.empty()) return Error{"", 0, option + " names no file (an empty name)"};
    std::error_code error;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(std::filesystem::absolute(name, error), error);
    files.push_back(error ? name : resolved.string());
  }
  for (size_t i = 0; i < outputs.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (files[i] == files[j])
        return Error{outputs[i].second, 0, outputs[j].first + " and " + outputs[i].first +
                                               " name the same file: one would replace the other"};
  return std::nullopt;
}

Result<bool> write_atomically(const std::string& path, const std::function<Result<bool>(const std::string&)>& write) {
  const std::string partial = path + ".partial";
  Result<bool> written = write(partial);
  if (!written.ok()) {
    std::remove(partial.c_str());
    Error error = written.error();
    if (error.file == partial) error.file = path;
    return error;
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    std::remove(partial.c_str());
    return Error{path, 0, "cannot rename " + partial + " to it"};
  }
  return true;
}

namespace {

/// "overlay0042.png": a frame `track --overlay` writes.
bool is_overlay_frame(const std::string& name) {
  const std::string prefix = "overlay";
  if (name.size() < prefix.size() + 4 + 4 || name.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string ext = name.substr(name.size() - 4);
  if (ext != ".png" && ext != ".ppm") return false;
  for (size_t i = prefix.size(); i < name.size() - 4; ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

}  // namespace

std::optional<Error> prepare_overlay_directory(const std::string& dir, const std::string& marker) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) return Error{dir, 0, "cannot create the directory: " + error.message()};
  std::vector<fs::path> ours;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name != marker && !is_overlay_frame(name))
      return Error{dir, 0, "holds " + name + ", which is not an overlay frame: give an empty or new directory"};
    ours.push_back(it->path());
  }
  if (error) return Error{dir, 0, "cannot list the directory: " + error.message()};
  for (const fs::path& file : ours) {
    fs::remove(file, error);
    if (error) return Error{file.string(), 0, "cannot remove an earlier run's frame: " + error.message()};
  }
  return std::nullopt;
}

}  // namespace edgetrack_app
