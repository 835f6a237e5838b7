// SPDX-License-Identifier: BSD-3-Clause
/// The helpers of the detector's sequence evaluation (sequences.sh), host only:
///
/// detection_sequence trajectory cube|wood_toy steady|leave SEED FRAMES OUT.csv
///   A truth-format trajectory for `edgetrack synth --trajectory`: the model starts at a random
///   view inside the single-image evaluation's range (bench_detection.cxx: within 60 degrees of
///   the model's z axis, 120 to 200 mm, wholly in view) and turns about its centre by up to
///   15 degrees while drifting halfway towards the image centre and back. "leave" also pans it
///   out of the view from frame 15 (speeding up to 8 px per frame over 8 frames), keeps it out
///   for 10 frames and pans it back, slowing down to where it was.
///   Prints absent_first, absent_last (the frames with no vertex in the image, -1 when none) and
///   back (the first frame after them with the model wholly in view).
///
/// detection_sequence score MODEL POSES.csv TRUTH.csv [--cube] [--absent FIRST:LAST --back R] [--each]
///   A run of `edgetrack track` against the truth (a truth CSV, a directory of ViSP pose files as
///   Castle-simu's CameraPose/, or another run's poses): frames until the first
///   tracked one, frames tracked, uncertain and lost, tracked frames while the object was absent
///   and tracked frames more than 5 mm or 5 degrees off (an overlay visibly beside the object),
///   frames from `back` to the first tracked frame after the absence, and the error of the tracked
///   frames: the model centre in the camera frame (mm) and the rotation (degrees), taking the
///   cube's 24 symmetric poses as the truth too with --cube (the detector may find any); --each
///   prints each tracked frame's error first.
///
/// detection_sequence corners MODEL CAMERA.xml DOWNSCALE A.csv B.csv
///   The corner difference of two runs: per frame, the mean distance (pixels of the tracked size)
///   from each model vertex projected with A's pose to the nearest vertex projected with B's (the
///   same for any symmetric pose of a model whose vertices map onto each other); mean and largest.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "configuration.h"
#include "detection_scene.h"
#include "downscaled_tracking.h"
#include "edgetrack/detector/viewpoints.h"
#include "edgetrack/model_io.h"
#include "pose_table.h"
#include "synthetic_sequence.h"

using namespace edgetrack;
using namespace edgetrack_test;
using edgetrack_app::PoseRow;

