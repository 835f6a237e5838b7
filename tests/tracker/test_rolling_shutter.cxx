// SPDX-License-Identifier: BSD-3-Clause
/// Control points at their rows' read times (rolling_shutter.h): each moved point projects, at
/// the frame's pose, where the pose of its row puts the edge; the edge's normal turns with the
/// shear; a global shutter, or no velocity, leaves the points as they were, bit for bit.
/// RowTimes::again reads the points by each match's point_index: a caller's matches whose index
/// names no point, or points other than those move() kept, are refused and nothing is read.
#include <climits>
#include <cmath>

#include "edgetrack/control_points.h"
#include "edgetrack/rolling_shutter.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

PinholeCamera qvga() { return PinholeCamera{real(220), real(220), real(160), real(120), 320, 240}; }

/// A vertical model edge 0.3 m in front of the camera, seen as a column from row 40 to 200.
std::vector<ControlPoint> column_points(const PinholeCamera& camera, const Se3& pose) {
  std::vector<ControlPoint> points;
  for (int k = 0; k < 5; ++k) {
    ControlPoint p;
    p.edge = 0;
    p.point_in_model = Vec3{real(0.01), real(-0.08 + 0.04 * k), real(0)};
    p.pixel = camera.project(pose * p.point_in_model);
    p.direction = Vec2{real(0), real(1)};
    p.normal = Vec2{real(-1), real(0)};
    points.push_back(p);
  }
  return points;
}

bool same_bits(const ControlPoint& a, const ControlPoint& b) {
  return a.point_in_model.x == b.point_in_model.x && a.point_in_model.y == b.point_in_model.y &&
         a.point_in_model.z == b.point_in_model.z && a.pixel.x == b.pixel.x && a.pixel.y == b.pixel.y &&
         a.normal.x == b.normal.x && a.normal.y == b.normal.y;
}

/// Matches found for `points`, one per point, each naming its point.
std::vector<EdgeMatch> matches_for(const std::vector<ControlPoint>& points) {
  std::vector<EdgeMatch> matches(points.size());
  for (size_t k = 0; k < points.size(); ++k) {
    matches[k].point = points[k];
    matches[k].point_index = static_cast<int>(k);
    matches[k].found = points[k].pixel;
  }
  return matches;
}

bool same_model_points(const std::vector<EdgeMatch>& a, const std::vector<EdgeMatch>& b) {
  bool same = a.size() == b.size();
  for (size_t k = 0; same && k < a.size(); ++k) same = same_bits(a[k].point, b[k].point);
  return same;
}

}  // namespace

static void test_rolling_shutter() {
  const PinholeCamera camera = qvga();
  const Se3 pose(rotation_exp(Vec3{real(0.1), real(-0.2), real(0.05)}), Vec3{real(0), real(0), real(0.3)});
  // 12 px per frame sideways at 0.3 m (a camera-frame translation) and a slight turn.
  const Twist velocity{Vec3{real(12 * 0.3 / 220), real(0), real(0)}, Vec3{real(0), real(0.002), real(0)}};
  const std::vector<ControlPoint> sampled = column_points(camera, pose);

  std::vector<ControlPoint> global = sampled;
  move_to_row_times(global, camera, pose, velocity, real(0));
  std::vector<ControlPoint> still = sampled;
  move_to_row_times(still, camera, pose, Twist{}, real(1));
  bool unchanged = true;
  for (size_t i = 0; i < sampled.size(); ++i) unchanged = unchanged && same_bits(global[i], sampled[i]) && same_bits(still[i], sampled[i]);
  TEST("readout 0, or no velocity, leaves the points as they were, bit for bit", unchanged, true);

  std::vector<ControlPoint> moved = sampled;
  const real readout(1);
  move_to_row_times(moved, camera, pose, velocity, readout);
  double worst_place = 0, worst_time = 0, worst_normal = 0;
  for (size_t i = 0; i < moved.size(); ++i) {
    const ControlPoint& p = moved[i];
    // Where the row's own pose puts the edge point: exp(t velocity) pose X, t the row's time.
    const double t = static_cast<double>(readout) * ((static_cast<double>(p.pixel.y) + 0.5) / camera.height - 0.5);
    const Se3 row_pose = Se3::exp(Twist{real(t) * velocity.v, real(t) * velocity.w}) * pose;
    const Vec2 seen = camera.project(row_pose * sampled[i].point_in_model);
    const Vec2 projected = camera.project(pose * p.point_in_model);
    worst_place = std::fmax(worst_place, static_cast<double>(norm(seen - p.pixel)));
    worst_place = std::fmax(worst_place, static_cast<double>(norm(projected - p.pixel)));
    worst_time = std::fmax(worst_time, std::fabs(t - static_cast<double>(row_time(p.pixel.y, readout / real(240), 240))));
    // A column sheared by 12 px over the 240 rows leans by atan(12 / 240) from the vertical.
    const double lean = std::atan2(-static_cast<double>(p.normal.y), -static_cast<double>(p.normal.x));
    worst_normal = std::fmax(worst_normal, std::fabs(lean - std::atan2(-12.0, 240.0)));
  }
  // Within 0.05 px and a tenth of a row's time: S47.16 holds 1/240 to 2.6e-4 relative.
  TEST("each point is where its row's pose sees it, and the frame's pose projects it there (0.05 px)",
       worst_place < 0.05, true);
  TEST("its row's time is the readout's share of its row", worst_time < 0.1 / 240, true);
  TEST("the normal turns with the shear, 12 px over the frame's rows (within 0.01 rad)", worst_normal < 0.01, true);
  TEST("the top row is earlier, so its point is moved back against the motion",
       moved[0].pixel.x < sampled[0].pixel.x && moved[4].pixel.x > sampled[4].pixel.x, true);
}

