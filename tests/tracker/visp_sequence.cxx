// SPDX-License-Identifier: BSD-3-Clause
/// Tracking ViSP's mbt/cube frames in-process.
#include "visp_sequence.h"

#include <cstdio>
#include <fstream>

#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/visp_config.h"

using namespace edgetrack;

namespace edgetrack_test {
namespace {

/// An 8-bit binary PGM's grey bytes, or false.
bool read_pgm(const std::string& path, int& width, int& height, std::vector<unsigned char>& grey) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int max_value = 0;
  if (!(in >> magic >> width >> height >> max_value) || magic != "P5" || max_value != 255 || in.get() == EOF) return false;
  grey.resize(static_cast<size_t>(width) * height);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(grey.data()), static_cast<std::streamsize>(grey.size())));
}

}  // namespace

SequenceRun run_visp_cube(const std::string& visp_images, int frames,
                          const std::function<void(const Tracker&)>& after_frame,
                          const std::function<void(TrackerParams&)>& adjust, const std::string& model_file) {
  SequenceRun run;
  const std::string mbt = visp_images + "/mbt/";
  const Result<EdgeModel> model = load_model(mbt + model_file);
  TrackerConfig config;
  const auto read = apply_visp_config(mbt + "cube.xml", config);
  const Result<Se3> initial = read_pos(mbt + "cube.0.pos");
  if (!model.ok() || !read.ok() || !initial.ok()) {
    std::fprintf(stderr, "%s: %s, cube.xml or cube.0.pos cannot be read\n", mbt.c_str(), model_file.c_str());
    return run;
  }
  if (adjust) adjust(config.params);
  std::vector<unsigned char> grey;
  int width = 0, height = 0;
  const auto read_frame = [&](int k) {
    char name[32];
    std::snprintf(name, sizeof name, "cube/image%04d.pgm", k);
    const bool ok = read_pgm(mbt + name, width, height, grey);
    if (!ok) std::fprintf(stderr, "%s%s: not a readable 8-bit binary PGM\n", mbt.c_str(), name);
    return ok;
  };
  if (!read_frame(0)) return run;
  config.camera.width = width;  // cube.xml gives no image size: the frames give it
  config.camera.height = height;
  Result<Tracker> tracker = Tracker::create(model.value(), config.camera, initial.value(), config.params);
  if (!tracker.ok()) {
    std::fprintf(stderr, "%s\n", tracker.error().text().c_str());
    return run;
  }
  for (int k = 0; k < frames; ++k) {
    if (k > 0 && !read_frame(k)) return run;
    const Result<FrameResult> tracked = tracker.value().track(packed_frame(grey.data(), width, height, PixelLayout::kGrey8));
    if (!tracked.ok()) {
      std::fprintf(stderr, "frame %d: %s\n", k, tracked.error().text().c_str());
      return run;
    }
    run.frames.push_back(tracked.value());
    if (after_frame) after_frame(tracker.value());
  }
  run.loaded = true;
  return run;
}

}  // namespace edgetrack_test
