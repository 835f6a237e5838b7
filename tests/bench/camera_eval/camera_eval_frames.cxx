// SPDX-License-Identifier: BSD-3-Clause
/// What a generated sequence with camera effects (synth's --shutter, --readout) allows the
/// tracker, frame by frame. Per frame, the camera position error (mm, as `edgetrack eval`) of:
///   tracked  the tracker from the true first pose through every frame (as `edgetrack track`);
///   early    the same poses against the true pose half a frame interval before the frame's time
///            (the start of a whole-interval exposure, the top row's read time of a whole-interval
///            readout): what the error would be were the truth stamped there;
///   alone    the frame solved alone from its own true pose (what the image allows the tracker);
///   rigid    one rigid pose fitted, from the true pose, to where each of alone's control points
///            is at its row's read time (the middle of its exposure), no image: what a rolling
///            shutter's shear leaves to a tracker of one rigid pose per frame, with perfect edges;
///   rigid_own the same rigid pose against the true pose at the mean read time of those points
///            (the object's own rows' time, not the middle row's): the shear alone;
/// and of alone's matches kept by the pose step, how far along the normal each lies from that
/// place (pixels): the mean |offset| and the share within a pixel.
///   camera_eval_frames MODEL.cao SEQUENCE_DIR READOUT [INTRINSICS] [--matches FRAME] [--robust-rounds N]
/// (synth's camera.xml, truth.csv, frames/frameNNNN.pgm; READOUT as synth's --readout;
/// INTRINSICS: synth's intrinsics.xml, the lens given as `track --intrinsics` gives it). With
/// --matches, the tracked run's control points of that frame instead, then its matches, one a
/// line: control point, found pixel, outlier, chosen hypothesis, contrast (to compare two builds
/// of `real`). --robust-rounds N: the tracked and alone runs with PoseParams::robust_rounds N
/// instead of the default (how far the robust rounds are from settling their weights).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "../tracking_eval/generated_sequence.h"
#include "camera_timing.h"
#include "edgetrack/camera_file.h"
#include "edgetrack/pose_solver.h"

using namespace edgetrack;

