// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpException.h: the exception the ported classes throw where
/// upstream throws (a tracker that cannot go on), with upstream's codes and message.
#pragma once

#ifdef _vpException_h_
#error "edgetrack's drop-in visp3/core/vpException.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

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
  int getCode() const { return code_; }
  const std::string& getStringMessage() const { return message_; }
  const char* getMessage() const { return message_.c_str(); }
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  int code_;
  std::string message_;
};

}  // inline namespace edgetrack_ports
