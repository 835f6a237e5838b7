// SPDX-License-Identifier: BSD-3-Clause
/// The ViSP program `edgetrack track` is measured beside (tests/bench/startup): Debian's ViSP
/// vpMbGenericTracker in edge mode over numbered PGM frames, as a ViSP user writes it
/// (vpImageIo::read, loadConfigFile, loadModel, initFromPose, track), printing one pose a frame.
/// usage: visp_track_sequence CONFIG.xml MODEL.cao INIT.pos 'FRAMES%04d.pgm' LAST
#include <visp3/core/vpException.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/io/vpImageIo.h>
#include <visp3/mbt/vpMbGenericTracker.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: visp_track_sequence CONFIG.xml MODEL.cao INIT.pos 'FRAMES%%04d.pgm' LAST\n");
    return 2;
  }
  vpPoseVector initial;
  std::ifstream pos(argv[3]);
  for (int i = 0; i < 6; ++i) pos >> initial[i];
  if (!pos) return std::fprintf(stderr, "visp_track_sequence: %s: six numbers expected\n", argv[3]), 1;
  const int last = std::atoi(argv[5]);
  try {
    vpMbGenericTracker tracker(1, vpMbGenericTracker::EDGE_TRACKER);
    tracker.loadConfigFile(argv[1], false);
    tracker.loadModel(argv[2]);
    vpImage<unsigned char> frame;
    char path[4096];
    for (int index = 0; index <= last; ++index) {
      std::snprintf(path, sizeof path, argv[4], index);
      vpImageIo::read(frame, path);
      if (index == 0) tracker.initFromPose(frame, vpHomogeneousMatrix(initial));
      tracker.track(frame);
      const vpPoseVector pose(tracker.getPose());
      std::printf("%d %.6f %.6f %.6f %.6f %.6f %.6f\n", index, pose[0], pose[1], pose[2], pose[3], pose[4], pose[5]);
    }
  } catch (const vpException& e) {
    std::fprintf(stderr, "visp_track_sequence: %s\n", e.getMessage());
    return 1;
  }
  return 0;
}
