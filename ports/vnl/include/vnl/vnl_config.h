// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_config.h (generated upstream from vnl_config.h.in): vnl's build
/// switches, at the values this port is built with.
#pragma once

/// Bounds checks on element access: off, as upstream's default.
#define VNL_CONFIG_CHECK_BOUNDS 0
/// The deprecated pre-C++11 methods: not provided.
#define VNL_CONFIG_LEGACY_METHODS 0
/// No function-local static state in vnl's numerics.
#define VNL_CONFIG_THREAD_SAFE 1
/// x86 SSE2 rounding: there is no SSE on the PXA270.
#define VNL_CONFIG_ENABLE_SSE2_ROUNDING 0
#define VNL_CONFIG_ENABLE_SSE2 0
