// SPDX-License-Identifier: BSD-3-Clause
/// Golden files of the tracking tests: one line per frame, the tracked camera position in the
/// model frame, "x y z" in metres, written by tracker_write_golden from a double build.
#pragma once

#include <string>
#include <vector>

#include "run_sequence.h"

namespace edgetrack_test {

constexpr int kGoldenFrames = 60;
/// The fast sequences (test_fast_motion.cxx): kFastFrames frames, every kFastSpeedUp-th pose.
constexpr int kFastFrames = 48;
constexpr int kFastSpeedUp = 5;

/// The reversal sequences (test_back_and_forth.cxx): the fast path's first kReversalTurn + 1
/// poses, then back over them to the first (2 kReversalTurn + 1 frames), reversing at once at
/// 13-14 px per QVGA frame.
constexpr int kReversalTurn = 39;
/// The spec of the scene's reversal sequence, and its golden file's name.
SequenceSpec reversal_spec(Scene scene);
std::string reversal_golden_name(Scene scene);

/// The edge hypotheses of the golden runs besides the default single one.
constexpr int kMultipleHypotheses = 3;

/// The covered sequences (test_field_conditions.cxx): kGoldenFrames frames, a board covering
/// this share of the object's image.
constexpr double kCoveredShare = 0.3;
/// The spec of the covered sequence, and its golden file's name.
SequenceSpec covered_spec();
std::string covered_golden_name(Scene scene);

/// The scene's golden file; `subsample` > 1 names the sped-up sequence's, `hypotheses` other
/// than the default (TrackerParams) that run's.
std::string golden_name(Scene scene, int subsample = 1, int hypotheses = edgetrack::TrackerParams{}.hypotheses);
bool write_golden(const std::string& path, const SequenceRun& run);
/// The positions in the file, or an empty vector when it cannot be read.
std::vector<edgetrack::Vec3> read_golden(const std::string& path);

/// The full poses beside a positions file ("<scene>_double_poses.txt" for
/// "<scene>_double_positions.txt"): per frame camera_from_model's translation (m) and rotation
/// matrix by rows, 12 numbers printed to the last bit of a double, for the double builds'
/// comparison at 1e-9 m and 1e-9 rad (golden_check.h).
std::string poses_golden_name(const std::string& positions_name);
struct GoldenPose {
  double translation[3];
  double rotation[9];
};
bool write_golden_poses(const std::string& path, const SequenceRun& run);
/// The poses in the file, or an empty vector when it cannot be read.
std::vector<GoldenPose> read_golden_poses(const std::string& path);

}  // namespace edgetrack_test
