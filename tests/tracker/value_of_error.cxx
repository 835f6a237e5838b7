// SPDX-License-Identifier: BSD-3-Clause
// Result::value() on an error stops the program with the error's text, on each path a program
// reaches it by: the readers' results and the tracker's, read as const&, & and &&.
// usage: tracker_value_of_error read_pos|load_model|create|track|set_params   (never returns 0)
#include <cstdio>
#include <string>
#include <utility>

#include "edgetrack/edgetrack.h"

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "";
  const edgetrack::PinholeCamera camera{real(600), real(600), real(160),
                                        real(120), 320, 240};
  const edgetrack::Se3 pose(edgetrack::Mat33::identity(),
                            edgetrack::Vec3{real(0), real(0), real(1)});
  if (path == "read_pos") {
    const auto read = edgetrack::read_pos("/nonexistent/init.pos");
    std::printf("tz %g\n", static_cast<double>(read.value().translation().z));  // const&
  } else if (path == "load_model") {
    auto model = edgetrack::load_model("/nonexistent/model.cao");
    std::printf("vertices %zu\n", model.value().vertices.size());  // &
  } else if (path == "create" || path == "track") {
    auto model = edgetrack::load_model(EDGETRACK_DATA_DIR "/models/cube60.cao");
    const edgetrack::PinholeCamera bad_camera{real(0), real(600), real(160),
                                              real(120), 320, 240};
    auto tracker = edgetrack::Tracker::create(model.value(), path == "create" ? bad_camera : camera, pose,
                                              edgetrack::TrackerParams{});
    edgetrack::Tracker moved = std::move(tracker).value();  // &&
    const edgetrack::FrameView empty{};
    std::printf("pose z %g\n", static_cast<double>(moved.track(empty).value().camera_from_model.translation().z));
  } else {
    std::fprintf(stderr, "usage: tracker_value_of_error read_pos|load_model|create|track\n");
    return 2;
  }
  std::printf("value() returned\n");
  return 0;
}
