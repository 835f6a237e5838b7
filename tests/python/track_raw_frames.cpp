// SPDX-License-Identifier: BSD-3-Clause
/// The C++ API on the very bytes a Python test handed the module: raw frame files (a row stride,
/// a layout) tracked by edgetrack::Tracker, each pose printed exactly (%a) for comparison.
/// usage: track_raw_frames MODEL CONFIG.xml INIT.pos LAYOUT WIDTH HEIGHT ROW_BYTES FILE...
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "edgetrack/edgetrack.h"

int main(int argc, char** argv) {
  if (argc < 9) return std::fprintf(stderr, "usage: %s MODEL CONFIG INIT LAYOUT W H ROW_BYTES FILE...\n", argv[0]), 2;
  auto model = edgetrack::load_model(argv[1]);
  edgetrack::TrackerConfig config;
  auto read = edgetrack::apply_visp_config(argv[2], config);
  auto initial = edgetrack::read_pos(argv[3]);
  if (!model.ok() || !read.ok() || !initial.ok()) return std::fprintf(stderr, "track_raw_frames: bad input\n"), 1;
  const std::string layout_text = argv[4];
  edgetrack::PixelLayout layout = edgetrack::PixelLayout::kGrey8;
  bool known = false;
  for (int k = 0; k < 64 && !known; ++k) {
    const auto candidate = static_cast<edgetrack::PixelLayout>(k);
    if (layout_text == edgetrack::layout_name(candidate)) layout = candidate, known = true;
  }
  if (!known) return std::fprintf(stderr, "track_raw_frames: unknown layout %s\n", argv[4]), 1;
  const int width = std::atoi(argv[5]), height = std::atoi(argv[6]), row_bytes = std::atoi(argv[7]);
  auto tracker = edgetrack::Tracker::create(model.value(), config.camera, initial.value(), config.params);
  if (!tracker.ok()) return std::fprintf(stderr, "track_raw_frames: %s\n", tracker.error().text().c_str()), 1;
  for (int i = 8; i < argc; ++i) {
    auto bytes = edgetrack::read_input_file(argv[i], std::size_t(1) << 28);
    if (!bytes.ok()) return std::fprintf(stderr, "track_raw_frames: %s\n", bytes.error().text().c_str()), 1;
    // Aligned storage: an RGB565 view needs 2-byte rows, as numpy's uint16 arrays have.
    std::vector<uint16_t> aligned((bytes.value().size() + 1) / 2);
    std::copy(bytes.value().begin(), bytes.value().end(), reinterpret_cast<uint8_t*>(aligned.data()));
    auto r = tracker.value().track({aligned.data(), width, height, row_bytes, layout});
    if (!r.ok()) return std::fprintf(stderr, "track_raw_frames: %s\n", r.error().text().c_str()), 1;
    const edgetrack::Se3& pose = r.value().camera_from_model;
    const edgetrack::Vec3& t = pose.translation();
    const double translation[3] = {double(t.x), double(t.y), double(t.z)};
    for (int row = 0; row < 3; ++row)
      std::printf("%a %a %a %a ", double(pose.rotation().m[row][0]), double(pose.rotation().m[row][1]),
                  double(pose.rotation().m[row][2]), translation[row]);
    std::printf("%s\n", edgetrack::status_name(r.value().status));
  }
  return 0;
}
