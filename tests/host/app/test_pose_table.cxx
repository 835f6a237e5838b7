// SPDX-License-Identifier: BSD-3-Clause
// Poses and truth CSV files round-trip, bad files are refused with file and line, and the
// evaluation reports the camera-position error in the object frame as the paper does.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "evaluation.h"
#include "pose_table.h"
#include "testlib/testlib_test.h"

using namespace edgetrack_app;
using edgetrack::Se3;

/// One unit of the real's resolution (double: 2.2e-16, S47.16: 1.5e-5), the scale of what a
/// pose loses on its way through `real`.
static double real_ulp() { return static_cast<double>(std::numeric_limits<real>::epsilon()); }

static void test_pose_table() {
  const std::string path = std::string(APP_TEST_TMP) + "/poses.csv";
  {
    auto writer = PoseTableWriter::open(path, true);
    TEST("a poses file opens for writing", writer.ok(), true);
    PoseRow row = pose_row(3, Se3::from_theta_u({real(0.01), real(-0.02), real(0.15)}, {real(0.5), real(-0.6), real(0.1)}));
    row.points = 61;
    row.ms = 2.5;
    row.edge_angle_deg = 3.25;
    writer.value().write(row);
    row.frame = 4;
    row.lost = true;
    writer.value().write(row);
    row.frame = 5;
    row.lost = false;
    row.uncertain = true;
    writer.value().write(row);
    TEST("the poses file closes", writer.value().close().ok(), true);
  }
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  TEST("the header is exactly the documented one", header,
       std::string("frame,tx,ty,tz,tux,tuy,tuz,points,ms,status,edge_angle_deg"));
  std::string statuses;
  for (std::string line; std::getline(in, line);) {
    line.erase(line.rfind(','));  // the edge angle
    statuses += line.substr(line.rfind(',') + 1) + " ";
  }
  TEST("the status is spelled as the library's status_name spells it", statuses, std::string("tracked lost uncertain "));
  auto rows = read_pose_table(path, kPosesHeader);
  TEST("the poses file reads back", rows.ok(), true);
  if (rows.ok()) {
    TEST_EQUAL("three rows", rows.value().size(), size_t(3));
    TEST_EQUAL("frame number", rows.value()[0].frame, 3);
    // Written from real: exact to 1e-6 in the floating types, to an ulp or two in fixed point.
    const double write_tolerance = std::max(1e-6, 2 * real_ulp());
    TEST_NEAR("tz in metres (to the resolution of real)", rows.value()[0].t[2], 0.15, write_tolerance);
    TEST_NEAR("thetaU x in radians", rows.value()[0].tu[0], 0.5, write_tolerance);
    TEST_EQUAL("points", rows.value()[0].points, 61);
    TEST("status tracked", rows.value()[0].lost || rows.value()[0].uncertain, false);
    TEST("status lost", rows.value()[1].lost, true);
    TEST("status uncertain", rows.value()[2].uncertain && !rows.value()[2].lost, true);
    TEST_NEAR("the edge angle in degrees", rows.value()[0].edge_angle_deg, 3.25, 1e-9);
  }
  {
    std::ofstream older(std::string(APP_TEST_TMP) + "/older.csv");
    older << kPosesHeaderWithoutAngle << "\n0,0,0,0.15,0,0,0,50,1.0,ok\n1,0,0,0.15,0,0,0,50,1.0,tracked\n";
  }
  auto older = read_pose_table(std::string(APP_TEST_TMP) + "/older.csv", kPosesHeader);
  TEST("a file of an older edgetrack, without the edge angle, whose status says ok for tracked, reads", older.ok(), true);
  if (older.ok()) TEST("ok is read as tracked", older.value()[0].lost || older.value()[0].uncertain, false);
  if (older.ok()) TEST_NEAR("its edge angle reads as 0", older.value()[1].edge_angle_deg, 0.0, 1e-12);
  {
    std::ofstream wide(std::string(APP_TEST_TMP) + "/wide_angle.csv");
    wide << kPosesHeader << "\n0,0,0,0.15,0,0,0,50,1.0,tracked,91\n";
  }
  auto wide = read_pose_table(std::string(APP_TEST_TMP) + "/wide_angle.csv", kPosesHeader);
  TEST("an edge angle over 90 degrees is refused", wide.ok(), false);
  if (!wide.ok()) TEST("naming the column", wide.error().message.find("edge_angle_deg") != std::string::npos, true);
  {
    std::ofstream unknown(std::string(APP_TEST_TMP) + "/unknown_status.csv");
    unknown << kPosesHeader << "\n0,0,0,0.15,0,0,0,50,1.0,fine,2\n";
  }
  auto unknown = read_pose_table(std::string(APP_TEST_TMP) + "/unknown_status.csv", kPosesHeader);
  TEST("an unknown status is refused", unknown.ok(), false);
  TEST("the refusal names the status the file may hold",
       unknown.error().message.find("expected tracked, uncertain or lost") != std::string::npos, true);
  auto as_truth = read_pose_table(path, kTruthHeader);
  TEST("a poses file is not a truth file", as_truth.ok(), false);
  TEST("the header error is at line 1", as_truth.error().line, 1);

  {
    std::ofstream bad(std::string(APP_TEST_TMP) + "/bad.csv");
    bad << kTruthHeader << "\n0,0,0,0.15,0,0,0\n1,0,0,zero,0,0,0\n";
  }
  auto bad = read_pose_table(std::string(APP_TEST_TMP) + "/bad.csv", kTruthHeader);
  TEST("a non-number is refused", bad.ok(), false);
  TEST_EQUAL("at its line", bad.error().line, 3);

  // Truth: the camera 150 mm in front of the model; tracked: the model shifted by (1, -2, 2) mm
  // in the camera frame, so the camera position in the object frame is off by (-1, 2, -2) mm.
  const Se3 truth_pose = Se3::from_theta_u({real(0), real(0), real(0.15)}, {real(0), real(0), real(0)});
  const Se3 tracked_pose = Se3::from_theta_u({real(0.001), real(-0.002), real(0.152)}, {real(0), real(0), real(0)});
  std::vector<PoseRow> truth = {pose_row(0, truth_pose), pose_row(1, truth_pose)};
  std::vector<PoseRow> tracked = {pose_row(0, truth_pose), pose_row(1, tracked_pose)};
  tracked[1].lost = true;
  auto e = evaluate(tracked, truth, "truth.csv");
  TEST("evaluation succeeds", e.ok(), true);
  if (e.ok()) {
    // The poses go through real (pose_of, R^T t): in millimetres, 1e-4 in the floating types;
    // in S47.16 each of the few products rounds to 2^-16 m = 0.015 mm, so allow 0.5 ulp per
    // operation over about 16 of them: 8 ulp.
    const double mm_tolerance = std::max(1e-4, 1000 * 8 * real_ulp());
    TEST_NEAR("mean |x| error over two frames", e.value().mean_abs_mm[0], 0.5, mm_tolerance);
    TEST_NEAR("mean |y| error", e.value().mean_abs_mm[1], 1.0, mm_tolerance);
    TEST_NEAR("mean |z| error", e.value().mean_abs_mm[2], 1.0, mm_tolerance);
    TEST_NEAR("mean distance", e.value().mean_distance_mm, 1.5, mm_tolerance);
    TEST_NEAR("camera x in the object frame", e.value().frames[1].position[0], -1.0, mm_tolerance);
    TEST_EQUAL("lost frames are counted", e.value().lost, 1);
  }
  std::vector<PoseRow> extra = {pose_row(7, truth_pose)};
  auto missing = evaluate(extra, truth, "truth.csv");
  TEST("a frame without truth is an error", missing.ok(), false);
  TEST("naming the truth file and the frame", missing.error().text(), std::string("truth.csv: no ground truth for frame 7"));
}

TESTMAIN(test_pose_table)
