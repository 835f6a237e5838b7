// SPDX-License-Identifier: BSD-3-Clause
/// Helpers the subcommands share: error reporting, the data folder, pose and camera checks.
#include <cstdio>
#include <filesystem>

#include "commands.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

int report(const std::string& command, const Error& error) {
  std::fprintf(stderr, "edgetrack %s: %s\n", command.c_str(), error.text().c_str());
  return 1;
}

// An installed edgetrack reads the models installed with it (<prefix>/share/edgetrack beside
// <prefix>/bin); one run from its build tree reads the source tree's data/.
std::string data_dir() {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed = executable.parent_path() / EDGETRACK_INSTALLED_DATA_DIR;
    if (std::filesystem::is_directory(installed / "models", error)) return installed.lexically_normal().string();
  }
  return EDGETRACK_DATA_DIR;
}

Result<std::string> path_from_executable(const std::string& relative) {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return Error{"/proc/self/exe", 0, "cannot tell where edgetrack runs from: " + error.message()};
  return (executable.parent_path() / relative).lexically_normal().string();
}

Result<bool> check_in_front(const edgetrack::EdgeModel& model, const edgetrack::Se3& camera_from_model,
                            const std::string& source) {
  for (size_t i = 0; i < model.vertices.size(); ++i) {
    const edgetrack::Vec3 p = camera_from_model * model.vertices[i];
    if (p.z <= real(0.001)) {
      char text[160];
      std::snprintf(text, sizeof text, "the pose puts the model behind the camera (vertex %zu at Z = %.4f m)", i,
                    static_cast<double>(p.z));
      return Error{source, 0, text};
    }
  }
  return true;
}

Result<bool> write_text_file(const std::string& path, const std::string& text) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  bool ok = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

Result<bool> write_camera_xml(const std::string& path, const edgetrack::PinholeCamera& camera) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  bool ok = std::fprintf(file,
                         "<?xml version=\"1.0\"?>\n<conf>\n  <camera>\n    <u0>%.10g</u0>\n    <v0>%.10g</v0>\n"
                         "    <px>%.10g</px>\n    <py>%.10g</py>\n    <image_width>%d</image_width>\n"
                         "    <image_height>%d</image_height>\n  </camera>\n</conf>\n",
                         static_cast<double>(camera.u0), static_cast<double>(camera.v0), static_cast<double>(camera.px),
                         static_cast<double>(camera.py), camera.width, camera.height) > 0;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

Result<bool> write_visp_camera_file(const std::string& path, const edgetrack::PinholeCamera& camera) {
  return write_visp_camera_file(path, "Camera", camera, camera);
}

Result<bool> write_visp_camera_file(const std::string& path, const std::string& name,
                                    const edgetrack::PinholeCamera& without_distortion,
                                    const edgetrack::PinholeCamera& with_distortion) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  const auto model = [file](const char* type, const edgetrack::PinholeCamera& c) {
    return std::fprintf(file,
                        "    <model>\n      <type>%s</type>\n      <px>%.10g</px>\n      <py>%.10g</py>\n"
                        "      <u0>%.10g</u0>\n      <v0>%.10g</v0>\n",
                        type, static_cast<double>(c.px), static_cast<double>(c.py), static_cast<double>(c.u0),
                        static_cast<double>(c.v0)) > 0;
  };
  bool ok = std::fprintf(file,
                         "<?xml version=\"1.0\"?>\n<root>\n  <camera>\n    <name>%s</name>\n"
                         "    <image_width>%d</image_width>\n    <image_height>%d</image_height>\n",
                         name.c_str(), without_distortion.width, without_distortion.height) > 0;
  ok = model("perspectiveProjWithoutDistortion", without_distortion) && ok;
  ok = std::fprintf(file, "    </model>\n") > 0 && ok;
  if (with_distortion.lens.model == edgetrack::LensModel::kVisp) {
    ok = model("perspectiveProjWithDistortion", with_distortion) && ok;
    ok = std::fprintf(file, "      <kud>%.10g</kud>\n      <kdu>%.10g</kdu>\n    </model>\n",
                      static_cast<double>(with_distortion.lens.kud), static_cast<double>(with_distortion.lens.kdu)) > 0 &&
         ok;
  }
  ok = std::fprintf(file, "  </camera>\n</root>\n") > 0 && ok;
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

}  // namespace edgetrack_app
