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

}  // namespace edgetrack_app
