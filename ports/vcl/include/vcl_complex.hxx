// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_complex.hxx: upstream's instantiation helper for std::complex, which
/// the standard library now instantiates itself.
#pragma once

#include "vcl_complex.h"

#define VCL_COMPLEX_INSTANTIATE(T) /* std::complex<T> needs no explicit instantiation */
