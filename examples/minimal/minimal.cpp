// SPDX-License-Identifier: BSD-3-Clause
/// The smallest program on the installed edgetrack package: tracks a model through numbered PGM
/// frames and prints the poses CSV that `edgetrack track --poses` writes (docs/FORMATS.md).
/// usage: minimal MODEL CAMERA.xml INIT.pos 'FRAMES%04d.pgm' [FIRST [LAST]]
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "edgetrack/edgetrack.h"

/// Frame `index` of a binary 8-bit PGM sequence: its grey bytes, which the tracker reads as they are.
static bool read_frame(const char* pattern, int index, int& width, int& height, std::vector<unsigned char>& grey) {
  char path[4096];
  std::snprintf(path, sizeof path, pattern, index);
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxval = 0;
  in >> magic >> std::ws;
  while (in.peek() == '#') in.ignore(1 << 20, '\n');
  if (magic != "P5" || !(in >> width >> height >> maxval) || maxval != 255 || in.get() == EOF) return false;
  grey.resize(static_cast<size_t>(width) * height);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(grey.data()), grey.size()));
}

int main(int argc, char** argv) {
  if (argc < 5) return std::fprintf(stderr, "usage: minimal MODEL CAMERA.xml INIT.pos 'FRAMES%%04d.pgm' [FIRST [LAST]]\n"), 2;
  const int first = argc > 5 ? std::atoi(argv[5]) : 0, last = argc > 6 ? std::atoi(argv[6]) : 1 << 30;
  int width = 0, height = 0;
  std::vector<unsigned char> frame;
  if (!read_frame(argv[4], first, width, height, frame)) return std::fprintf(stderr, "minimal: no 8-bit PGM frame %d\n", first), 1;

  auto model = edgetrack::load_model(argv[1]);
  edgetrack::TrackerConfig config;  // the camera and settings of a ViSP XML, as loadConfigFile reads it
  auto read = edgetrack::apply_visp_config(argv[2], config);
  auto initial = edgetrack::read_pos(argv[3]);
  for (const edgetrack::Error* e : {model.ok() ? nullptr : &model.error(), read.ok() ? nullptr : &read.error(),
                                    initial.ok() ? nullptr : &initial.error()})
    if (e) return std::fprintf(stderr, "minimal: %s\n", e->text().c_str()), 1;
  // A camera without an image size (as cube.xml's) takes the first frame's.
  auto tracker = edgetrack::Tracker::create(model.value(), config.camera, initial.value(), config.params);
  if (!tracker.ok()) return std::fprintf(stderr, "minimal: %s\n", tracker.error().text().c_str()), 1;

  std::printf("%s\n", edgetrack::kPosesCsvHeader);  // the poses CSV of `edgetrack track --poses`
  for (int index = first; index <= last && read_frame(argv[4], index, width, height, frame); ++index) {
    // Any camera layout goes the same way: RGB565, RGB24/BGR24, NV21 or I420, with a row stride.
    auto tracked = tracker.value().track({frame.data(), width, height, width, edgetrack::PixelLayout::kGrey8});
    if (!tracked.ok()) return std::fprintf(stderr, "minimal: frame %d: %s\n", index, tracked.error().text().c_str()), 1;
    std::printf("%s\n", edgetrack::poses_csv_line(edgetrack::poses_csv_row(index, tracked.value())).c_str());
  }
  return 0;
}
