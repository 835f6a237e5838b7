// SPDX-License-Identifier: BSD-3-Clause
/// The pose perturbation in which the pose's covariance (pose_uncertainty.cpp) and the drift
/// check's first-order gate (excluded_pull.cpp) measure a pose, and how both whiten a gradient
/// there: shared by both sources, built
/// with different options on the microcontroller (toolchains/mcu/hot_sources.cmake).
#pragma once

#include <limits>

#include "edgetrack/edge_model.h"
#include "edgetrack/se3.h"
#include "real/real.h"

namespace edgetrack {
namespace pose_perturbation {

constexpr int kDof = 6;

/// The pose perturbation the covariance is over: a translation v (mm) and a turn w about the
/// model's centre, scaled by the model's radius (mm at its farthest vertex), so that every
/// column of the Jacobian is pixels per millimetre of some point's motion: balanced columns keep
/// the fixed-point Cholesky well within range.
struct Perturbation {
  Vec3 centre;          ///< model frame, metres
  real radius_mm{1};
};

/// The model's centre (the mean of its overlay points) and radius.
Perturbation perturbation_of(const EdgeModel& model);

/// Cholesky of the information matrix (turns already scaled) in place, and 1 / its diagonal:
/// false where a direction is one the matches do not see.
bool factor_information(real (&information)[kDof][kDof], real (&inv_diagonal)[kDof]);

/// z = L^-1 g by forward substitution, for L the lower triangle factor_information leaves and
/// `inv_diagonal` 1 / its diagonal: g whitened by the covariance L^-T L^-1. False, with z filled
/// only so far, once a component passes `cap` in magnitude.
bool forward_substitute(const real (&l)[kDof][kDof], const real (&inv_diagonal)[kDof], const real (&g)[kDof],
                        real (&z)[kDof], const real& cap = std::numeric_limits<real>::max());

/// A whitened component beyond this is a direction no match sees; it also keeps the squares
/// within S40.23's range.
inline const real kWhitenedCap = real(1e4);

}  // namespace pose_perturbation
}  // namespace edgetrack
