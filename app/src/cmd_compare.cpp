// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack compare` (host, with Debian's ViSP): our tracker and ViSP's vpMbGenericTracker in
/// edge mode on the same grey frames, from the same XML, model and initial pose, the two
/// alternating frame by frame so that both see the same load. Times the tracking calls only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "args.h"
#include "commands.h"
#include "configuration.h"
#include "downscaled_tracking.h"
#include "edgetrack/grey_conversion.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/tracker.h"
#include "evaluation.h"
#include "frame_source.h"
#include "pose_table.h"
#include "visp_mbt_process.h"

using edgetrack::Error;
using edgetrack::PinholeCamera;
using edgetrack::Result;
using edgetrack::Se3;

namespace edgetrack_app {
namespace {

const char* const kSynopsis =
    "--model FILE --camera FILE --init-pose FILE --images PATTERN|DIR [--first N] [--last N] [--truth FILE|DIR] "
    "[--repeat N] [--csv FILE] [--downscale N]";

/// One tracker's frames: its poses (with points, ms and lost) in frame order.
struct Run {
  std::vector<PoseRow> rows;
};

/// What both runs share: the inputs, already read and checked.
struct Setup {
  std::string xml, model_path;
  edgetrack::EdgeModel model;
  PinholeCamera camera;  ///< at the tracked size
  edgetrack::TrackerParams params;
  Se3 initial;
  SourceOptions source;
  int factor = 1;
  VispChildLimits limits;
};

/// Our tracker's camera and settings from the XML that ViSP's loadConfigFile reads (the same
/// reader as track's --camera); the image size from the file or else width x height.
Result<bool> ours_from_visp_xml(const std::string& xml, int width, int height, PinholeCamera& camera,
                                edgetrack::TrackerParams& params) {
  auto read = read_configuration(xml, "");
  if (!read.ok()) return read.error();
  camera = read.value().config.camera;
  if (camera.width == 0) camera.width = width;
  if (camera.height == 0) camera.height = height;
  params = read.value().config.params;
  return true;
}

/// Whether our tracker lost the frame, as its status says.
bool ours_lost(const edgetrack::FrameResult& result) { return result.status == edgetrack::TrackingStatus::kLost; }

PoseRow row_of(int frame, const Se3& pose, int points, double ms, bool lost) {
  PoseRow row = pose_row(frame, pose);
  row.points = points;
  row.ms = ms;
  row.lost = lost;
  return row;
}

/// The frame both trackers get: grey, converted once here, outside both timed calls, by our
/// tracker's rule (vpImageConvert's), so that neither time holds a colour conversion that the
/// other does untimed. A packed grey frame is its own grey image.
edgetrack::FrameView grey_frame(const edgetrack::FrameView& view, vpImage<unsigned char>& grey) {
  if (view.layout == edgetrack::PixelLayout::kGrey8 && view.row_bytes == view.width) return view;
  grey.resize(static_cast<unsigned>(view.height), static_cast<unsigned>(view.width));
  edgetrack::PixelBox whole;
  whole.bottom = view.height;
  whole.right = view.width;
  edgetrack::convert_to_grey(view, whole, grey);
  return edgetrack::packed_frame(grey.bitmap, view.width, view.height, edgetrack::PixelLayout::kGrey8);
}

/// One pass over the sequence: each frame goes to ViSP and to ours, the first one alternating.
Result<bool> run_once(const Setup& setup, const std::string& worker, Run& ours, Run& visp) {
  auto source = open_frame_source(setup.source);
  if (!source.ok()) return source.error();
  auto tracker = edgetrack::Tracker::create(setup.model, setup.camera, setup.initial, setup.params);
  if (!tracker.ok()) return tracker.error();
  auto child = VispMbtProcess::start(worker, setup.xml, setup.model_path, setup.initial, setup.factor, setup.limits);
  if (!child.ok()) return child.error();
  ours.rows.clear();
  visp.rows.clear();
  Frame frame;
  vpImage<unsigned char> grey;
  for (int k = 0;; ++k) {
    auto got = source.value()->next(frame);
    if (!got.ok()) return got.error();
    if (!got.value()) break;
    if (frame.pixels.width != setup.camera.width * setup.factor || frame.pixels.height != setup.camera.height * setup.factor)
      return Error{frame.name, 0, "image size does not match the first frame's"};
    FramePixels small;
    const edgetrack::FrameView view = grey_frame(tracked_frame(frame.pixels, setup.factor, small), grey);
    VispFrameReply reply;
    for (int turn = 0; turn < 2; ++turn) {
      if ((turn + k) % 2 == 0) {
        auto answered = child.value()->track(view);
        if (!answered.ok())
          return Error{answered.error().file, 0, frame.name + ": " + answered.error().message};
        reply = answered.value();
      } else {
        const auto begin = std::chrono::steady_clock::now();
        auto tracked = tracker.value().track(view);
        if (!tracked.ok()) return Error{frame.name, 0, tracked.error().message};
        const edgetrack::FrameResult& result = tracked.value();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
        ours.rows.push_back(row_of(frame.index, result.camera_from_model, result.points_matched, ms, ours_lost(result)));
      }
    }
    PoseRow row;
    for (int i = 0; i < 3; ++i) row.t[i] = reply.pose[i], row.tu[i] = reply.pose[3 + i];
    visp.rows.push_back(row_of(frame.index, pose_of(row), reply.features, reply.track_ms, reply.lost != 0));
  }
  return true;
}

/// The mean distance in pixels between the model's vertices projected with each pose.
double corner_difference(const edgetrack::EdgeModel& model, const PinholeCamera& camera, const Se3& a, const Se3& b) {
  double sum = 0;
  int counted = 0;
  for (const edgetrack::Vec3& v : model.vertices) {
    const edgetrack::Vec3 pa = a * v, pb = b * v;
    if (pa.z <= real(0) || pb.z <= real(0)) continue;
    const edgetrack::Vec2 d = camera.project(pa) - camera.project(pb);
    sum += std::hypot(static_cast<double>(d.x), static_cast<double>(d.y));
    ++counted;
  }
  return counted > 0 ? sum / counted : 0.0;
}

struct Summary {
  double median_ms = 0, mean_ms = 0, points = 0;
  int lost = 0;
};

Summary summarise(const std::vector<double>& ms_all, const Run& run) {
  Summary s;
  std::vector<double> ms = ms_all;
  std::sort(ms.begin(), ms.end());
  if (!ms.empty()) s.median_ms = ms.size() % 2 ? ms[ms.size() / 2] : (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]) / 2;
  for (double m : ms) s.mean_ms += m / ms.size();
  for (const PoseRow& r : run.rows) {
    s.points += static_cast<double>(r.points) / run.rows.size();
    s.lost += r.lost ? 1 : 0;
  }
  return s;
}

Result<bool> write_csv(const std::string& path, const Setup& setup, const Run& ours, const Run& visp) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  std::fprintf(file, "frame,ours_ms,visp_ms,ours_points,visp_points,ours_lost,visp_lost,corner_px,"
                     "ours_tx,ours_ty,ours_tz,ours_tux,ours_tuy,ours_tuz,visp_tx,visp_ty,visp_tz,visp_tux,visp_tuy,visp_tuz\n");
  for (size_t k = 0; k < ours.rows.size(); ++k) {
    const PoseRow &o = ours.rows[k], &v = visp.rows[k];
    std::fprintf(file, "%d,%.4f,%.4f,%d,%d,%d,%d,%.4f", o.frame, o.ms, v.ms, o.points, v.points, o.lost ? 1 : 0,
                 v.lost ? 1 : 0, corner_difference(setup.model, setup.camera, pose_of(o), pose_of(v)));
    for (const PoseRow* r : {&o, &v})
      std::fprintf(file, ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", r->t[0], r->t[1], r->t[2], r->tu[0], r->tu[1], r->tu[2]);
    std::fprintf(file, "\n");
  }
  if (std::fclose(file) != 0) return Error{path, 0, "write failed"};
  return true;
}

/// The table, and one `compare:` line of key=value for scripts.
Result<bool> print_results(const Setup& setup, const Run& ours, const Run& visp, const std::vector<double>& ours_ms,
                           const std::vector<double>& visp_ms, const std::string& truth_path) {
  const Summary s[2] = {summarise(ours_ms, ours), summarise(visp_ms, visp)};
  const char* names[2] = {"edgetrack", "ViSP vpMbGenericTracker (edge)"};
  const char* keys[2] = {"ours", "visp"};
  Evaluation e[2];
  if (!truth_path.empty()) {
    auto truth = read_truth(truth_path);
    if (!truth.ok()) return truth.error();
    for (int i = 0; i < 2; ++i) {
      auto evaluated = evaluate(i == 0 ? ours.rows : visp.rows, truth.value(), truth_path);
      if (!evaluated.ok()) return evaluated.error();
      e[i] = evaluated.value();
    }
  }
  double corner = 0, corner_max = 0;
  for (size_t k = 0; k < ours.rows.size(); ++k) {
    const double d = corner_difference(setup.model, setup.camera, pose_of(ours.rows[k]), pose_of(visp.rows[k]));
    corner += d / ours.rows.size();
    corner_max = std::max(corner_max, d);
  }
  std::printf("%zu frames of %dx%d, %zu timed per tracker, real = %s\n\n", ours.rows.size(), setup.camera.width,
              setup.camera.height, ours_ms.size(), real_name());
  std::printf("| tracker | median ms | mean ms | control points | lost |%s\n|---|---:|---:|---:|---:|%s\n",
              truth_path.empty() ? "" : " x mm | y mm | z mm | distance mm | largest mm | rotation deg |",
              truth_path.empty() ? "" : "---:|---:|---:|---:|---:|---:|");
  for (int i = 0; i < 2; ++i) {
    std::printf("| %s | %.3f | %.3f | %.1f | %d |", names[i], s[i].median_ms, s[i].mean_ms, s[i].points, s[i].lost);
    if (!truth_path.empty())
      std::printf(" %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |", e[i].mean_abs_mm[0], e[i].mean_abs_mm[1],
                  e[i].mean_abs_mm[2], e[i].mean_distance_mm, e[i].max_distance_mm, e[i].mean_rotation_deg);
    std::printf("\n");
  }
  std::printf("\npose difference: mean corner reprojection difference %.3f px (largest %.3f px)\n", corner, corner_max);
  std::printf("compare: frames=%zu corner_px=%.4f corner_max_px=%.4f", ours.rows.size(), corner, corner_max);
  for (int i = 0; i < 2; ++i) {
    std::printf(" %s_median_ms=%.4f %s_mean_ms=%.4f %s_points=%.2f %s_lost=%d", keys[i], s[i].median_ms, keys[i],
                s[i].mean_ms, keys[i], s[i].points, keys[i], s[i].lost);
    if (!truth_path.empty())
      std::printf(" %s_distance_mm=%.4f %s_max_distance_mm=%.4f %s_rotation_deg=%.4f", keys[i], e[i].mean_distance_mm,
                  keys[i], e[i].max_distance_mm, keys[i], e[i].mean_rotation_deg);
  }
  std::printf("\n");
  return true;
}

/// Reads and checks the inputs: the model, the initial pose, the first frame's size, the XML.
Result<Setup> read_setup(const Args& a, const SourceOptions& source, int factor, const VispChildLimits& limits) {
  Setup setup;
  setup.limits = limits;
  setup.source = source;
  setup.xml = a.text("--camera");
  setup.model_path = a.text("--model");
  setup.factor = factor;
  auto model = edgetrack::load_model(setup.model_path);
  if (!model.ok()) return model.error();
  setup.model = model.value();
  auto initial = edgetrack::read_pos(a.text("--init-pose"));
  if (!initial.ok()) return initial.error();
  setup.initial = initial.value();
  auto in_front = check_in_front(setup.model, setup.initial, a.text("--init-pose"));
  if (!in_front.ok()) return in_front.error();
  auto frames = open_frame_source(setup.source);
  if (!frames.ok()) return frames.error();
  Frame first;
  auto got = frames.value()->next(first);
  if (!got.ok()) return got.error();
  PinholeCamera camera;
  auto configured = ours_from_visp_xml(setup.xml, first.pixels.width, first.pixels.height, camera, setup.params);
  if (!configured.ok()) return configured.error();
  if (camera.width != first.pixels.width || camera.height != first.pixels.height)
    return Error{first.name, 0, "image size does not match the camera's (" + setup.xml + ")"};
  setup.camera = edgetrack::downscaled_camera(camera, factor);
  downscale_settings(setup.params, factor);
  return setup;
}

int compare_main(int argc, char** argv) {
  const CommandLine line = {
      "compare",
      kSynopsis,
      {
          {"--model", "FILE", "model, ViSP .cao (both trackers load it)", ""},
          {"--camera", "FILE", "ViSP XML: ViSP's loadConfigFile reads it, ours its <camera> and <ecm>", ""},
          {"--init-pose", "FILE", "initial camera_from_model, a ViSP pose file: .pos (6 numbers) or a 4x4 homogeneous matrix", ""},
          {"--images", "PATTERN|DIR", "printf pattern (seq/frame%04d.pgm) or directory", ""},
          {"--first", "N", "first frame number (default: 0, or 1 when a pattern has no frame 0)", ""},
          {"--last", "N", "last frame number, inclusive (default: the last frame)", ""},
          {"--truth", "FILE|DIR", "ground truth as eval --truth reads it: errors of each tracker", ""},
          {"--repeat", "N", "run the sequence N times for the timings; poses from the last run", "1"},
          {"--csv", "FILE", "write per-frame times, points, lost flags, corner difference and both poses", ""},
          {"--downscale", "N", "track frames N times smaller (640x480 -> QVGA with 2), both trackers", "1"},
          {"--visp-frame-limit", "SECONDS", "the longest ViSP's tracker may take on one frame before compare stops it", "30"},
          {"--visp-run-limit", "SECONDS", "the longest ViSP's tracker may take on a whole run before compare stops it",
           "3600"},
      },
      {"--model", "--camera", "--init-pose", "--images"},
      {},
      {},
  };
  Args a;
  if (auto stop = parse_command_line(line, argc, argv, a)) return *stop;
  auto first = a.frame_number("--first"), last = a.frame_number("--last");
  auto repeat = a.integer("--repeat"), factor = a.integer("--downscale");
  auto frame_limit = a.number("--visp-frame-limit"), run_limit = a.number("--visp-run-limit");
  for (const Error* bad : {&first.error(), &last.error(), &repeat.error(), &factor.error(), &frame_limit.error(),
                           &run_limit.error()})
    if (!bad->message.empty()) return report("compare", *bad) + 1;
  if (!(frame_limit.value() > 0) || !(run_limit.value() > 0))
    return report("compare", {"", 0, "--visp-frame-limit and --visp-run-limit must be positive"}) + 1;
  if (repeat.value() < 1) return report("compare", {"", 0, "--repeat must be positive"}) + 1;
  if (factor.value() < 1 || factor.value() > 8) return report("compare", {"", 0, "--downscale must be 1..8"}) + 1;
  SourceOptions source;
  source.images = a.text("--images");
  source.first = first.value();
  source.last = last.value();
  auto setup = read_setup(a, source, factor.value(), {frame_limit.value(), run_limit.value()});
  if (!setup.ok()) return report("compare", setup.error());
  auto worker = find_visp_worker();
  if (!worker.ok()) return report("compare", worker.error());
  Run ours, visp;
  std::vector<double> ours_ms, visp_ms;
  for (int r = 0; r < repeat.value(); ++r) {
    auto ran = run_once(setup.value(), worker.value(), ours, visp);
    if (!ran.ok()) return report("compare", ran.error());
    for (const PoseRow& row : ours.rows) ours_ms.push_back(row.ms);
    for (const PoseRow& row : visp.rows) visp_ms.push_back(row.ms);
  }
  if (a.has("--csv")) {
    auto written = write_csv(a.text("--csv"), setup.value(), ours, visp);
    if (!written.ok()) return report("compare", written.error());
  }
  auto printed = print_results(setup.value(), ours, visp, ours_ms, visp_ms, a.text("--truth"));
  if (!printed.ok()) return report("compare", printed.error());
  return 0;
}

}  // namespace

std::vector<Command> comparison_commands() {
  return {{"compare", "our tracker and ViSP's vpMbGenericTracker (edge) on the same frames, times and poses", compare_main}};
}

}  // namespace edgetrack_app
