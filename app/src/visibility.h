// SPDX-License-Identifier: BSD-3-Clause
/// `track --visibility soft|gl`: which renderer draws the Edge-ID image the tracker's
/// visibility test reads, the portable one (the tracker's own, every build) or GL through
/// OSMesa as the paper did it (host build).
#pragma once

#include <memory>
#include <string>

#include "edgetrack/pinhole_camera.h"
#include "edgetrack/result.h"
#include "edgetrack/tracker.h"

namespace edgetrack_app {

/// The Edge-ID source `mode` names: nullptr for "soft" (the tracker's portable renderer), a GL
/// source for "gl", an Error for anything else or for "gl" in a build without OSMesa.
edgetrack::Result<std::unique_ptr<edgetrack::EdgeIdSource>> make_edge_id_source(const std::string& mode,
                                                                                const edgetrack::PinholeCamera& camera);

/// Edge-ID through OSMesa for images of the camera's size; an Error without OSMesa.
edgetrack::Result<std::unique_ptr<edgetrack::EdgeIdSource>> make_gl_edge_id_source(
    const edgetrack::PinholeCamera& camera);

}  // namespace edgetrack_app
