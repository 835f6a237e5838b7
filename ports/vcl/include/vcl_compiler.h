// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_compiler.h (generated upstream from vcl_compiler.h.in): the VXL version
/// this port follows, the configuration switches upstream code tests, and VXL_DEPRECATED.
#pragma once

// The upstream release whose headers this port follows.
#define VXL_VERSION 5.5.2
#define VXL_VERSION_MAJOR 5
#define VXL_VERSION_MINOR 5
#define VXL_VERSION_PATCH 2
#define VXL_VERSION_TWEAK 0
#define VXL_COMPILED_CXX_STANDARD_VERSION 201703L

// Upstream's build switches, at upstream's defaults.
#define VXL_LEGACY_FUTURE_REMOVE 0
#define VXL_RUN_FAILING_TESTS 0
#define VXL_USE_HISTORICAL_IMPLICIT_CONVERSIONS 0
#define VXL_USE_HISTORICAL_PROTECTED_IVARS 0

#define VCL_COMMA ,
#if defined(NDEBUG)
#define VXL_USED_IN_DEBUG(x)
#else
#define VXL_USED_IN_DEBUG(x) x
#endif

#ifndef VXL_DEPRECATED
#define VXL_DEPRECATED [[deprecated]]
#define VXL_DEPRECATED_MSG(MSG) [[deprecated(MSG)]]
#endif
#define VXL_DELETED_FUNCTION = delete

// The C++98-era spellings upstream still accepts.
#define VXL_CONSTEXPR_FUNC constexpr
#define VXL_CONSTEXPR_VAR constexpr
#define VXL_FULLCXX11SUPPORT 1
#define VCL_STATIC_CONST_INIT_FLOAT_DECL(x) = x
#define VCL_STATIC_CONST_INIT_FLOAT_DEFN(x)

#ifdef VNL_CONFIG_LEGACY_METHODS
#include "vcl_legacy_aliases.h"
#endif
