// SPDX-License-Identifier: BSD-3-Clause
/// The child process running ViSP's tracker, behind two pipes.
#include "visp_mbt_process.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "commands.h"
#include "edgetrack/pose_io.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

Result<std::string> find_visp_worker() {
  auto found = path_from_executable(EDGETRACK_VISP_WORKER_FROM_BINDIR);
  if (!found.ok()) return found;
  const std::string worker = found.value();
  if (access(worker.c_str(), X_OK) != 0)
    return Error{worker, 0, "ViSP's tracker program is missing (it is installed with edgetrack compare, beside it)"};
  return worker;
}

Result<std::unique_ptr<VispMbtProcess>> VispMbtProcess::start(const std::string& worker, const std::string& xml,
                                                                const std::string& model,
                                                                const edgetrack::Se3& camera_from_model, int downscale,
                                                                const VispChildLimits& limits) {
  const edgetrack::Vec3 t = camera_from_model.translation();
  const edgetrack::Vec3 tu = edgetrack::rotation_log(camera_from_model.rotation());
  std::vector<std::string> args = {worker, xml, model};
  for (const real& v : {t.x, t.y, t.z, tu.x, tu.y, tu.z}) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", static_cast<double>(v));
    args.push_back(text);
  }
  args.push_back(std::to_string(downscale));
  std::FILE* messages = std::tmpfile();
  if (!messages) return Error{worker, 0, "cannot make a temporary file for its messages"};
  int down[2], up[2];
  if (pipe(down) != 0) {
    std::fclose(messages);
    return Error{worker, 0, "cannot create a pipe"};
  }
  if (pipe(up) != 0) {
    for (int fd : {down[0], down[1]}) close(fd);
    std::fclose(messages);
    return Error{worker, 0, "cannot create a pipe"};
  }
  std::signal(SIGPIPE, SIG_IGN);  // a child that ended is reported by track(), not by a signal
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    for (int fd : {down[0], down[1], up[0], up[1]}) close(fd);
    std::fclose(messages);
    return Error{worker, 0, "cannot start the process"};
  }
  if (pid == 0) {
    dup2(down[0], 0);
    dup2(up[1], 1);
    dup2(fileno(messages), 2);
    for (int fd : {down[0], down[1], up[0], up[1]}) close(fd);
    setenv("OMP_NUM_THREADS", "1", 1);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(&a[0]);
    argv.push_back(nullptr);
    execv(worker.c_str(), argv.data());
    std::fprintf(stderr, "cannot run the program: %s\n", std::strerror(errno));
    _exit(127);
  }
  close(down[0]);
  close(up[1]);
  return std::unique_ptr<VispMbtProcess>(new VispMbtProcess(worker, pid, down[1], up[0], messages, limits));
}

VispMbtProcess::~VispMbtProcess() {
  if (!ended_) {
    VispFrameHeader end;  // width 0: the end
    double left = limits_.frame_seconds;
    if (!timed_out_) transfer(true, &end, sizeof end, left);
    end_of_child("");
  }
  close(to_);
  close(from_);
  std::fclose(messages_);
}

bool VispMbtProcess::transfer(bool send, void* data, size_t bytes, double& frame_left) {
  char* at = static_cast<char*>(data);
  while (bytes > 0) {
    const double left = std::min(frame_left, limits_.run_seconds - run_used_);
    if (left <= 0) {
      timed_out_ = true;
      return false;
    }
    pollfd p{send ? to_ : from_, static_cast<short>(send ? POLLOUT : POLLIN), 0};
    const auto begin = std::chrono::steady_clock::now();
    const int ready = poll(&p, 1, static_cast<int>(std::ceil(left * 1000)));
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    frame_left -= waited;
    run_used_ += waited;
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return false;
    if (ready == 0) continue;  // the time left is checked above
    const ssize_t done = send ? write(to_, at, bytes) : read(from_, at, bytes);
    if (done < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (done <= 0) return false;
    at += done;
    bytes -= static_cast<size_t>(done);
  }
  return true;
}

std::string VispMbtProcess::end_of_child(const std::string& what) {
  ended_ = true;
  int status = 0;
  if (timed_out_) kill(pid_, SIGKILL);
  // A child that closed its pipe ends soon after; one that does not within the frame limit is stopped.
  for (double waited = 0; waitpid(pid_, &status, WNOHANG) == 0; waited += 0.01) {
    if (waited > limits_.frame_seconds) kill(pid_, SIGKILL);
    usleep(10000);
  }
  if (timed_out_) return what;
  std::string text = what;
  if (WIFSIGNALED(status)) {
    text += std::string("it was killed by signal ") + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  } else if (WIFEXITED(status)) {
    text += "it ended with exit status " + std::to_string(WEXITSTATUS(status));
  }
  // Its last message, if it left one.
  std::string line, last;
  std::rewind(messages_);
  for (int c; (c = std::fgetc(messages_)) != EOF;) {
    if (c != '\n') {
      line += static_cast<char>(c);
    } else if (!line.empty()) {
      last = line;
      line.clear();
    }
  }
  if (!line.empty()) last = line;
  return text + (last.empty() ? ", saying nothing" : ": " + last);
}

Result<VispFrameReply> VispMbtProcess::track(const edgetrack::FrameView& grey) {
  if (ended_) return Error{worker_, 0, "ViSP's tracker has already stopped"};
  VispFrameHeader header;
  header.width = grey.width;
  header.height = grey.height;
  VispFrameReply reply;
  const size_t bytes = static_cast<size_t>(grey.width) * grey.height;
  double frame_left = limits_.frame_seconds;
  const bool answered = transfer(true, &header, sizeof header, frame_left) &&
                        transfer(true, const_cast<void*>(grey.pixels), bytes, frame_left) &&
                        transfer(false, &reply, sizeof reply, frame_left);
  if (!answered && timed_out_) {
    char text[160];
    std::snprintf(text, sizeof text, "ViSP's tracker gave no answer within %s (%g s); stopped it",
                  frame_left <= 0 ? "the frame's time limit" : "the run's time limit",
                  frame_left <= 0 ? limits_.frame_seconds : limits_.run_seconds);
    return Error{worker_, 0, end_of_child(text)};
  }
  if (!answered) return Error{worker_, 0, end_of_child("ViSP's tracker stopped: ")};
  bool finite = std::isfinite(reply.track_ms) && reply.track_ms >= 0;
  for (int i = 0; i < 6; ++i)
    finite = finite && std::isfinite(reply.pose[i]) &&
             std::fabs(reply.pose[i]) <= (i < 3 ? edgetrack::kMaxPosTranslation : edgetrack::kMaxPosRotation);
  const bool counts = reply.features >= 0 && static_cast<size_t>(reply.features) <= bytes && (reply.lost == 0 || reply.lost == 1);
  if (!finite || !counts) {
    timed_out_ = true;  // stop it: its answers cannot be trusted
    char text[200];
    std::snprintf(text, sizeof text, "ViSP's tracker answered out of range (pose %g %g %g %g %g %g, %d features, lost %d, %g ms); stopped it",
                  reply.pose[0], reply.pose[1], reply.pose[2], reply.pose[3], reply.pose[4], reply.pose[5],
                  reply.features, reply.lost, reply.track_ms);
    return Error{worker_, 0, end_of_child(text)};
  }
  return reply;
}

}  // namespace edgetrack_app