static void test_row_times_match_indices() {
  const PinholeCamera camera = qvga();
  const Se3 pose(Mat33::identity(), Vec3{real(0), real(0), real(0.3)});
  const Twist velocity{Vec3{real(0.02), real(0), real(0)}, Vec3{real(0), real(0.002), real(0)}};
  const Twist own{Vec3{real(0.03), real(0), real(0)}, Vec3{real(0), real(0.001), real(0)}};
  const real readout(1);
  const std::vector<ControlPoint> sampled = column_points(camera, pose);

  RowTimes never_moved;
  std::vector<ControlPoint> points = sampled;
  std::vector<EdgeMatch> matches = matches_for(points);
  TEST("again() before any move() refuses the points",
       never_moved.again(points, matches, camera, pose, own, readout), false);

  RowTimes row_times;
  row_times.move(points, camera, pose, velocity, readout);
  matches = matches_for(points);
  const std::vector<ControlPoint> moved_once = points;
  const std::vector<EdgeMatch> found = matches;
  bool refused = true, untouched = true;
  for (const int index : {-1, static_cast<int>(sampled.size()), INT_MAX, INT_MIN}) {
    std::vector<EdgeMatch> bad = found;
    bad[2].point_index = index;
    const std::vector<EdgeMatch> bad_as_given = bad;
    refused = refused && !row_times.again(points, bad, camera, pose, own, readout);
    untouched = untouched && same_model_points(bad, bad_as_given);
  }
  for (size_t k = 0; k < points.size(); ++k) untouched = untouched && same_bits(points[k], moved_once[k]);
  TEST("a match whose point_index names no point is refused", refused, true);
  TEST("a refused call changes neither the points nor the matches", untouched, true);

  std::vector<ControlPoint> fewer(points.begin(), points.end() - 1);
  TEST("points other than those move() kept are refused", row_times.again(fewer, matches, camera, pose, own, readout),
       false);

  TEST("the tracker's own matches are taken", row_times.again(points, matches, camera, pose, own, readout), true);
  bool paired = true;
  for (size_t k = 0; k < matches.size(); ++k)
    paired = paired && matches[k].point.point_in_model.x == points[k].point_in_model.x &&
             matches[k].point.point_in_model.y == points[k].point_in_model.y &&
             matches[k].point.point_in_model.z == points[k].point_in_model.z;
  TEST("each match takes its own point's new model point", paired, true);
  TEST("the new velocity moves the model points again", points[0].point_in_model.x != moved_once[0].point_in_model.x,
       true);

  row_times.move(points, camera, pose, Twist{}, readout);
  TEST("after a move() with no velocity the earlier frame's points are gone",
       row_times.again(points, matches, camera, pose, own, readout), false);
}

TESTMAIN(test_rolling_shutter)
TESTMAIN(test_row_times_match_indices)
