// SPDX-License-Identifier: BSD-3-Clause
/// The wireframe model the tracker follows: vertices, faces (kept for hidden-line removal) and the
/// contour edges that are tracked, derived from the faces with a crease-angle rule.
#pragma once

#include <string>
#include <vector>

#include "edgetrack/geometry.h"
#include "edgetrack/result.h"

namespace edgetrack {

/// A planar polygon of the model, its vertices in order, and its triangulation.
struct Face {
  std::vector<int> vertices;  ///< indices into EdgeModel::vertices, in boundary order
  Vec3 normal;                ///< unit normal by the right-hand rule over `vertices`
  std::string name;           ///< the name= parameter of a .cao face, or empty
};

/// One triangle of a face's triangulation; the renderer draws these.
struct Triangle {
  int a = 0;
  int b = 0;
  int c = 0;
  int face = 0;  ///< index into EdgeModel::faces
};

/// A tracked contour edge between two vertices.
struct Edge {
  int a = 0;
  int b = 0;
  int faces[2] = {-1, -1};  ///< the faces it borders (-1: none), for tests and display
};

/// A polygonal surface model together with its tracked edges.
/// Invariant: every index is in range, every face has a triangulation, edges.size() <= kMaxEdges.
struct EdgeModel {
  std::vector<Vec3> vertices;  ///< point_in_model, metres
  std::vector<Face> faces;
  std::vector<Triangle> triangles;
  std::vector<Edge> edges;
  /// True when every face boundary segment is shared by exactly two faces that run it in
  /// opposite directions: a closed, consistently wound surface, whose back faces can never be
  /// seen, so renderers may skip them.
  bool closed = false;
};

/// The most edges a model may have: what the Edge-ID colour code can name (paper, section 3.4).
constexpr int kMaxEdges = 32767;

/// How build_edge_model chooses the tracked edges.
struct EdgeRules {
  /// An edge between two faces is tracked when the angle between their planes exceeds this
  /// (radians). 0.5236 rad = 30 degrees.
  real crease_angle = real(0.5235987755982988);
};

/// The raw content of a model file, before edges are derived.
struct Polygons {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;    ///< vertex indices in boundary order
  std::vector<std::string> face_names;    ///< one per face, possibly empty
  std::vector<std::pair<int, int>> lines;  ///< free-standing segments, tracked as they are
};

/// Triangulates the faces (ear clipping, so non-convex faces work) and derives the tracked edges:
/// an edge bordered by one face (a boundary) is tracked; an edge shared by two faces is tracked
/// when the angle between them exceeds rules.crease_angle (so triangulation diagonals of flat
/// faces are not); an edge shared by more than two faces is tracked; free lines are tracked.
/// `source` names the model in error messages.
Result<EdgeModel> build_edge_model(const Polygons& polygons, const EdgeRules& rules, const std::string& source);

}  // namespace edgetrack
