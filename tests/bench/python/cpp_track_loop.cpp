// SPDX-License-Identifier: BSD-3-Clause
/// The C++ side of the binding's cost: reads ViSP's mbt/cube frames FIRST..LAST into memory as
/// grey8, creates a tracker, tracks the first TRACKED of them through the C++ API and prints the
/// mean time of one track() call in microseconds (bench.py does the same from Python). Run with
/// TRACKED = 0 it does all but the tracking: the difference of two runs' instruction counts is
/// what the TRACKED calls cost (results.sh).
/// usage: cpp_track_loop MODEL CONFIG INIT PATTERN FIRST LAST TRACKED
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "edgetrack/edgetrack.h"

namespace {

/// An 8-bit binary PGM without comments, as ViSP's sequences are.
bool read_pgm(const std::string& path, int& width, int& height, std::vector<uint8_t>& pixels) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int top = 0;
  if (!(in >> magic >> width >> height >> top) || magic != "P5" || top != 255) return false;
  in.get();
  pixels.resize(static_cast<size_t>(width) * height);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size())));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 8) return std::fprintf(stderr, "usage: %s MODEL CONFIG INIT PATTERN FIRST LAST TRACKED\n", argv[0]), 2;
  auto model = edgetrack::load_model(argv[1]);
  edgetrack::TrackerConfig config;
  auto read = edgetrack::apply_visp_config(argv[2], config);
  auto initial = edgetrack::read_pos(argv[3]);
  if (!model.ok() || !read.ok() || !initial.ok()) return std::fprintf(stderr, "cpp_track_loop: bad inputs\n"), 1;
  std::vector<std::vector<uint8_t>> frames;
  int width = 0, height = 0;
  for (int index = std::atoi(argv[5]); index <= std::atoi(argv[6]); ++index) {
    char path[4096];
    std::snprintf(path, sizeof path, argv[4], index);
    frames.emplace_back();
    if (!read_pgm(path, width, height, frames.back())) return std::fprintf(stderr, "cpp_track_loop: %s\n", path), 1;
  }
  const size_t tracked = static_cast<size_t>(std::atoi(argv[7]));
  if (tracked > frames.size()) return std::fprintf(stderr, "cpp_track_loop: only %zu frames\n", frames.size()), 2;
  auto tracker = edgetrack::Tracker::create(model.value(), config.camera, initial.value(), config.params);
  if (!tracker.ok()) return std::fprintf(stderr, "cpp_track_loop: %s\n", tracker.error().text().c_str()), 1;
  long long ns = 0;
  for (size_t k = 0; k < tracked; ++k) {
    const auto begin = std::chrono::steady_clock::now();
    auto r = tracker.value().track(edgetrack::packed_frame(frames[k].data(), width, height, edgetrack::PixelLayout::kGrey8));
    ns += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - begin).count();
    if (!r.ok()) return std::fprintf(stderr, "cpp_track_loop: %s\n", r.error().text().c_str()), 1;
  }
  if (tracked > 0) std::printf("%.3f\n", ns / 1e3 / static_cast<double>(tracked));
  return 0;
}