namespace {

constexpr double kTurnDeg = 15, kTurnPeriod = 80, kDriftPeriod = 120;
constexpr double kPanPx = 8;
constexpr int kPanStart = 15, kOutFrames = 10;
constexpr double kRampFrames = 8;
constexpr double kWrongMm = 5, kWrongDeg = 5;

int usage() {
  std::fprintf(stderr,
               "usage: detection_sequence trajectory cube|wood_toy steady|leave SEED FRAMES OUT.csv\n"
               "       detection_sequence score MODEL POSES.csv TRUTH.csv [--cube] [--absent FIRST:LAST --back R] [--each]\n"
               "       detection_sequence corners MODEL CAMERA.xml DOWNSCALE A.csv B.csv\n");
  return 2;
}

/// Vertices projected inside the image (margin pixels from its border), of all of them.
int vertices_in_view(const EdgeModel& model, const PinholeCamera& camera, const Se3& pose, int margin) {
  int inside = 0;
  for (const Vec3& p : model.vertices) {
    const Vec3 c = pose * p;
    if (c.z <= real(0.01)) continue;
    const Vec2 uv = camera.project(c);
    inside += uv.x >= real(margin) && uv.y >= real(margin) && uv.x <= real(camera.width - 1 - margin) &&
              uv.y <= real(camera.height - 1 - margin);
  }
  return inside;
}

/// The start turned by `turn` about the model's centre (camera frame) and moved by `shift`.
Se3 moved(const Se3& start, const Vec3& centre_in_camera, const Mat33& turn, const Vec3& shift) {
  return Se3(turn * start.rotation(), turn * (start.translation() - centre_in_camera) + centre_in_camera + shift);
}

struct Events {
  int absent_first = -1, absent_last = -1, back = -1;
};

int trajectory_main(int argc, char** argv) {
  if (argc != 7) return usage();
  const Scene scene = std::strcmp(argv[2], "wood_toy") == 0 ? Scene::kWoodToy : Scene::kCube;
  const bool leave = std::strcmp(argv[3], "leave") == 0;
  const uint32_t seed = static_cast<uint32_t>(std::atoi(argv[4]));
  const int frames = std::atoi(argv[5]);
  const Result<EdgeModel> model = load_model(model_path(scene));
  if (!model.ok() || frames < 1) return usage();
  const EdgeModel& m = model.value();
  const PinholeCamera camera = qvga_camera();
  ViewRange range;
  range.max_angle = real(60.0 * M_PI / 180);
  range.distance_min = real(0.12);
  range.distance_max = real(0.2);
  const Se3 start = random_view(m, camera, range, seed);
  const Vec3 centre = start * model_extent(m).centre;
  std::mt19937 rng(seed * 7919u + 3);
  std::normal_distribution<double> gauss;
  const Vec3 axis = normalized(Vec3{real(gauss(rng)), real(gauss(rng)), real(gauss(rng))});
  const Vec3 to_middle{-centre.x / 2, -centre.y / 2, real(0)};
  // The pan runs along x towards the nearer side, in metres per frame at the centre's depth.
  const double pan_step = (centre.x > real(0) ? 1 : -1) * kPanPx * static_cast<double>(centre.z / camera.px);
  std::FILE* out = std::fopen(argv[6], "w");
  if (!out) return usage();
  std::fprintf(out, "%s\n", edgetrack_app::kTruthHeader);
  Events events;
  double pan = 0;
  int out_for = 0, last_inside = 0;
  enum class Pan { kBefore, kOut, kAway, kBack, kDone } phase = leave ? Pan::kBefore : Pan::kDone;
  for (int k = 0; k < frames; ++k) {
    if (phase == Pan::kBefore && k >= kPanStart) phase = Pan::kOut;
    // The pan speeds up over kRampFrames, as a hand-held camera does; away, it pans on while a
    // vertex is still in view (the turn brings some back); back, it slows down to a stop.
    const double ramp = std::fmin(1.0, (k - kPanStart + 1) / kRampFrames);
    if (phase == Pan::kOut || (phase == Pan::kAway && last_inside > 0)) pan += ramp * pan_step;
    if (phase == Pan::kBack) pan -= std::fmin(1.0, std::fabs(pan / pan_step) / 4) * pan_step;
    if (phase == Pan::kBack && std::fabs(pan / pan_step) < 0.1) pan = 0, phase = Pan::kDone;
    const double angle = kTurnDeg * M_PI / 180 * std::sin(2 * M_PI * k / kTurnPeriod);
    const real drift = real((1 - std::cos(2 * M_PI * k / kDriftPeriod)) / 2);
    const Se3 pose = moved(start, centre, rotation_exp(real(angle) * axis),
                           drift * to_middle + Vec3{real(pan), real(0), real(0)});
    const int inside = last_inside = vertices_in_view(m, camera, pose, 0);
    if (inside == 0) {
      if (events.absent_first < 0) events.absent_first = k;
      events.absent_last = k;
      if (phase == Pan::kOut) phase = Pan::kAway;
    }
    if (phase == Pan::kAway && inside == 0 && ++out_for >= kOutFrames) phase = Pan::kBack;
    if (events.absent_last >= 0 && events.back < 0 && inside == static_cast<int>(m.vertices.size())) events.back = k;
    const PoseRow row = edgetrack_app::pose_row(k, pose);
    std::fprintf(out, "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", k, row.t[0], row.t[1], row.t[2], row.tu[0], row.tu[1],
                 row.tu[2]);
  }
  if (std::fclose(out) != 0) return usage();
  std::printf("trajectory: absent_first=%d absent_last=%d back=%d\n", events.absent_first, events.absent_last, events.back);
  return 0;
}

/// A poses file, or the truth: a truth CSV or a directory of ViSP pose files (read_truth).
Result<std::vector<PoseRow>> read_rows(const std::string& path) {
  Result<std::vector<PoseRow>> rows = edgetrack_app::read_pose_table(path, edgetrack_app::kPosesHeader);
  return rows.ok() ? rows : edgetrack_app::read_truth(path);
}

struct Score {
  int first_tracked = -1, tracked = 0, uncertain = 0, lost = 0, tracked_absent = 0, tracked_wrong = 0;
  int back_to_tracked = -1;
  double sum_mm = 0, max_mm = 0, sum_deg = 0, max_deg = 0;
};

int score_main(int argc, char** argv) {
  if (argc < 5) return usage();
  bool cube = false, each = false;
  int absent_first = -1, absent_last = -1, back = -1;
  for (int i = 5; i < argc; ++i) {
    if (std::strcmp(argv[i], "--cube") == 0) cube = true;
    else if (std::strcmp(argv[i], "--each") == 0) each = true;
    else if (std::strcmp(argv[i], "--absent") == 0 && i + 1 < argc) std::sscanf(argv[++i], "%d:%d", &absent_first, &absent_last);
    else if (std::strcmp(argv[i], "--back") == 0 && i + 1 < argc) back = std::atoi(argv[++i]);
    else return usage();
  }
  const Result<EdgeModel> model = load_model(argv[2]);
  auto poses = read_rows(argv[3]), truth = read_rows(argv[4]);
  for (const Error* bad : {&model.error(), &poses.error(), &truth.error()})
    if (!bad->message.empty()) return std::fprintf(stderr, "%s\n", bad->text().c_str()), 1;
  const Vec3 centre = model_extent(model.value()).centre;
  const std::vector<Mat33> symmetries = cube ? cube_symmetries() : std::vector<Mat33>{Mat33::identity()};
  std::map<int, Se3> true_pose;
  for (const PoseRow& row : truth.value()) true_pose[row.frame] = edgetrack_app::pose_of(row);
  Score s;
  for (const PoseRow& row : poses.value()) {
    if (row.lost || row.uncertain) {
      s.lost += row.lost;
      s.uncertain += row.uncertain;
      continue;
    }
    const auto found = true_pose.find(row.frame);
    if (found == true_pose.end()) return std::fprintf(stderr, "%s: no truth for frame %d\n", argv[4], row.frame), 1;
    const PoseError e = pose_error(edgetrack_app::pose_of(row), found->second, centre, symmetries);
    if (each) std::printf("frame %d: %.3f mm %.3f deg\n", row.frame, e.centre_mm, e.rotation_deg);
    if (s.first_tracked < 0) s.first_tracked = row.frame;
    ++s.tracked;
    s.tracked_absent += row.frame >= absent_first && row.frame <= absent_last;
    s.tracked_wrong += e.centre_mm > kWrongMm || e.rotation_deg > kWrongDeg;
    if (absent_last >= 0 && row.frame > absent_last && s.back_to_tracked < 0)
      s.back_to_tracked = row.frame > back ? row.frame - back : 0;
    s.sum_mm += e.centre_mm, s.sum_deg += e.rotation_deg;
    s.max_mm = std::fmax(s.max_mm, e.centre_mm), s.max_deg = std::fmax(s.max_deg, e.rotation_deg);
  }
  const double n = s.tracked > 0 ? s.tracked : 1;
  std::printf("score: frames=%zu first_tracked=%d tracked=%d uncertain=%d lost=%d tracked_absent=%d tracked_wrong=%d "
              "back_to_tracked=%d mean_mm=%.3f max_mm=%.3f mean_deg=%.3f max_deg=%.3f\n",
              poses.value().size(), s.first_tracked, s.tracked, s.uncertain, s.lost, s.tracked_absent, s.tracked_wrong,
              s.back_to_tracked, s.sum_mm / n, s.max_mm, s.sum_deg / n, s.max_deg);
  return 0;
}

/// Mean over A's projected vertices of the distance to the nearest of B's.
double corner_difference(const EdgeModel& model, const PinholeCamera& camera, const Se3& a, const Se3& b) {
  double sum = 0;
  for (const Vec3& p : model.vertices) {
    const Vec2 u = camera.project(a * p);
    double nearest = 1e30;
    for (const Vec3& q : model.vertices) {
      const Vec2 v = camera.project(b * q);
      nearest = std::fmin(nearest, std::hypot(static_cast<double>(u.x - v.x), static_cast<double>(u.y - v.y)));
    }
    sum += nearest;
  }
  return sum / static_cast<double>(model.vertices.size());
}

int corners_main(int argc, char** argv) {
  if (argc != 7) return usage();
  const Result<EdgeModel> model = load_model(argv[2]);
  const auto camera = edgetrack_app::read_camera(argv[3], 1, 1);  // the image size plays no part here
  auto a = read_rows(argv[5]), b = read_rows(argv[6]);
  for (const Error* bad : {&model.error(), &camera.error(), &a.error(), &b.error()})
    if (!bad->message.empty()) return std::fprintf(stderr, "%s\n", bad->text().c_str()), 1;
  const PinholeCamera tracked = edgetrack::downscaled_camera(camera.value(), std::atoi(argv[4]));
  std::map<int, Se3> other;
  for (const PoseRow& row : b.value()) other[row.frame] = edgetrack_app::pose_of(row);
  double sum = 0, largest = 0;
  int frames = 0;
  for (const PoseRow& row : a.value()) {
    const auto found = other.find(row.frame);
    if (found == other.end()) continue;
    const double d = corner_difference(model.value(), tracked, edgetrack_app::pose_of(row), found->second);
    sum += d, largest = std::fmax(largest, d), ++frames;
  }
  std::printf("corners: frames=%d corner_px=%.3f corner_max_px=%.3f\n", frames, frames > 0 ? sum / frames : 0.0, largest);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  if (mode == "trajectory") return trajectory_main(argc, argv);
  if (mode == "score") return score_main(argc, argv);
  if (mode == "corners") return corners_main(argc, argv);
  return usage();
}
