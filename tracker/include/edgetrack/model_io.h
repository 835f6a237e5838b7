// SPDX-License-Identifier: BSD-3-Clause
/// Model files: ViSP's .cao and Wavefront .obj, read into an EdgeModel (docs/FORMATS.md).
#pragma once

#include <optional>
#include <string>

#include "edgetrack/edge_model.h"
#include "edgetrack/input_file.h"
#include "edgetrack/result.h"

namespace edgetrack {

/// Reads a ViSP .cao model (V1 or V2) as vpMbTracker::loadCAOModel does: load("part.cao",
/// t=[..], tu=[..]) includes (relative to the including file, each part's indices local to it,
/// its points placed by t and tu), points, lines, faces from lines, faces from points,
/// cylinders, circles and their name=, useLod=, minLineLengthThreshold= and
/// minPolygonAreaThreshold= parameters. Errors name the file and line; a refused include
/// also shows the chain of load() lines (file:line of each; a long chain as its first and last
/// few links and the count between).
///
/// Includes are read without recursion, each file once: a file is known by its canonical path
/// (input_file_identity), so a cycle through other names (symbolic links, "..") is an error and
/// a repeat is skipped as ViSP skips a file already in the model.
struct CaoIncludeLimits {
  int max_depth = 4096;                      ///< files on one include chain, the top file included
  int max_files = 16384;                     ///< distinct files in one model
  std::size_t max_bytes = kMaxTextFileBytes;  ///< all of them together: a model is one text input
};
Result<Polygons> read_cao(const std::string& path, const CaoIncludeLimits& limits = CaoIncludeLimits{});
/// The same for a model held in memory (`text`, the file's content; `name` stands for the file
/// in errors). A relative load() path resolves against `base_directory`; with none given, it is
/// refused at its line (an absolute one is read either way).
Result<Polygons> read_cao_text(const std::string& text, const std::string& name,
                               const std::optional<std::string>& base_directory = std::nullopt,
                               const CaoIncludeLimits& limits = CaoIncludeLimits{});

/// Reads the v and f records of a Wavefront .obj (f accepts v, v/vt, v//vn, v/vt/vn and negative
/// indices); other records are skipped.
Result<Polygons> read_obj(const std::string& path);
/// The same for an .obj held in memory; `name` stands for the file in errors.
Result<Polygons> read_obj_text(const std::string& text, const std::string& name);

/// Reads a .cao or .obj by its extension and builds the edge model.
Result<EdgeModel> load_model(const std::string& path, const EdgeRules& rules = EdgeRules{});
/// The same for a model held in memory: `name`'s extension (.cao or .obj) gives the format and
/// `name` stands for the file in errors; `base_directory` as read_cao_text's.
Result<EdgeModel> load_model_text(const std::string& text, const std::string& name,
                                  const std::optional<std::string>& base_directory = std::nullopt,
                                  const EdgeRules& rules = EdgeRules{});

}  // namespace edgetrack