namespace {

double camera_position_error_mm(const Se3& pose, const Se3& truth) {
  return 1000.0 * static_cast<double>(norm(pose.inverse().translation() - truth.inverse().translation()));
}

/// Where `point` is in frame k's image: projected with the pose at its row's read time (a
/// steadily moving edge's blur ramp is centred on the middle of its exposure, the read time).
/// The row is the one the point falls on at the frame's time, then at that read time, which
/// `read` receives (frame intervals from the frame's time).
Vec2 timed_pixel(const ControlPoint& point, const std::vector<Se3>& truth, size_t k, const PinholeCamera& camera,
                 double readout, double& read) {
  Vec2 pixel = point.pixel;
  for (int pass = 0; pass < 2; ++pass) {
    read = readout * ((static_cast<double>(pixel.y) + 0.5) / camera.height - 0.5);
    pixel = camera.project(edgetrack_app::pose_at_time(truth, static_cast<double>(k) + read) * point.point_in_model);
  }
  return pixel;
}

struct Sums {
  double tracked = 0, early = 0, alone = 0, rigid = 0, rigid_own = 0, offset = 0;
  int frames = 0, matches = 0, within_pixel = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s MODEL.cao SEQUENCE_DIR READOUT [INTRINSICS] [--matches FRAME] [--robust-rounds N]\n",
                 argv[0]);
    return 2;
  }
  GeneratedSequence sequence;
  if (!sequence.load(argv[0], argv[1], argv[2])) return 1;
  const double readout = std::atof(argv[3]);
  int dump = -1, robust_rounds = -1;
  for (int i = 4; i < argc; ++i) {
    if (std::strcmp(argv[i], "--robust-rounds") == 0 && i + 1 < argc) {
      robust_rounds = std::atoi(argv[++i]);
      continue;
    }
    if (std::strcmp(argv[i], "--matches") == 0 && i + 1 < argc) {
      dump = std::atoi(argv[++i]);
      continue;
    }
    PinholeCamera& camera = sequence.config.camera;
    const Result<PinholeCamera> lens = read_camera_file(argv[i], {"", camera.width, camera.height});
    if (!lens.ok()) {
      std::fprintf(stderr, "%s\n", lens.error().text().c_str());
      return 1;
    }
    camera = lens.value();
  }
  const std::vector<Se3>& truth = sequence.truth;
  TrackerConfig& config = sequence.config;
  if (robust_rounds >= 0) config.params.pose.robust_rounds = robust_rounds;
  TrackerParams from_truth = config.params;
  from_truth.motion.start_frames = 0;
  Result<Tracker> tracked = Tracker::create(sequence.model, config.camera, truth[0], config.params);
  Result<Tracker> alone = Tracker::create(sequence.model, config.camera, truth[0], from_truth);
  if (!tracked.ok() || !alone.ok()) return 1;
  if (dump < 0) std::printf("frame tracked_mm early_mm alone_mm rigid_mm rigid_own_mm\n");
  Sums sums;
  for (size_t k = 0; k < truth.size(); ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "/frames/frame%04zu.pgm", k);
    const Result<edgetrack_app::FramePixels> pixels = edgetrack_app::read_netpbm_pixels(sequence.directory + name);
    if (!pixels.ok()) break;
    const FrameView frame = pixels.value().view();
    const Result<FrameResult> t = tracked.value().track(frame);
    if (!t.ok()) return 1;
    if (dump >= 0) {
      if (static_cast<int>(k) != dump) continue;
      for (const ControlPoint& p : tracked.value().control_points())
        std::printf("point %d %.6f %.6f\n", p.edge, static_cast<double>(p.pixel.x), static_cast<double>(p.pixel.y));
      for (const EdgeMatch& m : tracked.value().matches())
        std::printf("%d %.6f %.6f found %.6f %.6f outlier %d chosen %d contrast %.6f\n", m.point.edge,
                    static_cast<double>(m.point.pixel.x), static_cast<double>(m.point.pixel.y),
                    static_cast<double>(m.found.x), static_cast<double>(m.found.y), m.outlier ? 1 : 0, m.chosen,
                    static_cast<double>(m.contrast));
      return 0;
    }
    alone.value().reset(truth[k]);
    const Result<FrameResult> a = alone.value().track(frame);
    if (!a.ok()) return 1;
    std::vector<EdgeMatch> timed;
    double read_sum = 0;
    for (const EdgeMatch& m : alone.value().matches()) {
      double read = 0;
      const Vec2 place = timed_pixel(m.point, truth, k, config.camera, readout, read);
      read_sum += read;
      EdgeMatch exact;
      exact.point = m.point;
      exact.found = place;
      timed.push_back(exact);
      if (m.outlier) continue;
      const double offset = std::fabs(static_cast<double>(dot(m.point.normal, m.used() - place)));
      sums.offset += offset;
      sums.within_pixel += offset < 1;
      ++sums.matches;
    }
    const PoseSolution rigid = solve_pose(timed, config.camera, truth[k], config.params.pose);
    const double mean_read = read_sum / static_cast<double>(timed.empty() ? 1 : timed.size());
    const Se3 own_time = edgetrack_app::pose_at_time(truth, static_cast<double>(k) + mean_read);
    const Se3 half_earlier = edgetrack_app::pose_at_time(truth, static_cast<double>(k) - 0.5);
    const double errors[5] = {camera_position_error_mm(t.value().camera_from_model, truth[k]),
                              camera_position_error_mm(t.value().camera_from_model, half_earlier),
                              camera_position_error_mm(a.value().camera_from_model, truth[k]),
                              camera_position_error_mm(rigid.camera_from_model, truth[k]),
                              camera_position_error_mm(rigid.camera_from_model, own_time)};
    sums.tracked += errors[0];
    sums.early += errors[1];
    sums.alone += errors[2];
    sums.rigid += errors[3];
    sums.rigid_own += errors[4];
    ++sums.frames;
    std::printf("%zu %.3f %.3f %.3f %.3f %.3f\n", k, errors[0], errors[1], errors[2], errors[3], errors[4]);
  }
  if (sums.frames == 0) return 1;
  const double n = sums.frames, m = sums.matches > 0 ? sums.matches : 1;
  std::printf("mean tracked_mm=%.4f early_mm=%.4f alone_mm=%.4f rigid_mm=%.4f rigid_own_mm=%.4f offset_px=%.4f "
              "within_pixel=%.4f\n",
              sums.tracked / n, sums.early / n, sums.alone / n, sums.rigid / n, sums.rigid_own / n, sums.offset / m,
              sums.within_pixel / m);
  return 0;
}
