// SPDX-License-Identifier: BSD-3-Clause
/// The largest frames edgetrack accepts, from image files, options and configuration files
/// alike: sides up to 16384 pixels and at most 64 M pixels (8192 x 8192, or 16384 x 4096),
/// 192 MB as RGB.
#pragma once

namespace edgetrack {

constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 64LL << 20;

}  // namespace edgetrack
