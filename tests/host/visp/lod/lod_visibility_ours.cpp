// SPDX-License-Identifier: BSD-3-Clause
/// lod_visibility_upstream.cpp's output from edgetrack: the configuration applied, the model
/// loaded, a fresh FaceVisibility updated at each pose, then "kept POSE NAME visible|hidden" for each
/// named face, free line, cylinder and circle.
//   lod_visibility_ours CONFIG.xml MODEL.cao POSES WIDTH HEIGHT
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pose_lines.h"

#include "edgetrack/face_visibility.h"
#include "edgetrack/model_io.h"
#include "edgetrack/se3.h"
#include "edgetrack/visp_config.h"

using namespace edgetrack;

int main(int argc, char** argv) {
  if (argc != 6) return 2;
  TrackerConfig config;
  const Result<ConfigNotes> read = apply_visp_config(argv[1], config);
  const Result<EdgeModel> model = load_model(argv[2]);
  if (!read.ok() || !model.ok()) {
    std::fprintf(stderr, "%s\n", (!read.ok() ? read.error() : model.error()).text().c_str());
    return 1;
  }
  config.camera.width = std::atoi(argv[4]);
  config.camera.height = std::atoi(argv[5]);
  int index = 0;
  for (const auto& p : read_pose_lines(argv[3])) {
    const Se3 pose = Se3::from_theta_u({real(p[0]), real(p[1]), real(p[2])}, {real(p[3]), real(p[4]), real(p[5])});
    FaceVisibility visibility(model.value());
    visibility.update(model.value(), config.camera, pose, config.params.faces);
    for (size_t f = 0; f < model.value().faces.size(); ++f)
      std::printf("kept %d %s %s\n", index, model.value().faces[f].attributes.name.c_str(),
                  visibility.face_visible(static_cast<int>(f)) ? "visible" : "hidden");
    for (size_t e = 0; e < model.value().edges.size(); ++e) {
      const Edge& edge = model.value().edges[e];
      if (edge.faces[0] >= 0 || edge.faces[1] >= 0) continue;
      std::printf("kept %d %s %s\n", index, edge.attributes.name.c_str(),
                  visibility.edge_tracked(static_cast<int>(e)) ? "visible" : "hidden");
    }
    for (size_t c = 0; c < model.value().cylinders.size(); ++c)
      std::printf("kept %d %s %s\n", index, model.value().cylinders[c].attributes.name.c_str(),
                  visibility.edge_tracked(cylinder_primitive(model.value(), static_cast<int>(c), 0)) ? "visible"
                                                                                                   : "hidden");
    for (size_t k = 0; k < model.value().circles.size(); ++k)
      std::printf("kept %d %s %s\n", index, model.value().circles[k].attributes.name.c_str(),
                  visibility.edge_tracked(circle_primitive(model.value(), static_cast<int>(k))) ? "visible" : "hidden");
    ++index;
  }
  return 0;
}
