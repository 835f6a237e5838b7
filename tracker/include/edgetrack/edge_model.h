// SPDX-License-Identifier: BSD-3-Clause
/// The wireframe model the tracker follows: vertices, faces (kept for hidden-line removal), the
/// contour edges that are tracked, derived from the faces with a crease-angle rule, and the
/// curved primitives (cylinders, circles) whose tracked outline depends on the pose.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "edgetrack/geometry.h"
#include "edgetrack/result.h"

namespace edgetrack {

/// The per-primitive parameters of a .cao record, stored for the level-of-detail filter. Unset
/// values take the general setting (ViSP: the XML's <lod> block, else useLod false, 50 px,
/// 2500 px^2).
struct PrimitiveAttributes {
  std::string name;                      ///< name=, or empty
  std::optional<bool> use_lod;           ///< useLod=
  std::optional<real> min_line_length;   ///< minLineLengthThreshold= (pixels): lines, cylinders
  std::optional<real> min_polygon_area;  ///< minPolygonAreaThreshold= (pixels^2): faces, circles
};

/// A planar polygon of the model, its vertices in order, and its triangulation.
struct Face {
  std::vector<int> vertices;  ///< indices into EdgeModel::vertices, in boundary order
  Vec3 normal;                ///< unit normal by the right-hand rule over `vertices`
  PrimitiveAttributes attributes;
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
  PrimitiveAttributes attributes;  ///< a free-standing .cao line's own; face edges use their faces'
};

/// The side of a cylinder (ViSP's vpMbtDistanceCylinder): tracked along its two silhouette
/// generator lines seen from the current pose (contours.h).
struct Cylinder {
  Vec3 axis_a;  ///< the axis' end points, model frame, metres: the side runs from one to the other
  Vec3 axis_b;
  real radius{0};
  PrimitiveAttributes attributes;
};

/// A circle (ViSP's vpMbtDistanceCircle), tracked along its projected ellipse.
struct Circle {
  Vec3 centre;
  Vec3 normal;  ///< unit normal of its plane
  real radius{0};
  /// kCircleSides + 1 points evenly around the circle (the last repeats the first), model frame:
  /// the polygon Edge-ID draws and sampling walks.
  std::vector<Vec3> rim;
  int cap_of = -1;  ///< the cylinder this circle closes (same centre, radius and axis), or -1
  PrimitiveAttributes attributes;
};

/// One triangle of a cylinder's tessellated side (inscribed), for occlusion and rendering.
struct SurfaceTriangle {
  Vec3 corners[3];  ///< model frame
  Vec3 normal;      ///< outward unit normal of the facet
  int cylinder = 0;
  int points[3] = {0, 0, 0};  ///< the corners' indices in EdgeModel::cylinder_points
};

/// A polygonal surface model together with its tracked edges and curved primitives.
/// Tracked primitives are numbered (ControlPoint::edge, the Edge-ID code): edges first, then two
/// silhouette lines per cylinder, then one per circle (the functions below).
/// Invariant: every index is in range, every face has a triangulation, primitive_count() <= kMaxEdges.
struct EdgeModel {
  std::vector<Vec3> vertices;  ///< point_in_model, metres
  std::vector<Face> faces;
  std::vector<Triangle> triangles;
  std::vector<Edge> edges;
  std::vector<Cylinder> cylinders;
  std::vector<Circle> circles;
  std::vector<SurfaceTriangle> cylinder_surface;  ///< every cylinder's side, kCylinderSides facets each
  /// The corners of cylinder_surface once each (a renderer moves and projects each once a frame):
  /// per cylinder, kCylinderSides + 1 points around its base rim, then as many around its top.
  std::vector<Vec3> cylinder_points;
  /// True when every face boundary segment is shared by exactly two faces that run it in
  /// opposite directions: a closed, consistently wound surface, whose back faces can never be
  /// seen, so renderers may skip them.
  bool closed = false;
};

/// The most tracked primitives a model may have: what the Edge-ID colour code can name (paper,
/// section 3.4), per-frame cylinder silhouettes and circles included.
constexpr int kMaxEdges = 32767;
/// Facets of a tessellated cylinder side and sides of a circle's polygon: at 64 the polygon
/// lies within 0.12 % of the radius of the true curve (0.05 mm for a 40 mm radius).
constexpr int kCylinderSides = 64;
constexpr int kCircleSides = 64;

/// Tracked primitives: edges, two silhouette lines per cylinder, one per circle.
inline int primitive_count(const EdgeModel& model) {
  return static_cast<int>(model.edges.size() + 2 * model.cylinders.size() + model.circles.size());
}
/// The primitive number of silhouette line `side` (0 or 1) of cylinder `cylinder`.
inline int cylinder_primitive(const EdgeModel& model, int cylinder, int side) {
  return static_cast<int>(model.edges.size()) + 2 * cylinder + side;
}
/// The primitive number of circle `circle`.
inline int circle_primitive(const EdgeModel& model, int circle) {
  return static_cast<int>(model.edges.size() + 2 * model.cylinders.size()) + circle;
}

/// How build_edge_model chooses the tracked edges.
struct EdgeRules {
  /// An edge between two faces is tracked when the angle between their planes exceeds this
  /// (radians). 0.5236 rad = 30 degrees.
  real crease_angle = real(0.5235987755982988);
};

/// A cylinder or circle as a model file gives it: vertex indices and a radius.
struct CylinderRecord {
  int axis_a = 0;
  int axis_b = 0;
  real radius{0};
  PrimitiveAttributes attributes;
};
struct CircleRecord {
  int centre = 0;
  int plane_a = 0;  ///< two more points of the circle's plane (the first also sets where the rim starts)
  int plane_b = 0;
  real radius{0};
  PrimitiveAttributes attributes;
};

/// The raw content of a model file, before edges are derived.
struct Polygons {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;             ///< vertex indices in boundary order
  std::vector<PrimitiveAttributes> face_attributes;  ///< one per face (or none)
  std::vector<std::pair<int, int>> lines;          ///< free-standing segments, tracked as they are
  std::vector<PrimitiveAttributes> line_attributes;  ///< one per line (or none)
  std::vector<CylinderRecord> cylinders;
  std::vector<CircleRecord> circles;
};

/// Triangulates the faces (ear clipping, so non-convex faces work) and derives the tracked edges:
/// an edge bordered by one face (a boundary) is tracked; an edge shared by two faces is tracked
/// when the angle between them exceeds rules.crease_angle (so triangulation diagonals of flat
/// faces are not); an edge shared by more than two faces is tracked; free lines are tracked.
/// Cylinders get their tessellated side, circles their plane, rim and cap_of. `source` names the
/// model in error messages.
Result<EdgeModel> build_edge_model(const Polygons& polygons, const EdgeRules& rules, const std::string& source);

}  // namespace edgetrack
