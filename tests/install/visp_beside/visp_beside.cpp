// SPDX-License-Identifier: BSD-3-Clause
/// Real ViSP and edgetrack in one translation unit: frames read by ViSP's vpImageIo into ViSP's
/// vpImage, tracked by edgetrack through its own plain types, each pose handed back to ViSP as a
/// vpHomogeneousMatrix and printed from it, as `frame N tx ty tz tux tuy tuz`.
/// usage: visp_beside MODEL CAMERA.xml INIT.pos 'FRAMES%04d.pgm' FIRST LAST
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/io/vpImageIo.h>

#include <cstdio>
#include <cstdlib>

#include "edgetrack/edgetrack.h"

/// edgetrack's pose as ViSP's matrix.
static vpHomogeneousMatrix to_visp(const edgetrack::Se3& pose) {
  vpHomogeneousMatrix cMo;
  for (unsigned int i = 0; i < 3; ++i) {
    for (unsigned int j = 0; j < 3; ++j) cMo[i][j] = static_cast<double>(pose.rotation().m[i][j]);
  }
  cMo[0][3] = static_cast<double>(pose.translation().x);
  cMo[1][3] = static_cast<double>(pose.translation().y);
  cMo[2][3] = static_cast<double>(pose.translation().z);
  return cMo;
}

int main(int argc, char** argv) {
  if (argc != 7) return std::fprintf(stderr, "usage: visp_beside MODEL CAMERA.xml INIT.pos 'FRAMES%%04d.pgm' FIRST LAST\n"), 2;
  const int first = std::atoi(argv[5]), last = std::atoi(argv[6]);
  char path[4096];
  vpImage<unsigned char> I;
  std::snprintf(path, sizeof path, argv[4], first);
  vpImageIo::read(I, path);

  auto model = edgetrack::load_model(argv[1]);
  if (!model.ok()) return std::fprintf(stderr, "visp_beside: %s\n", model.error().text().c_str()), 1;
  edgetrack::TrackerConfig config;
  auto read = edgetrack::apply_visp_config(argv[2], config);
  if (!read.ok()) return std::fprintf(stderr, "visp_beside: %s\n", read.error().text().c_str()), 1;
  auto initial = edgetrack::read_pos(argv[3]);
  if (!initial.ok()) return std::fprintf(stderr, "visp_beside: %s\n", initial.error().text().c_str()), 1;
  config.camera.width = static_cast<int>(I.getWidth());
  config.camera.height = static_cast<int>(I.getHeight());
  auto tracker = edgetrack::Tracker::create(model.value(), config.camera, initial.value(), config.params);
  if (!tracker.ok()) return std::fprintf(stderr, "visp_beside: %s\n", tracker.error().text().c_str()), 1;

  for (int index = first; index <= last; ++index) {
    std::snprintf(path, sizeof path, argv[4], index);
    vpImageIo::read(I, path);
    const edgetrack::FrameView frame = edgetrack::packed_frame(I.bitmap, static_cast<int>(I.getWidth()),
                                                               static_cast<int>(I.getHeight()),
                                                               edgetrack::PixelLayout::kGrey8);
    auto tracked = tracker.value().track(frame);
    if (!tracked.ok()) return std::fprintf(stderr, "visp_beside: %s: %s\n", path, tracked.error().text().c_str()), 1;
    const vpHomogeneousMatrix cMo = to_visp(tracked.value().camera_from_model);
    const vpTranslationVector t = cMo.getTranslationVector();
    const vpThetaUVector tu = cMo.getThetaUVector();
    std::printf("frame %d %.9f %.9f %.9f %.9f %.9f %.9f\n", index, t[0], t[1], t[2], tu[0], tu[1], tu[2]);
  }
  return 0;
}
