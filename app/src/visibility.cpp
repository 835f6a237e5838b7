// SPDX-License-Identifier: BSD-3-Clause
/// Picks the Edge-ID renderer named by `track --visibility`.
#include "visibility.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

Result<std::unique_ptr<edgetrack::EdgeIdSource>> make_edge_id_source(const std::string& mode,
                                                                     const edgetrack::PinholeCamera& camera) {
  if (mode == "soft") return std::unique_ptr<edgetrack::EdgeIdSource>();
  if (mode == "gl") return make_gl_edge_id_source(camera);
  return Error{"", 0, "--visibility must be 'soft' (portable Edge-ID) or 'gl' (OSMesa), not '" + mode + "'"};
}

}  // namespace edgetrack_app
