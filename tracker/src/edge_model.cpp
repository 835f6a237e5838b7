// SPDX-License-Identifier: BSD-3-Clause
/// Face normals, ear-clipping triangulation and the crease-angle rule that picks tracked edges.
#include "edgetrack/edge_model.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>

#include "edgetrack/angles.h"

namespace edgetrack {
namespace {

/// The face's vertices relative to its first one, divided by the largest coordinate difference,
/// so that products stay well inside the range and resolution of every `real`.
std::vector<Vec3> normalized_corners(const std::vector<Vec3>& vertices, const std::vector<int>& face) {
  using std::fabs;
  const Vec3 origin = vertices[face[0]];
  real extent(0);
  for (int index : face) {
    const Vec3 d = vertices[index] - origin;
    if (fabs(d.x) > extent) extent = fabs(d.x);
    if (fabs(d.y) > extent) extent = fabs(d.y);
    if (fabs(d.z) > extent) extent = fabs(d.z);
  }
  std::vector<Vec3> corners;
  corners.reserve(face.size());
  for (int index : face) {
    const Vec3 d = vertices[index] - origin;
    corners.push_back(extent > real(0) ? Vec3{d.x / extent, d.y / extent, d.z / extent} : d);
  }
  return corners;
}

/// Newell's method: the polygon's area-weighted normal, robust for non-convex polygons.
Vec3 newell_normal(const std::vector<Vec3>& corners) {
  Vec3 n;
  const size_t count = corners.size();
  for (size_t i = 0; i < count; ++i) {
    const Vec3& p = corners[i];
    const Vec3& q = corners[(i + 1) % count];
    n.x = n.x + (p.y - q.y) * (p.z + q.z);
    n.y = n.y + (p.z - q.z) * (p.x + q.x);
    n.z = n.z + (p.x - q.x) * (p.y + q.y);
  }
  return n;
}

real cross2(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// True when p lies inside or on the counter-clockwise triangle abc.
bool inside_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross2(a, b, p) >= real(0) && cross2(b, c, p) >= real(0) && cross2(c, a, p) >= real(0);
}

/// Ear clipping over the face projected on the plane its normal is most aligned with, turned so
/// that the polygon runs counter-clockwise. Returns false when the polygon is not simple.
bool triangulate(const std::vector<Vec3>& corners, const Vec3& normal, std::vector<std::array<int, 3>>& out) {
  using std::fabs;
  const real ax = fabs(normal.x), ay = fabs(normal.y), az = fabs(normal.z);
  std::vector<Vec2> flat;
  flat.reserve(corners.size());
  for (const Vec3& c : corners) {
    if (az >= ax && az >= ay)
      flat.push_back(normal.z > real(0) ? Vec2{c.x, c.y} : Vec2{c.y, c.x});
    else if (ay >= ax)
      flat.push_back(normal.y > real(0) ? Vec2{c.z, c.x} : Vec2{c.x, c.z});
    else
      flat.push_back(normal.x > real(0) ? Vec2{c.y, c.z} : Vec2{c.z, c.y});
  }
  std::vector<int> remaining(corners.size());
  for (size_t i = 0; i < remaining.size(); ++i) remaining[i] = static_cast<int>(i);
  while (remaining.size() > 3) {
    const size_t count = remaining.size();
    bool clipped = false;
    for (size_t i = 0; i < count && !clipped; ++i) {
      const int prev = remaining[(i + count - 1) % count];
      const int cur = remaining[i];
      const int next = remaining[(i + 1) % count];
      if (cross2(flat[prev], flat[cur], flat[next]) <= real(0)) continue;  // reflex or flat corner
      bool empty = true;
      for (int other : remaining) {
        if (other == prev || other == cur || other == next) continue;
        if (inside_triangle(flat[other], flat[prev], flat[cur], flat[next])) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.push_back({prev, cur, next});
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return false;
  }
  out.push_back({remaining[0], remaining[1], remaining[2]});
  return true;
}

/// A point at angle `angle` on the circle of `radius` around `centre` spanned by unit u and v.
Vec3 on_circle(const Vec3& centre, const Vec3& u, const Vec3& v, const real& radius, const real& angle) {
  using std::cos;
  using std::sin;
  return centre + (radius * cos(angle)) * u + (radius * sin(angle)) * v;
}

/// A unit vector perpendicular to the unit vector n.
Vec3 perpendicular(const Vec3& n) {
  using std::fabs;
  const Vec3 helper = fabs(n.x) < real(0.9) ? Vec3{real(1), real(0), real(0)} : Vec3{real(0), real(1), real(0)};
  return normalized(cross(helper, n));
}

/// Checks the cylinders, tessellates their sides (inscribed, kCylinderSides facets) and adds them.
Result<bool> add_cylinders(const Polygons& polygons, const std::string& source, EdgeModel& model) {
  const int vertex_count = static_cast<int>(model.vertices.size());
  const real pi = real(kPi);
  for (size_t c = 0; c < polygons.cylinders.size(); ++c) {
    const CylinderRecord& record = polygons.cylinders[c];
    const std::string label = "cylinder " + std::to_string(c);
    if (record.axis_a < 0 || record.axis_a >= vertex_count || record.axis_b < 0 || record.axis_b >= vertex_count)
      return Error{source, 0, label + " uses a point index outside 0.." + std::to_string(vertex_count - 1)};
    Cylinder cylinder;
    cylinder.axis_a = model.vertices[record.axis_a];
    cylinder.axis_b = model.vertices[record.axis_b];
    cylinder.radius = record.radius;
    cylinder.attributes = record.attributes;
    if (!(record.radius > real(0))) return Error{source, 0, label + " has no positive radius"};
    const Vec3 axis = cylinder.axis_b - cylinder.axis_a;
    if (norm(axis) == real(0)) return Error{source, 0, label + " has its two axis points at the same place"};
    const Vec3 d = normalized(axis);
    const Vec3 u = perpendicular(d), v = cross(d, u);
    // The rims' points once each, base then top (the last of each at angle 2 pi, as the last
    // facet's corner always was), and the facets' corners named by their indices.
    const auto angle = [pi](int k) { return real(2 * k) * pi / real(kCylinderSides); };
    const int base = static_cast<int>(model.cylinder_points.size()), top = base + kCylinderSides + 1;
    for (int k = 0; k <= kCylinderSides; ++k)
      model.cylinder_points.push_back(on_circle(cylinder.axis_a, u, v, record.radius, angle(k)));
    for (int k = 0; k <= kCylinderSides; ++k) model.cylinder_points.push_back(model.cylinder_points[base + k] + axis);
    const std::vector<Vec3>& at = model.cylinder_points;
    for (int k = 0; k < kCylinderSides; ++k) {
      const Vec3 outward = normalized(on_circle(Vec3{}, u, v, real(1), (angle(k) + angle(k + 1)) / real(2)));
      const int index = static_cast<int>(c), b0 = base + k, b1 = b0 + 1, t0 = top + k, t1 = t0 + 1;
      model.cylinder_surface.push_back({{at[b0], at[b1], at[t1]}, outward, index, {b0, b1, t1}});
      model.cylinder_surface.push_back({{at[b0], at[t1], at[t0]}, outward, index, {b0, t1, t0}});
    }
    model.cylinders.push_back(cylinder);
  }
  return true;
}

/// Checks the circles, finds their planes and rims, and the cylinders they close.
Result<bool> add_circles(const Polygons& polygons, const std::string& source, EdgeModel& model) {
  using std::fabs;
  const int vertex_count = static_cast<int>(model.vertices.size());
  const real pi = real(kPi);
  for (size_t k = 0; k < polygons.circles.size(); ++k) {
    const CircleRecord& record = polygons.circles[k];
    const std::string label = "circle " + std::to_string(k);
    for (int index : {record.centre, record.plane_a, record.plane_b})
      if (index < 0 || index >= vertex_count)
        return Error{source, 0, label + " uses a point index outside 0.." + std::to_string(vertex_count - 1)};
    if (!(record.radius > real(0))) return Error{source, 0, label + " has no positive radius"};
    Circle circle;
    circle.centre = model.vertices[record.centre];
    circle.radius = record.radius;
    circle.attributes = record.attributes;
    const Vec3 to_a = model.vertices[record.plane_a] - circle.centre;
    const Vec3 to_b = model.vertices[record.plane_b] - circle.centre;
    const Vec3 n = cross(normalized(to_a), normalized(to_b));
    if (norm(n) < real(1e-3)) return Error{source, 0, label + ": its centre and two plane points are on one line"};
    circle.normal = normalized(n);
    const Vec3 u = normalized(to_a), v = cross(circle.normal, u);
    for (int s = 0; s <= kCircleSides; ++s)
      circle.rim.push_back(
          on_circle(circle.centre, u, v, record.radius, real(2 * (s % kCircleSides)) * pi / real(kCircleSides)));
    // A circle closing a cylinder's end: the cylinder's own side never hides it (Edge-ID).
    const real tolerance = real(1e-3) * record.radius;
    for (size_t c = 0; c < model.cylinders.size() && circle.cap_of < 0; ++c) {
      const Cylinder& cylinder = model.cylinders[c];
      const Vec3 d = normalized(cylinder.axis_b - cylinder.axis_a);
      const bool at_end =
          norm(circle.centre - cylinder.axis_a) < tolerance || norm(circle.centre - cylinder.axis_b) < tolerance;
      if (at_end && fabs(cylinder.radius - record.radius) < tolerance && fabs(dot(d, circle.normal)) > real(0.999))
        circle.cap_of = static_cast<int>(c);
    }
    model.circles.push_back(circle);
  }
  return true;
}

struct EdgeUse {
  int faces[2] = {-1, -1};
  bool same_direction = false;  ///< both faces run the edge the same way (inconsistent winding)
  int count = 0;
  int first_a = 0;
};

/// Adds the free-standing lines as tracked edges; a line that is already a face boundary gives
/// that edge its parameters instead. `uses` holds the face boundaries by sorted end points.
Result<bool> add_free_lines(const Polygons& polygons, const std::string& source,
                            std::map<std::pair<int, int>, EdgeUse>& uses, EdgeModel& model) {
  const int vertex_count = static_cast<int>(model.vertices.size());
  auto fail = [&](const std::string& message) { return Error{source, 0, message}; };
  for (size_t l = 0; l < polygons.lines.size(); ++l) {
    const std::pair<int, int>& line = polygons.lines[l];
    if (line.first < 0 || line.first >= vertex_count || line.second < 0 || line.second >= vertex_count)
      return fail("a line uses a vertex out of range");
    if (line.first == line.second) return fail("a line joins vertex " + std::to_string(line.first) + " to itself");
    const std::pair<int, int> key(line.first < line.second ? line.first : line.second,
                                  line.first < line.second ? line.second : line.first);
    if (uses.count(key)) {  // already a face boundary: the line's own parameters go to that edge
      for (Edge& edge : model.edges)
        if (edge.a == key.first && edge.b == key.second && l < polygons.line_attributes.size())
          edge.attributes = polygons.line_attributes[l];
      continue;
    }
    uses[key].count = 0;
    Edge edge;
    edge.a = key.first;
    edge.b = key.second;
    if (l < polygons.line_attributes.size()) edge.attributes = polygons.line_attributes[l];
    model.edges.push_back(edge);
  }
  return true;
}

/// The faces' boundaries by sorted end points, and the order in which they were first seen (so
/// that edge indices are stable).
struct EdgeUses {
  std::map<std::pair<int, int>, EdgeUse> by_ends;
  std::vector<std::pair<int, int>> order;

  void add(int a, int b, int face) {
    const std::pair<int, int> key(a < b ? a : b, a < b ? b : a);
    auto found = by_ends.find(key);
    if (found == by_ends.end()) {
      EdgeUse use;
      use.faces[0] = face;
      use.count = 1;
      use.first_a = a;
      by_ends.emplace(key, use);
      order.push_back(key);
      return;
    }
    EdgeUse& use = found->second;
    if (use.count == 1) {
      use.faces[1] = face;
      use.same_direction = (use.first_a == a);
    }
    ++use.count;
  }
};

/// Checks face `f` (its vertices, its area, a simple polygon), adds it with its normal and
/// triangles to the model and its boundary to `uses`.
Result<bool> add_face(const Polygons& polygons, size_t f, const std::string& source, EdgeUses& uses, EdgeModel& model) {
  const int vertex_count = static_cast<int>(model.vertices.size());
  const std::vector<int>& face = polygons.faces[f];
  const std::string label = "face " + std::to_string(f);
  auto fail = [&](const std::string& message) { return Error{source, 0, label + message}; };
  if (face.size() < 3) return fail(" has fewer than 3 vertices");
  for (size_t i = 0; i < face.size(); ++i) {
    if (face[i] < 0 || face[i] >= vertex_count)
      return fail(" uses vertex " + std::to_string(face[i]) + " of " + std::to_string(vertex_count));
    for (size_t j = 0; j < i; ++j)
      if (face[i] == face[j]) return fail(" repeats vertex " + std::to_string(face[i]));
  }
  const std::vector<Vec3> corners = normalized_corners(model.vertices, face);
  const Vec3 area_normal = newell_normal(corners);
  if (norm(area_normal) == real(0)) return fail(" has no area");
  Face out;
  out.vertices = face;
  out.normal = normalized(area_normal);
  if (f < polygons.face_attributes.size()) out.attributes = polygons.face_attributes[f];
  std::vector<std::array<int, 3>> pieces;
  if (!triangulate(corners, area_normal, pieces)) return fail(" is not a simple polygon");
  for (const auto& p : pieces) model.triangles.push_back({face[p[0]], face[p[1]], face[p[2]], static_cast<int>(f)});
  model.faces.push_back(out);
  for (size_t i = 0; i < face.size(); ++i) uses.add(face[i], face[(i + 1) % face.size()], static_cast<int>(f));
  return true;
}

/// The model is closed when every boundary joins two faces that run it in opposite directions;
/// a boundary is tracked when it is an open border or a crease sharper than the rule's angle.
void add_crease_edges(const EdgeUses& uses, const EdgeRules& rules, EdgeModel& model) {
  using std::cos;
  model.closed = !uses.order.empty();
  for (const auto& key : uses.order) {
    const EdgeUse& use = uses.by_ends.at(key);
    if (use.count != 2 || use.same_direction) model.closed = false;
  }
  const real crease_cos = cos(rules.crease_angle);
  for (const auto& key : uses.order) {
    const EdgeUse& use = uses.by_ends.at(key);
    bool tracked = use.count != 2;
    if (use.count == 2) {
      const Vec3& n0 = model.faces[use.faces[0]].normal;
      const Vec3 n1 = use.same_direction ? -model.faces[use.faces[1]].normal : model.faces[use.faces[1]].normal;
      tracked = dot(n0, n1) < crease_cos;
    }
    if (!tracked) continue;
    Edge edge;
    edge.a = key.first;
    edge.b = key.second;
    edge.faces[0] = use.faces[0];
    edge.faces[1] = use.count >= 2 ? use.faces[1] : -1;
    model.edges.push_back(edge);
  }
}

}  // namespace

Result<EdgeModel> build_edge_model(const Polygons& polygons, const EdgeRules& rules, const std::string& source) {
  auto fail = [&](const std::string& message) { return Error{source, 0, message}; };
  const auto finite = [](const real& v) { return std::isfinite(static_cast<double>(v)); };
  for (size_t v = 0; v < polygons.vertices.size(); ++v) {
    const Vec3& p = polygons.vertices[v];
    if (!finite(p.x) || !finite(p.y) || !finite(p.z)) return fail("point " + std::to_string(v) + " is not a finite number");
  }
  for (const CylinderRecord& c : polygons.cylinders)
    if (!finite(c.radius)) return fail("a cylinder's radius is not a finite number");
  for (const CircleRecord& c : polygons.circles)
    if (!finite(c.radius)) return fail("a circle's radius is not a finite number");
  EdgeModel model;
  model.vertices = polygons.vertices;
  EdgeUses uses;
  for (size_t f = 0; f < polygons.faces.size(); ++f) {
    const Result<bool> face = add_face(polygons, f, source, uses, model);
    if (!face.ok()) return face.error();
  }
  add_crease_edges(uses, rules, model);
  const Result<bool> lines = add_free_lines(polygons, source, uses.by_ends, model);
  if (!lines.ok()) return lines.error();
  const Result<bool> cylinders = add_cylinders(polygons, source, model);
  if (!cylinders.ok()) return cylinders.error();
  const Result<bool> circles = add_circles(polygons, source, model);
  if (!circles.ok()) return circles.error();
  if (primitive_count(model) == 0) return fail("the model has no edge, cylinder or circle to track");
  if (primitive_count(model) > kMaxEdges)
    return fail("the model has " + std::to_string(primitive_count(model)) +
                " tracked primitives (edges, 2 per cylinder, circles); Edge-ID codes at most " +
                std::to_string(kMaxEdges));
  return model;
}

}  // namespace edgetrack
