// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack templates`: makes the detector's templates for a model and a camera and writes them
/// to a file that `detect --templates` reads (docs/FORMATS.md).
#include <chrono>
#include <cstdio>

#include "args.h"
#include "atomic_output.h"
#include "commands.h"
#include "configuration.h"
#include "detection_options.h"
#include "edgetrack/detector/template_io.h"
#include "edgetrack/model_io.h"

using edgetrack::Error;

namespace edgetrack_app {

int templates_main(int argc, char** argv) {
  CommandLine line = {
      "templates",
      "--model FILE --camera FILE [--size WIDTHxHEIGHT] --out FILE [--cxx FILE] [range options]",
      {
          {"--model", "FILE", "model, .cao or .obj", ""},
          {"--camera", "FILE", "ViSP camera XML (with the image size, or give --size)", ""},
          {"--size", "WIDTHxHEIGHT", "image size when the XML has none", ""},
          {"--out", "FILE", "the template file to write", ""},
          {"--cxx", "FILE", "also a C++ source of them as constant data, for a firmware to link (docs/MCU.md)", ""},
      },
      {"--model", "--camera", "--out"},
      {},
      {},
  };
  for (const OptionSpec& spec : template_range_specs()) line.options.push_back(spec);
  for (const OptionSpec& spec : intrinsics_specs()) line.options.push_back(spec);
  Args a;
  if (auto stop = parse_command_line(line, argc, argv, a)) return *stop;
  std::vector<std::pair<std::string, std::string>> outputs = {{"--out", a.text("--out")}};
  if (a.has("--cxx")) outputs.push_back({"--cxx", a.text("--cxx")});
  if (auto empty = check_output_names(outputs)) return report("templates", *empty) + 1;
  int width = 0, height = 0;
  auto size = a.size("--size", width, height);
  if (!size.ok()) return report("templates", size.error()) + 1;
  auto params = template_params_from(a);
  if (!params.ok()) return report("templates", params.error()) + 1;
  auto model = edgetrack::load_model(a.text("--model"));
  if (!model.ok()) return report("templates", model.error());
  auto read = read_camera(a.text("--camera"), width, height);
  if (!read.ok()) return report("templates", read.error());
  auto camera = apply_intrinsics(a, read.value());
  if (!camera.ok()) return report("templates", camera.error());
  if (camera.value().width == 0 || camera.value().height == 0)
    return report("templates", {a.text("--camera"), 0, "the camera has no image size: give --size WIDTHxHEIGHT"});
  const auto start = std::chrono::steady_clock::now();
  auto set = edgetrack::make_template_set(model.value(), camera.value(), params.value());
  if (!set.ok()) return report("templates", {a.text("--model"), 0, set.error().message});
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  auto written = write_atomically(a.text("--out"), [&](const std::string& partial) {
    return edgetrack::write_templates(partial, set.value());
  });
  if (!written.ok()) return report("templates", written.error());
  if (a.has("--cxx")) {
    auto source = write_atomically(a.text("--cxx"), [&](const std::string& partial) {
      return edgetrack::write_template_source(partial, set.value());
    });
    if (!source.ok()) return report("templates", source.error());
  }
  std::printf("templates: %zu templates over %d distances, %zu features, %.2f MB in memory, made in %.0f ms; wrote %s\n",
              set.value().templates.size(), set.value().distance_count, set.value().features.size(),
              static_cast<double>(set.value().memory_bytes()) / (1 << 20), ms, a.text("--out").c_str());
  return 0;
}

}  // namespace edgetrack_app
