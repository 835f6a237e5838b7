// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/core/vpTrackingException.h (its codes follow vpException's in upstream).
#pragma once

#include "visp3/core/vpException.h"

class vpTrackingException : public vpException {
 public:
  enum errorTrackingCodeEnum { featureLostError = 100, notEnoughPointError, initializationError, fatalError };

  vpTrackingException(int code, const std::string& message) : vpException(code, message) {}
};
