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

/// How long the child may take: for one frame (its answer after the frame was sent) and for the
/// whole run (every frame's wait added up). Past either, it is stopped and the run fails.
struct VispChildLimits {
  double frame_seconds = 30;
  double run_seconds = 3600;
};

/// The child, supervised: every wait is bounded by the limits, every answer is checked (a finite
/// pose in a .pos file's ranges, counts in range), and an end is reported as what it was (an
/// exit status with the child's last message, or the signal that killed it).
class VispMbtProcess {
 public:
  /// Starts `worker` on the XML and the model from camera_from_model; frames will be `downscale`
  /// times smaller than the ones the XML's camera describes. OMP_NUM_THREADS=1: one core each.
  /// The child's standard error goes to a temporary file, whose last line an error quotes.
  static edgetrack::Result<std::unique_ptr<VispMbtProcess>> start(const std::string& worker, const std::string& xml,
                                                                  const std::string& model,
                                                                  const edgetrack::Se3& camera_from_model, int downscale,
                                                                  const VispChildLimits& limits);
  ~VispMbtProcess();
  VispMbtProcess(const VispMbtProcess&) = delete;
  VispMbtProcess& operator=(const VispMbtProcess&) = delete;

  /// ViSP tracks `grey` (a packed grey8 frame); an Error naming the worker when it did not
  /// answer in time, answered out of range, or ended.
  edgetrack::Result<VispFrameReply> track(const edgetrack::FrameView& grey);

 private:
  VispMbtProcess(std::string worker, pid_t pid, int to_child, int from_child, std::FILE* messages,
                 const VispChildLimits& limits)
      : worker_(std::move(worker)), pid_(pid), to_(to_child), from_(from_child), messages_(messages),
        limits_(limits) {}
  /// Sends or receives `bytes` within the frame's and the run's time left; false on an end or a timeout.
  bool transfer(bool send, void* data, size_t bytes, double& frame_left);
  /// Stops the child (when it still runs) and says how it ended, for an Error.
  std::string end_of_child(const std::string& what);
  std::string worker_;
  pid_t pid_;
  int to_, from_;
  std::FILE* messages_;  ///< the child's standard error
  VispChildLimits limits_;
  double run_used_ = 0;  ///< seconds waited on the child so far
  bool timed_out_ = false;
  bool ended_ = false;
};

}  // namespace edgetrack_app
