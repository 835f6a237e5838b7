// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's two pose files, told apart by their content: a .pos pose vector and the 4x4
/// homogeneous matrix vpHomogeneousMatrix::save writes (as Castle-simu's CameraPose files) read
/// to the same pose; a matrix that is not a rigid transform, and any other count of numbers,
/// is refused at its line.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "edgetrack/pose_io.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

namespace {

/// Writes `pose` as vpHomogeneousMatrix::save does: four rows of four numbers. The rotation is
/// made from the pose's thetaU in double (Rodrigues), orthonormal to double's precision as a
/// ViSP program's is, whatever the `real` (S47.16's own matrix is off by its resolution).
void write_matrix(const std::string& path, const Se3& pose) {
  const Vec3 tu = pose.theta_u(), t = pose.translation();
  const double w[3] = {static_cast<double>(tu.x), static_cast<double>(tu.y), static_cast<double>(tu.z)};
  const double translation[3] = {static_cast<double>(t.x), static_cast<double>(t.y), static_cast<double>(t.z)};
  const double angle = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const double k[3] = {w[0] / angle, w[1] / angle, w[2] / angle};
  const double c = std::cos(angle), s = std::sin(angle);
  const double cross[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
  std::ofstream file(path);
  char row[160];
  for (int r = 0; r < 3; ++r) {
    double m[3];
    for (int col = 0; col < 3; ++col) m[col] = (r == col ? c : 0) + s * cross[r][col] + (1 - c) * k[r] * k[col];
    std::snprintf(row, sizeof row, "%.10g %.10g %.10g %.10g\n", m[0], m[1], m[2], translation[r]);
    file << row;
  }
  file << "0 0 0 1\n";
}

/// The error of reading `text` as a pose file, or "" when it reads.
Error refusal(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  const Result<Se3> read = read_pos(path);
  return read.ok() ? Error{} : read.error();
}

bool says(const Error& error, const std::string& words) { return error.message.find(words) != std::string::npos; }

}  // namespace

static void test_pose_files() {
  const std::string visp = EDGETRACK_VISP_IMAGES;
  const std::string out = EDGETRACK_TEST_OUTPUT;
  const std::string name = real_name();
  const double tol = name == "s47_16" ? 1e-4 : name == "float" ? 1e-5 : 1e-6;

  // Castle-simu's first camera pose: R's rows (1 0 0), (0 -0.906 0.423), (0 -0.423 -0.906).
  const Result<Se3> castle = read_pos(visp + "/mbt-depth/Castle-simu/CameraPose/Camera_001.txt");
  TEST("Castle-simu's CameraPose/Camera_001.txt (a 4x4 matrix) reads", castle.ok(), true);
  if (castle.ok()) {
    TEST_NEAR("its tz is 0.6010702848 m", castle.value().translation().z, 0.6010702848, tol);
    TEST_NEAR("its R[1][1] is -0.9063078165", castle.value().rotation().m[1][1], -0.9063078165, 2 * tol);
    TEST_NEAR("its R[1][2] is 0.4226182699", castle.value().rotation().m[1][2], 0.4226182699, 2 * tol);
    // A rotation of -155 degrees about x (cos -0.906, sin -0.423): thetaU (-2.705, 0, 0).
    TEST_NEAR("its thetaU is -155 degrees about x", castle.value().theta_u().x, -155 * 3.141592653589793 / 180, 10 * tol);
  }

  // mbt/cube.0.pos written as a matrix reads back as the same pose.
  const Result<Se3> cube = read_pos(visp + "/mbt/cube.0.pos");
  TEST("mbt/cube.0.pos reads", cube.ok(), true);
  if (cube.ok()) {
    write_matrix(out + "/cube0_matrix.txt", cube.value());
    const Result<Se3> again = read_pos(out + "/cube0_matrix.txt");
    TEST("the same pose written as a homogeneous matrix reads", again.ok(), true);
    if (again.ok()) {
      const Vec3 a = cube.value().theta_u(), b = again.value().theta_u();
      TEST_NEAR("to the same thetaU (x)", a.x, static_cast<double>(b.x), 10 * tol);
      TEST_NEAR("to the same thetaU (z)", a.z, static_cast<double>(b.z), 10 * tol);
      TEST_NEAR("to the same tz", cube.value().translation().z, static_cast<double>(again.value().translation().z), tol);
    }
  }

  const std::string bad = out + "/bad_pose.txt";
  const std::string rows = "1 0 0 0.1\n0 1 0 0.2\n0 0 1 0.5\n";
  Error e = refusal(bad, "1 0 0 0.1\n0 0.9 0 0.2\n0 0 1 0.5\n0 0 0 1\n");
  TEST("a stretched rotation is refused", says(e, "is not a rotation"), true);
  TEST("at the matrix's first line", e.line, 1);
  e = refusal(bad, "1 0 0 0.1\n0 1 0 0.2\n0 0 -1 0.5\n0 0 0 1\n");
  TEST("a reflection (det -1) is refused", says(e, "is not a rotation"), true);
  e = refusal(bad, rows + "0 0 0 2\n");
  TEST("a last row other than 0 0 0 1 is refused", says(e, "last row"), true);
  TEST("at its line", e.line, 4);
  e = refusal(bad, "1 0 0 0.1\n0 1 0 nan\n0 0 1 0.5\n0 0 0 1\n");
  TEST("a NaN is refused", says(e, "ty (m)"), true);
  TEST("at its line", e.line, 2);
  e = refusal(bad, rows);
  TEST("twelve numbers are refused", says(e, "expected 6 numbers"), true);
  TEST("naming the count", says(e, "found 12"), true);
  e = refusal(bad, rows + "0 0 0 1\n7\n");
  TEST("seventeen numbers are refused", says(e, "found more than 16: '7'"), true);
  TEST("at the line of the seventeenth", e.line, 5);
  e = refusal(bad, "0.1 0.2 0.5 0 0 0 9\n");
  TEST("seven numbers are refused", says(e, "found 7"), true);
  TEST("a .pos of six numbers still reads", refusal(bad, "0.1 0.2 0.5\n0 0 0.3\n").message.empty(), true);
}

TESTMAIN(test_pose_files)
