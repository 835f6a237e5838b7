// SPDX-License-Identifier: BSD-3-Clause
/// The child process running ViSP's tracker, behind two pipes.
#include "visp_mbt_process.h"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <vector>

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

Result<std::string> find_visp_worker() {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return Error{"/proc/self/exe", 0, "cannot tell where edgetrack runs from: " + error.message()};
  const std::string worker =
      (executable.parent_path() / EDGETRACK_VISP_WORKER_FROM_BINDIR).lexically_normal().string();
  if (access(worker.c_str(), X_OK) != 0)
    return Error{worker, 0, "ViSP's tracker program is missing (it is installed with edgetrack compare, beside it)"};
  return worker;
}

Result<std::unique_ptr<VispMbtProcess>> VispMbtProcess::start(const std::string& worker, const std::string& xml,
                                                                const std::string& model,
                                                                const edgetrack::Se3& camera_from_model, int downscale) {
  const edgetrack::Vec3 t = camera_from_model.translation();
  const edgetrack::Vec3 tu = edgetrack::rotation_log(camera_from_model.rotation());
  std::vector<std::string> args = {worker, xml, model};
  for (const real& v : {t.x, t.y, t.z, tu.x, tu.y, tu.z}) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", static_cast<double>(v));
    args.push_back(text);
  }
  args.push_back(std::to_string(downscale));
  int down[2], up[2];
  if (pipe(down) != 0) return Error{worker, 0, "cannot create a pipe"};
  if (pipe(up) != 0) {
    close(down[0]);
    close(down[1]);
    return Error{worker, 0, "cannot create a pipe"};
  }
  std::signal(SIGPIPE, SIG_IGN);  // a child that ended is reported by track(), not by a signal
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return Error{worker, 0, "cannot start the process"};
  if (pid == 0) {
    dup2(down[0], 0);
    dup2(up[1], 1);
    for (int fd : {down[0], down[1], up[0], up[1]}) close(fd);
    setenv("OMP_NUM_THREADS", "1", 1);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(&a[0]);
    argv.push_back(nullptr);
    execv(worker.c_str(), argv.data());
    std::fprintf(stderr, "%s: cannot run the program\n", worker.c_str());
    _exit(127);
  }
  close(down[0]);
  close(up[1]);
  return std::unique_ptr<VispMbtProcess>(new VispMbtProcess(pid, fdopen(down[1], "wb"), fdopen(up[0], "rb")));
}

VispMbtProcess::~VispMbtProcess() {
  const VispFrameHeader end;
  std::fwrite(&end, sizeof end, 1, to_);
  std::fclose(to_);
  std::fclose(from_);
  int status = 0;
  waitpid(pid_, &status, 0);
}

Result<VispFrameReply> VispMbtProcess::track(const edgetrack::FrameView& grey) {
  VispFrameHeader header;
  header.width = grey.width;
  header.height = grey.height;
  VispFrameReply reply;
  const size_t bytes = static_cast<size_t>(grey.width) * grey.height;
  const bool sent = std::fwrite(&header, sizeof header, 1, to_) == 1 &&
                    std::fwrite(grey.pixels, 1, bytes, to_) == bytes && std::fflush(to_) == 0;
  if (!sent || std::fread(&reply, sizeof reply, 1, from_) != 1)
    return Error{"edgetrack-visp-mbt", 0, "ViSP's tracker stopped (its message is above)"};
  return reply;
}

}  // namespace edgetrack_app
