// SPDX-License-Identifier: BSD-3-Clause
/// Moving-edge parameters from the <ecm> block of a ViSP XML configuration (as in mbt/cube.xml):
/// mask size and number, tracking range, edge threshold, mu1/mu2 and sample step, and how they
/// become the tracker's parameters.
#pragma once

#include <string>

#include "edgetrack/result.h"
#include "edgetrack/tracker.h"

namespace edgetrack_app {

/// The values found; a field not present in the file keeps -1.
struct EcmConfig {
  int mask_size = -1;
  int mask_number = -1;
  int range = -1;
  double threshold = -1;
  double mu1 = -1;
  double mu2 = -1;
  double sample_step = -1;
};

/// Reads the first <ecm> element; an Error names the file and line of a bad value, or says
/// that there is no <ecm> block.
edgetrack::Result<EcmConfig> read_ecm_config(const std::string& path);

/// Sets the values present in `config` on `params`: threshold, mask size and number and range
/// on params.me, the sample step on params.sampling.step. mu1/mu2 have no meaning here (sites are
/// re-sampled every frame, so there is no previous contrast to test them on) and are left out.
/// A value outside what the tracker can use is an Error naming `path`.
edgetrack::Result<bool> apply_ecm_config(const EcmConfig& config, const std::string& path,
                                         edgetrack::TrackerParams& params);

}  // namespace edgetrack_app
