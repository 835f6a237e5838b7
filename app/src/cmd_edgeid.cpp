// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack edgeid` (host): the portable Edge-ID against Edge-ID through GL (OSMesa, RGB565
/// colour buffer) over the poses of a sequence, and the paper's colour-approximation finding
/// measured through GL: how many edge IDs come back wrong with the naive byte code and with the
/// 8-level code.
#include <cstdio>

#include "args.h"
#include "commands.h"
#include "configuration.h"
#include "edgetrack/control_points.h"
#include "edgetrack/edge_id_buffer.h"
#include "edgetrack/model_io.h"
#include "gl_edge_id.h"
#include "pose_table.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {

int edgeid_main(int argc, char** argv) {
  const CommandLine line = {
      "edgeid",
      "--model FILE --camera FILE [--size WIDTHxHEIGHT] --poses FILE",
      {
          {"--model", "FILE", "model, .cao or .obj", ""},
          {"--camera", "FILE", "ViSP camera XML", ""},
          {"--size", "WIDTHxHEIGHT", "image size when the XML has none", ""},
          {"--poses", "FILE", "poses (edgetrack track) or ground truth (edgetrack synth) CSV", ""},
      },
      {"--model", "--camera", "--poses"},
      {},
      {},
  };
  Args a;
  if (auto stop = parse_command_line(line, argc, argv, a)) return *stop;
  int width = 0, height = 0;
  auto size = a.size("--size", width, height);
  if (!size.ok()) return report("edgeid", size.error()) + 1;
  auto model = edgetrack::load_model(a.text("--model"));
  if (!model.ok()) return report("edgeid", model.error());
  auto camera = read_camera(a.text("--camera"), width, height);
  if (!camera.ok()) return report("edgeid", camera.error());
  auto rows = read_pose_table(a.text("--poses"), kPosesHeader);
  if (!rows.ok()) rows = read_pose_table(a.text("--poses"), kTruthHeader);
  if (!rows.ok()) return report("edgeid", rows.error());
  auto gl = GlEdgeIdBuffer::create(camera.value());
  if (!gl.ok()) return report("edgeid", gl.error());

  // Visibility of every candidate control point, portable rasteriser against GL.
  edgetrack::EdgeIdBuffer soft(camera.value());
  long points = 0, soft_visible = 0, gl_visible = 0, agree = 0;
  for (const PoseRow& row : rows.value()) {
    const edgetrack::Se3 pose = pose_of(row);
    soft.render(model.value(), pose);
    gl.value()->render(model.value(), pose);
    for (const edgetrack::ControlPoint& p :
         edgetrack::sample_control_points(model.value(), camera.value(), pose, edgetrack::SamplingParams{})) {
      const bool s = soft.shows(p.edge, p.pixel, p.direction), g = gl.value()->shows(p.edge, p.pixel, p.direction);
      ++points;
      soft_visible += s;
      gl_visible += g;
      agree += s == g;
    }
  }
  const double agreement = points ? 100.0 * agree / points : 0.0;
  std::printf("visibility over %zu frames: %ld control points, %ld visible by the portable Edge-ID, %ld by GL; "
              "they agree on %ld (%.2f %%)\n",
              rows.value().size(), points, soft_visible, gl_visible, agree, agreement);

  // Colour approximation: every edge ID the code can name, through a GL RGB565 buffer.
  const int ids = std::min(edgetrack::kMaxEdges, camera.value().width * camera.value().height);
  std::vector<edgetrack::Rgb888> naive(ids), levels(ids);
  for (int i = 0; i < ids; ++i) {
    naive[i] = edgetrack::encode_edge_id_naive(i);
    levels[i] = edgetrack::encode_edge_id(i);
  }
  const std::vector<uint16_t> naive_back = gl.value()->draw_colours(naive);
  long naive_wrong = 0, levels_wrong = 0, levels_soft_wrong = 0;
  for (int i = 0; i < ids; ++i) naive_wrong += edgetrack::decode_edge_id_naive(edgetrack::unpack_rgb565(naive_back[i])) != i;
  const std::vector<uint16_t> levels_back = gl.value()->draw_colours(levels);
  for (int i = 0; i < ids; ++i) {
    levels_wrong += edgetrack::decode_edge_id(edgetrack::unpack_rgb565(levels_back[i])) != i;
    levels_soft_wrong += edgetrack::decode_edge_id(edgetrack::unpack_rgb565(edgetrack::pack_rgb565(levels[i]))) != i;
  }
  std::printf("colour approximation over %d edge IDs written by GL into RGB565 and decoded: naive byte code %ld wrong "
              "(%.2f %%), 8-level code %ld wrong (%.2f %%); 8-level code packed by the portable rasteriser %ld wrong\n",
              ids, naive_wrong, 100.0 * naive_wrong / ids, levels_wrong, 100.0 * levels_wrong / ids, levels_soft_wrong);
  std::printf("edgeid: points=%ld agree_percent=%.3f naive_wrong=%ld levels_wrong=%ld ids=%d\n", points, agreement,
              naive_wrong, levels_wrong, ids);
  return 0;
}

}  // namespace edgetrack_app
