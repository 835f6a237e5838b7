// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_identity_3x3.h: the 3x3 identity as a vnl_double_3x3.
#pragma once

#include "vnl/vnl_double_3x3.h"

struct vnl_identity_3x3 : public vnl_double_3x3 {
  vnl_identity_3x3() { set_identity(); }
};
