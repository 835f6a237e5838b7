// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack compare`'s side of the pipe to `edgetrack-visp-mbt` (visp_worker_protocol.h): starts
/// the child with its settings, hands it one frame at a time and reads its answer.
#pragma once

#include <sys/types.h>

#include <cstdio>
#include <memory>
#include <string>

#include "edgetrack/result.h"
#include "edgetrack/se3.h"
#include "edgetrack/frame_view.h"
#include "visp_worker_protocol.h"

namespace edgetrack_app {

/// The child's program: edgetrack-visp-mbt where the installation (and the build tree) puts it,
/// relative to the running executable; an Error naming that path when it is not there.
edgetrack::Result<std::string> find_visp_worker();

class VispMbtProcess {
 public:
  /// Starts `worker` on the XML and the model from camera_from_model; frames will be `downscale`
  /// times smaller than the ones the XML's camera describes. OMP_NUM_THREADS=1: one core each.
  static edgetrack::Result<std::unique_ptr<VispMbtProcess>> start(const std::string& worker, const std::string& xml,
                                                                  const std::string& model,
                                                                  const edgetrack::Se3& camera_from_model, int downscale);
  ~VispMbtProcess();
  VispMbtProcess(const VispMbtProcess&) = delete;
  VispMbtProcess& operator=(const VispMbtProcess&) = delete;

  /// ViSP tracks `grey` (a packed grey8 frame); an Error (with what the child said on standard
  /// error) when it ended.
  edgetrack::Result<VispFrameReply> track(const edgetrack::FrameView& grey);

 private:
  VispMbtProcess(pid_t pid, std::FILE* to_child, std::FILE* from_child) : pid_(pid), to_(to_child), from_(from_child) {}
  pid_t pid_;
  std::FILE* to_;
  std::FILE* from_;
};

}  // namespace edgetrack_app
