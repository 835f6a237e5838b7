// SPDX-License-Identifier: BSD-3-Clause
/// Pi and the degree conversions, named once (set-up constants: convert with real(...)).
#pragma once

namespace edgetrack {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180;
constexpr double kDegreesPerRadian = 180 / kPi;

}  // namespace edgetrack
