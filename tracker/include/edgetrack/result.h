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

/// Prints "edgetrack: value() of a failed result: <the error's text>" on stderr and aborts: what
/// Result::value() does on an error, in every build (with or without exceptions, NDEBUG or not).
[[noreturn]] void stop_on_error_value(const Error& error);

/// Either a value or an Error. `ok()` tells which; `value()` on an error stops the program with
/// the error's text (stop_on_error_value), never hands back an unspecified value.
template <class T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit on purpose
  Result(Error error) : error_(std::move(error)) {}  // NOLINT

  bool ok() const { return value_.has_value(); }
  const T& value() const& { return checked(), *value_; }
  T& value() & { return checked(), *value_; }
  T&& value() && { return checked(), std::move(*value_); }
  const Error& error() const { return error_; }

 private:
  void checked() const {
    if (!value_) stop_on_error_value(error_);
  }
  std::optional<T> value_;
  Error error_;
};

}  // namespace edgetrack
