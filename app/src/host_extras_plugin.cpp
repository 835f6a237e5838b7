// SPDX-License-Identifier: BSD-3-Clause
/// The host extras plugin (edgetrack-host.so): the table of host_extras.h over the OpenCV and
/// OSMesa implementations linked into it.
#include "host_extras.h"

#include "plots.h"
#include "real/real_config.h"

extern "C" __attribute__((visibility("default"))) const edgetrack_app::HostExtras* edgetrack_host_extras() {
  using namespace edgetrack_app;
  static const HostExtras extras{EDGETRACK_REAL_NAME, EDGETRACK_VERSION,   read_image_any,
                                 write_image,         open_video_file,     open_camera_device,
                                 open_video_output,   write_plots,         make_overlay,
                                 make_gl_edge_id_source, click_initial_pose, host_commands};
  return &extras;
}
