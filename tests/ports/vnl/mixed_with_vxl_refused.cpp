// SPDX-License-Identifier: BSD-3-Clause
/// Must not compile: VXL's own vnl_vector.h (which opens with `#ifndef vnl_vector_h_` /
/// `#define vnl_vector_h_`; VXL is not installed here, so its guard stands for it), then our
/// drop-in of the same header in one translation unit. The test expects our header's #error.
#define vnl_vector_h_

#include "vnl/vnl_vector.h"
