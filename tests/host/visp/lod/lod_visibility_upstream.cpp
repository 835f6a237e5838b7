// SPDX-License-Identifier: BSD-3-Clause
/// Which faces and lines Debian's ViSP 3.5 edge tracker keeps for a model with per-primitive
/// level-of-detail parameters: for each pose of POSES, a fresh vpMbEdgeTracker (configuration
/// loaded before the model, as ViSP's examples do) initialised at that pose on a blank image,
/// then "kept POSE NAME visible|hidden" for each of its polygons (but a cylinder's and a circle's,
/// named cylinder_* and circle_*) and for each cylinder and circle. lod_visibility_ours.cpp prints
/// the same from edgetrack.
//   lod_visibility_upstream CONFIG.xml MODEL.cao POSES WIDTH HEIGHT
#include <cstdio>
#include <cstdlib>
#include <list>
#include <string>

#include "pose_lines.h"

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/mbt/vpMbEdgeTracker.h>

int main(int argc, char** argv) {
  if (argc != 6) return 2;
  const unsigned int width = static_cast<unsigned int>(std::atoi(argv[4]));
  const unsigned int height = static_cast<unsigned int>(std::atoi(argv[5]));
  int index = 0;
  for (const auto& p : read_pose_lines(argv[3])) {
    const vpHomogeneousMatrix cMo(p[0], p[1], p[2], p[3], p[4], p[5]);
    vpMbEdgeTracker tracker;
    tracker.loadConfigFile(argv[1]);
    tracker.loadModel(argv[2]);
    vpImage<unsigned char> image(height, width, 128);
    tracker.initFromPose(image, cMo);
    vpMbHiddenFaces<vpMbtPolygon>& faces = tracker.getFaces();
    for (unsigned int i = 0; i < faces.size(); ++i) {
      const std::string name = faces[i]->getName();
      if (name.rfind("cylinder_", 0) == 0 || name.rfind("circle_", 0) == 0) continue;
      std::printf("kept %d %s %s\n", index, name.c_str(), faces[i]->isVisible() ? "visible" : "hidden");
    }
    std::list<vpMbtDistanceCylinder*> cylinders;
    tracker.getLcylinder(cylinders);
    for (const vpMbtDistanceCylinder* cylinder : cylinders)
      std::printf("kept %d %s %s\n", index, cylinder->getName().c_str(), cylinder->isVisible() ? "visible" : "hidden");
    std::list<vpMbtDistanceCircle*> circles;
    tracker.getLcircle(circles);
    for (const vpMbtDistanceCircle* circle : circles)
      std::printf("kept %d %s %s\n", index, circle->getName().c_str(), circle->isVisible() ? "visible" : "hidden");
    ++index;
  }
  return 0;
}
