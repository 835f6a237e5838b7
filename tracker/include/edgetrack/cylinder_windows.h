// SPDX-License-Identifier: BSD-3-Clause
/// Where the inside of a cylinder's tessellated side can show: only through its two open ends.
/// The inscribed prism is convex, so from a camera outside it a viewing ray that meets a
/// back-facing facet has crossed a front-facing facet first, or an end. The back facets therefore
/// decide the nearest surface only inside the images of the two rims, and Edge-ID tests them
/// there alone: the same nearest surface with far fewer triangles under its lines.
#pragma once

#include "edgetrack/edge_model.h"
#include "edgetrack/pinhole_camera.h"
#include "edgetrack/raster.h"
#include "edgetrack/se3.h"

namespace edgetrack {

/// The boxes of the two rims (axis_a's, axis_b's) of cylinder `cylinder` of `model` projected with
/// camera_from_model, grown by a pixel beyond the rasteriser's 1/16-pixel rounding and clipped to
/// the image (a box may be empty). False when the argument above does not hold or the facets may
/// be clipped on their way to the screen: the camera within the radius of the axis, a facet
/// corner nearer than 2 cm or projecting more than 32 pixels outside the image (the rasteriser
/// clips at 1 cm and 64 pixels out). Then every back facet must be filled.
bool cylinder_rim_boxes(const EdgeModel& model, int cylinder, const PinholeCamera& camera,
                        const Se3& camera_from_model, PixelRect (&boxes)[2]);

}  // namespace edgetrack
