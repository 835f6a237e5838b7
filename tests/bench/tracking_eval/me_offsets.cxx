// SPDX-License-Identifier: BSD-3-Clause
/// Where the moving edges put their matches on a generated sequence, at the true pose of every
/// frame: the control points are sampled at the true pose, so each match's distance along the
/// normal from its control point is its error. Signed outwards (from the model's projected
/// centre), where `synth --clutter` puts its lines. Prints, for the contrast test against the
/// response at the true projection (what the tracker does from a given pose) and without it:
/// the strongest maximum (the single-hypothesis match), and the nearest of up to 4 hypotheses.
/// With CLUTTER_MM (synth's --clutter; 0: none), also how far each control point's line lies from it in
/// the image: the lines are offset in 3D, away from the model's centre, so where that offset
/// points along the line of sight the line lands on the edge itself.
///   tracking_eval_me_offsets MODEL.cao SEQUENCE_DIR [CLUTTER_MM]   (synth's camera.xml, truth.csv, frames/)
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "edgetrack/grey_conversion.h"
#include "edgetrack/moving_edges.h"
#include "edgetrack/scene_extras.h"
#include "generated_sequence.h"

using namespace edgetrack;

namespace {

/// Offsets of one way of matching, pixels.
struct Tally {
  int count = 0;
  int within_pixel = 0;  ///< |offset| < 1
  double sum = 0;        ///< signed, outwards
  double sum_abs = 0;
  void add(double offset) {
    ++count;
    within_pixel += std::fabs(offset) < 1;
    sum += offset;
    sum_abs += std::fabs(offset);
  }
  void print(const char* label) const {
    std::printf("%s: %d matches, %.1f %% within a pixel of the edge, mean offset %+.3f px outwards, mean |offset| %.3f px\n",
                label, count, 100.0 * within_pixel / (count ? count : 1), sum / (count ? count : 1),
                sum_abs / (count ? count : 1));
  }
};

/// The image distance (pixels) from the control point to its clutter line, or -1 when the line
/// is behind the camera or seen end-on.
double line_distance(const ControlPoint& point, const Segment3& line, const PinholeCamera& camera, const Se3& pose) {
  const Vec3 a = pose * line.a, b = pose * line.b;
  if (a.z <= real(0) || b.z <= real(0)) return -1;
  const Vec2 pa = camera.project(a), d = camera.project(b) - pa;
  const real length = norm(d);
  if (length <= real(1)) return -1;
  return std::fabs(static_cast<double>((d.x * (point.pixel.y - pa.y) - d.y * (point.pixel.x - pa.x)) / length));
}

/// How far the control points' clutter lines lie from them.
struct LineTally {
  int count = 0;
  int on_edge = 0;     ///< within the line's drawn width, 1.5 px: edge and line are one feature
  int within_mask = 0;  ///< within the mask's half + 1: inside the edge's own response
  double sum = 0;
  void add(double distance, double mask_reach) {
    ++count;
    on_edge += distance < 1.5;
    within_mask += distance <= mask_reach;
    sum += distance;
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: %s MODEL.cao SEQUENCE_DIR [CLUTTER_MM]\n", argv[0]);
    return 2;
  }
  GeneratedSequence sequence;
  if (!sequence.load(argv[0], argv[1], argv[2])) return 1;
  const TrackerConfig& config = sequence.config;
  const std::vector<Se3>& truth = sequence.truth;
  const EdgeModel& model = sequence.model;
  Vec3 centre;
  for (const Vec3& v : model.vertices) centre = centre + v;
  centre = (real(1) / real(static_cast<int>(model.vertices.size()))) * centre;
  Result<Tracker> tracker = Tracker::create(model, config.camera, truth[0], config.params);
  const vpMe me = moving_edge_masks(config.params.me);
  const unsigned range = config.params.me.range;
  vpImage<unsigned char> grey(static_cast<unsigned>(config.camera.height), static_cast<unsigned>(config.camera.width));
  std::vector<real> references;
  std::vector<EdgeMatch> matches;
  Tally strongest[2], nearest[2];  // [0]: without the contrast test, [1]: with it
  const double clutter_mm = argc == 4 ? std::atof(argv[3]) : 0;
  const std::vector<Segment3> clutter =
      clutter_mm > 0 ? parallel_clutter(model, real(clutter_mm / 1000)) : std::vector<Segment3>{};
  const double mask_reach = static_cast<int>(config.params.me.mask_size) / 2 + 1;
  LineTally lines;
  for (size_t k = 0; k < truth.size(); ++k) {
    const auto pixels = sequence.frame(k);
    if (!pixels.ok()) break;
    const FrameView frame = pixels.value().view();
    // The tracker samples its visible control points at the pose it is reset to.
    tracker.value().reset(truth[k]);
    if (!tracker.value().track(frame).ok()) break;
    const std::vector<ControlPoint>& points = tracker.value().control_points();
    convert_to_grey(frame, PixelBox{0, 0, frame.height, frame.width}, grey);
    const Vec2 middle = config.camera.project(truth[k] * centre);
    for (const ControlPoint& point : points) {
      // parallel_clutter's lines follow the model's edges, one each; other primitives have none.
      if (point.edge >= static_cast<int>(clutter.size())) continue;
      const double distance = line_distance(point, clutter[static_cast<size_t>(point.edge)], config.camera, truth[k]);
      if (distance >= 0) lines.add(distance, mask_reach);
    }
    for (int test = 0; test < 2; ++test) {
      if (test) contrasts_at_points(grey, points, me, references);
      search_moving_edges(grey, points, me, range, kMaxHypotheses, matches, test ? &references : nullptr);
      for (const EdgeMatch& m : matches) {
        const real outwards = dot(m.point.normal, m.point.pixel - middle) < real(0) ? real(-1) : real(1);
        const double found = static_cast<double>(outwards * dot(m.point.normal, m.found - m.point.pixel));
        double best = found;
        for (int a = 0; a < m.alternative_count; ++a) {
          const double d = static_cast<double>(outwards * dot(m.point.normal, m.alternatives[a] - m.point.pixel));
          if (std::fabs(d) < std::fabs(best)) best = d;
        }
        strongest[test].add(found);
        nearest[test].add(best);
      }
    }
  }
  std::printf("%s, %zu frames at the true pose, range %d, mask %d px\n", sequence.directory.c_str(), truth.size(),
              static_cast<int>(range), static_cast<int>(config.params.me.mask_size));
  strongest[0].print("strongest edge, no contrast test");
  strongest[1].print("strongest passing the contrast test (the single hypothesis)");
  nearest[0].print("nearest of 4 hypotheses, no contrast test");
  nearest[1].print("nearest of 4 hypotheses, with the contrast test");
  if (lines.count)
    std::printf("clutter lines: %d control points, mean %.2f px from their line, %.1f %% within 1.5 px (the line's width), "
                "%.1f %% within %.0f px (the mask's half + 1)\n",
                lines.count, lines.sum / lines.count, 100.0 * lines.on_edge / lines.count,
                100.0 * lines.within_mask / lines.count, mask_reach);
  return 0;
}
