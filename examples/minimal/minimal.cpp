// SPDX-License-Identifier: BSD-3-Clause
/// The smallest program on the installed edgetrack package: tracks a model through numbered PGM
/// frames and prints the pose and the result of each frame.
/// usage: minimal MODEL CAMERA.xml INIT.pos 'FRAMES%04d.pgm' [FIRST [LAST]]
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/tracker.h"

/// A binary PGM (P5, 8 bits) packed into RGB565, the tracker's frame layout.
static bool read_pgm(const std::string& path, int& width, int& height, std::vector<uint16_t>& rgb565) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxval = 0;
  if (!(in >> magic >> std::ws)) return false;
  while (in.peek() == '#') in.ignore(1 << 20, '\n');
  if (magic != "P5" || !(in >> width >> height >> maxval) || maxval != 255) return false;
  in.get();
  std::vector<unsigned char> grey(static_cast<size_t>(width) * height);
  if (!in.read(reinterpret_cast<char*>(grey.data()), grey.size())) return false;
  rgb565.resize(grey.size());
  for (size_t i = 0; i < grey.size(); ++i) rgb565[i] = ((grey[i] >> 3) << 11) | ((grey[i] >> 2) << 5) | (grey[i] >> 3);
  return true;
}

static int fail(const std::string& message) {
  std::fprintf(stderr, "minimal: %s\n", message.c_str());
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 5) return fail("usage: minimal MODEL CAMERA.xml INIT.pos 'FRAMES%04d.pgm' [FIRST [LAST]]");
  const int first = argc > 5 ? std::atoi(argv[5]) : 0, last = argc > 6 ? std::atoi(argv[6]) : 1 << 30;
  auto frame_path = [&](int index) {
    std::vector<char> path(std::string(argv[4]).size() + 32);
    std::snprintf(path.data(), path.size(), argv[4], index);
    return std::string(path.data());
  };
  int width = 0, height = 0;
  std::vector<uint16_t> frame;
  if (!read_pgm(frame_path(first), width, height, frame)) return fail(frame_path(first) + ": not an 8-bit PGM");

  auto model = edgetrack::load_model(argv[1]);
  auto camera = edgetrack::read_visp_camera_xml(argv[2], width, height);
  auto initial = edgetrack::read_pos(argv[3]);
  for (const edgetrack::Error* e : {&model.error(), &camera.error(), &initial.error()})
    if (!e->message.empty()) return fail(e->text());
  auto tracker = edgetrack::Tracker::create(model.value(), camera.value(), initial.value(), edgetrack::TrackerParams{});
  if (!tracker.ok()) return fail(tracker.error().text());

  for (int index = first; index <= last && read_pgm(frame_path(index), width, height, frame); ++index) {
    const edgetrack::FrameResult r = tracker.value().track(frame.data());
    const edgetrack::Vec3 t = r.camera_from_model.translation(), tu = r.camera_from_model.theta_u();
    std::printf("frame %d t %.6f %.6f %.6f tu %.6f %.6f %.6f matched %d/%d %s\n", index, double(t.x), double(t.y),
                double(t.z), double(tu.x), double(tu.y), double(tu.z), r.points_matched, r.points_sampled,
                r.pose.solved ? "solved" : "not-solved");
  }
  return 0;
}
