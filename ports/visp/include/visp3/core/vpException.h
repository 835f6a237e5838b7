// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpException.h: the exception the ported classes throw where
/// upstream throws (a tracker that cannot go on), with upstream's codes and message.
#pragma once

#ifdef _vpException_h_
#error "edgetrack's drop-in visp3/core/vpException.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdarg>
#include <cstdio>
#include <exception>
#include <string>

inline namespace edgetrack_ports {

class vpException : public std::exception {
 public:
  enum generalExceptionEnum {
    memoryAllocationError,
    memoryFreeError,
    functionNotImplementedError,
    ioError,
    cannotUseConstructorError,
    notImplementedError,
    divideByZeroError,
    dimensionError,
    fatalError,
    badValue,
    notInitialized
  };

  vpException(int code, const std::string& message) : code_(code), message_(message) {}
  /// As upstream: the message is `format` filled in printf's way.
  vpException(int code, const char* format, va_list args) : code_(code) { setMessage(format, args); }
  vpException(int code, const char* format, ...) : code_(code) {
    va_list args;
    va_start(args, format);
    setMessage(format, args);
    va_end(args);
  }
  explicit vpException(int code) : code_(code) {}
  int getCode() const { return code_; }
  const std::string& getStringMessage() const { return message_; }
  const char* getMessage() const { return message_.c_str(); }
  const char* what() const noexcept override { return message_.c_str(); }

 protected:
  void setMessage(const char* format, va_list args) {
    va_list count;
    va_copy(count, args);
    const int length = std::vsnprintf(nullptr, 0, format, count);
    va_end(count);
    if (length <= 0) {
      message_.clear();
      return;
    }
    // C++11 strings keep room for the terminating NUL, so vsnprintf writes in place.
    message_.resize(static_cast<std::size_t>(length));
    std::vsnprintf(&message_[0], message_.size() + 1, format, args);
  }

 private:
  int code_;
  std::string message_;
};

}  // inline namespace edgetrack_ports
