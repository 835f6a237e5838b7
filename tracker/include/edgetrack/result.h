// SPDX-License-Identifier: BSD-3-Clause
/// Errors as values: what the loaders and the tracker return instead of throwing or exiting.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace edgetrack {

/// Where and why something failed: `file:line: message` when a file position is known.
struct Error {
  std::string file;  ///< empty when no file is involved
  int line = 0;      ///< 1-based line number, 0 when not known
  std::string message;

  std::string text() const;
};

/// Either a value or an Error. `ok()` tells which; `value()` may only be read when ok().
template <class T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit on purpose
  Result(Error error) : error_(std::move(error)) {}  // NOLINT

  bool ok() const { return value_.has_value(); }
  const T& value() const& { return *value_; }
  T& value() & { return *value_; }
  T&& value() && { return std::move(*value_); }
  const Error& error() const { return error_; }

 private:
  std::optional<T> value_;
  Error error_;
};

}  // namespace edgetrack
