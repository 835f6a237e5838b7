// SPDX-License-Identifier: BSD-3-Clause
// Poses and ground-truth CSV files, and the evaluation of one against the other.
#include "evaluation.h"
#include "fuzz_input.h"
#include "pose_table.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = edgetrack_fuzz::scratch_file(data, size, "csv");
  auto poses = edgetrack_app::read_pose_table(path, edgetrack_app::kPosesHeader);
  auto truth = edgetrack_app::read_pose_table(path, edgetrack_app::kTruthHeader);
  edgetrack_fuzz::check_result(poses);
  edgetrack_fuzz::check_result(truth);
  // Each file evaluated against itself: a poses file as its own truth is read as truth too.
  if (poses.ok()) edgetrack_fuzz::check_result(edgetrack_app::evaluate(poses.value(), poses.value(), path));
  if (truth.ok()) edgetrack_fuzz::check_result(edgetrack_app::evaluate(truth.value(), truth.value(), path));
  return 0;
}
