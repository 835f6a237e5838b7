// SPDX-License-Identifier: BSD-3-Clause
/// Model files: ViSP's .cao and Wavefront .obj, read into an EdgeModel (docs/FORMATS.md).
#pragma once

#include <string>

#include "edgetrack/edge_model.h"
#include "edgetrack/result.h"

namespace edgetrack {

/// Reads a ViSP .cao model (V1 or V2): points, lines, faces from lines, faces from points.
/// Cylinders, circles and load() includes are refused with an error naming the file and line.
Result<Polygons> read_cao(const std::string& path);

/// Reads the v and f records of a Wavefront .obj (f accepts v, v/vt, v//vn, v/vt/vn and negative
/// indices); other records are skipped.
Result<Polygons> read_obj(const std::string& path);

/// Reads a .cao or .obj by its extension and builds the edge model.
Result<EdgeModel> load_model(const std::string& path, const EdgeRules& rules = EdgeRules{});

}  // namespace edgetrack
