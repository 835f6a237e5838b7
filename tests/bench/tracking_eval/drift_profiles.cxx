// SPDX-License-Identifier: BSD-3-Clause
/// Whether a match's grey profile tells a thin dark line beside an edge from the edge itself
/// (thin_lines.h; issue #27, drift in clutter). Runs the tracker through a generated sequence
/// ("tracked") and solves each frame alone from its true pose ("alone"), and sorts every match
/// by where it lies against the true edge (the control point projected with the true pose,
/// along its normal): "right" within a pixel, "wrong" beyond. Prints per run the matches of
/// each kind and the share of each that the thin-line test calls a line.
///   tracking_eval_drift_profiles MODEL.cao SEQUENCE_DIR [BEYOND_PX RETURN_SHARE]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "edgetrack/grey_conversion.h"
#include "edgetrack/thin_lines.h"
#include "generated_sequence.h"

using namespace edgetrack;

namespace {

struct Tally {
  long right = 0, wrong = 0, right_lines = 0, wrong_lines = 0;

  void add(const std::vector<EdgeMatch>& matches, const vpImage<unsigned char>& grey, const PinholeCamera& camera,
           const Se3& truth, const ThinLineParams& params) {
    for (const EdgeMatch& m : matches) {
      const Vec2 edge = camera.project(truth * m.point.point_in_model);
      const double off = std::fabs(static_cast<double>(dot(m.point.normal, m.found - edge)));
      const bool line = on_thin_line(grey, m.found, m.point.normal, m.contrast < real(0), params);
      if (off <= 1.0) {
        ++right;
        right_lines += line;
      } else {
        ++wrong;
        wrong_lines += line;
      }
    }
  }
  void print(const char* name) const {
    std::printf("%s right=%ld wrong=%ld right_lines=%.3f wrong_lines=%.3f\n", name, right, wrong,
                right ? double(right_lines) / right : 0.0, wrong ? double(wrong_lines) / wrong : 0.0);
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: %s MODEL.cao SEQUENCE_DIR [BEYOND_PX RETURN_SHARE]\n", argv[0]);
    return 2;
  }
  GeneratedSequence sequence;
  if (!sequence.load(argv[0], argv[1], argv[2])) return 1;
  ThinLineParams params;
  if (argc == 5) {
    params.beyond_px = std::atoi(argv[3]);
    params.return_share = real(std::atof(argv[4]));
  }
  const TrackerConfig& config = sequence.config;
  // The matches the pose step alone tracks with, as they drift onto the lines: no drift check.
  TrackerParams unchecked = config.params;
  unchecked.thin_lines.check = DriftAction::kNone;
  TrackerParams from_truth = unchecked;
  from_truth.motion.start_frames = 0;
  Result<Tracker> tracked = Tracker::create(sequence.model, config.camera, sequence.truth[0], unchecked);
  Result<Tracker> alone = Tracker::create(sequence.model, config.camera, sequence.truth[0], from_truth);
  if (!tracked.ok() || !alone.ok()) return 1;
  Tally tracked_tally, alone_tally;
  vpImage<unsigned char> grey;
  for (size_t k = 0; k < sequence.truth.size(); ++k) {
    Result<edgetrack_app::FramePixels> pixels = sequence.frame(k);
    if (!pixels.ok()) break;
    const FrameView frame = pixels.value().view();
    grey.resize(frame.height, frame.width);
    convert_to_grey(frame, PixelBox{0, 0, frame.height, frame.width}, grey);
    if (!tracked.value().track(frame).ok()) return 1;
    tracked_tally.add(tracked.value().matches(), grey, config.camera, sequence.truth[k], params);
    alone.value().reset(sequence.truth[k]);
    if (!alone.value().track(frame).ok()) return 1;
    alone_tally.add(alone.value().matches(), grey, config.camera, sequence.truth[k], params);
  }
  tracked_tally.print("tracked");
  alone_tally.print("alone");
  return 0;
}
