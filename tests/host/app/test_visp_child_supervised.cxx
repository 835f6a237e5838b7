// SPDX-License-Identifier: BSD-3-Clause
/// compare's ViSP child under supervision, with fake children (shell scripts) in its place: one
/// that never answers is stopped at the frame's time limit, one that answers too slowly at the
/// run's; a NaN pose or a negative count is refused; a child killed by a signal is reported so,
/// one that exits is reported with its exit status and its last message, one that says nothing
/// as saying nothing; a well-behaved one is read.
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "testlib/testlib_test.h"
#include "visp_mbt_process.h"

using namespace edgetrack_app;

namespace {

/// A fake child: `body` after reading the 8-byte header and the 4x2 frame (16 bytes in all).
std::string fake_child(const std::string& name, const std::string& body) {
  const std::string path = std::string(APP_TEST_TMP) + "/" + name + ".sh";
  std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
  chmod(path.c_str(), 0755);
  return path;
}

/// One frame through the fake child: the Error's message, or "" when it answered well.
std::string first_frame(const std::string& child, const VispChildLimits& limits, VispFrameReply* reply = nullptr) {
  auto process = VispMbtProcess::start(child, "camera.xml", "model.cao", edgetrack::Se3(), 1, limits);
  if (!process.ok()) return "start: " + process.error().message;
  const unsigned char grey[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  auto answered = process.value()->track(edgetrack::packed_frame(grey, 4, 2, edgetrack::PixelLayout::kGrey8));
  if (answered.ok() && reply) *reply = answered.value();
  return answered.ok() ? "" : answered.error().message;
}

bool says(const std::string& message, const std::string& words) {
  std::printf("  message: %s\n", message.c_str());
  return message.find(words) != std::string::npos;
}

// A reply (visp_worker_protocol.h, little-endian): track_ms (double), features (int32), lost
// (int32), six doubles; `pose_x` the bytes of the first pose value.
std::string reply_printf(const std::string& features, const std::string& pose_x) {
  const std::string zero8 = "\\0\\0\\0\\0\\0\\0\\0\\0";
  return "head -c 16 >/dev/null; printf '" + zero8 + features + "\\0\\0\\0\\0" + pose_x + zero8 + zero8 + zero8 +
         zero8 + zero8 + "'; cat >/dev/null";
}

}  // namespace

static void test_visp_child_supervised() {
  const VispChildLimits quick{1.0, 60.0};
  const std::string nan_bytes = "\\0\\0\\0\\0\\0\\0\\370\\177";    // 0x7ff8000000000000
  const std::string one_bytes = "\\0\\0\\0\\0\\0\\0\\360\\77";     // 1.0
  const std::string features_6 = "\\6\\0\\0\\0", features_minus_5 = "\\373\\377\\377\\377";

  VispFrameReply reply;
  TEST("a child that answers well is read",
       first_frame(fake_child("good", reply_printf(features_6, one_bytes)), quick, &reply), std::string());
  TEST_NEAR("its pose's tx", reply.pose[0], 1.0, 0);
  TEST("its feature count", reply.features, 6);
  TEST("more features than the frame has pixels are refused",
       says(first_frame(fake_child("many", reply_printf("\\11\\0\\0\\0", one_bytes)), quick), "9 features"), true);

  TEST("a child that never answers is stopped at the frame's limit",
       says(first_frame(fake_child("silent", "exec sleep 100"), quick), "no answer within the frame's time limit (1 s)"), true);
  TEST("a child slower than the run's limit is stopped at it",
       says(first_frame(fake_child("slow", "exec sleep 100"), {30.0, 0.5}), "no answer within the run's time limit (0.5 s)"), true);
  TEST("a NaN pose is refused",
       says(first_frame(fake_child("nan", reply_printf(features_6, nan_bytes)), quick), "answered out of range (pose nan"), true);
  TEST("a negative feature count is refused",
       says(first_frame(fake_child("negative", reply_printf(features_minus_5, one_bytes)), quick), "-5 features"), true);
  TEST("a child killed by a signal is reported so",
       says(first_frame(fake_child("killed", "kill -SEGV $$"), quick), "killed by signal 11"), true);
  TEST("a child that exits is reported with its status and last message",
       says(first_frame(fake_child("exits", "echo 'ViSP refused camera.xml' >&2; exit 3"), quick),
            "ended with exit status 3: ViSP refused camera.xml"),
       true);
  TEST("a child that exits without a word is reported as saying nothing",
       says(first_frame(fake_child("mute", "exit 0"), quick), "exit status 0, saying nothing"), true);
  TEST("a program that cannot run is reported with the reason",
       says(first_frame(std::string(APP_TEST_TMP) + "/no-such-child", quick), "cannot run the program"), true);
}

TESTMAIN(test_visp_child_supervised)
