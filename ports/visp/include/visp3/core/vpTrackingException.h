// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpTrackingException.h (its codes follow vpException's in upstream).
#pragma once

#ifdef _vpTrackingException_H
#error "edgetrack's drop-in visp3/core/vpTrackingException.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "visp3/core/vpException.h"

inline namespace edgetrack_ports {

class vpTrackingException : public vpException {
 public:
  enum errorTrackingCodeEnum { featureLostError = 100, notEnoughPointError, initializationError, fatalError };

  vpTrackingException(int code, const std::string& message) : vpException(code, message) {}
  vpTrackingException(int code, const char* format, ...) : vpException(code) {
    va_list args;
    va_start(args, format);
    setMessage(format, args);
    va_end(args);
  }
  explicit vpTrackingException(int code) : vpException(code) {}
};

}  // inline namespace edgetrack_ports
