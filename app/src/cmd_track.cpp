// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack track`: the paper's tracker over a sequence, with the poses CSV, the AR overlay
/// and the Table 1 summary of the run.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "args.h"
#include "click_init.h"
#include "commands.h"
#include "configuration.h"
#include "detection_options.h"
#include "downscaled_tracking.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/tracker.h"
#include "frame_source.h"
#include "host_io.h"
#include "overlay.h"
#include "pose_from_points.h"
#include "pose_table.h"
#include "visibility.h"

using edgetrack::Error;
using edgetrack::PinholeCamera;
using edgetrack::Result;
using edgetrack::Se3;

namespace edgetrack_app {
namespace {

const char* const kSynopsis =
    "--model M.cao|.obj --camera C.xml (--init-pose P.pos | --init I.init --init-points P.txt | --init-click I.init "
    "[--save-clicks P.txt] [--save-pose P.pos] | --init-auto [--init-distance MIN:MAX] [--templates T]) [--visibility soft|gl] --images PATTERN|DIR|VIDEO [--first N] [--last N] "
    "[--poses OUT.csv] [--overlay DIR] [--video OUT.mp4] [--config X.xml]";

/// Per-step totals over a run, for the Table 1 summary.
struct RunTotals {
  int frames = 0;
  int lost = 0;
  int uncertain = 0;
  int reasons[edgetrack::kStatusReasonCount] = {};  ///< frames per edgetrack::StatusReason
  double step_ms[edgetrack::kStepCount] = {0, 0, 0, 0};
  double points_matched = 0;
  double points_sampled = 0;
};

void print_table1(const RunTotals& totals) {
  const double n = totals.frames > 0 ? totals.frames : 1;
  double total = 0;
  for (double ms : totals.step_ms) total += ms;
  std::printf("\nTable 1 for this run (%d frames, real = %s, steady clock of the machine running it; under QEMU, the emulator's):\n\n", totals.frames, real_name());
  std::printf("| step | ms per frame | share |\n|---|---:|---:|\n");
  for (int s = 0; s < edgetrack::kStepCount; ++s)
    std::printf("| %s | %.3f | %.1f %% |\n", edgetrack::step_name(static_cast<edgetrack::Step>(s)), totals.step_ms[s] / n,
                total > 0 ? 100 * totals.step_ms[s] / total : 0.0);
  std::printf("| total | %.3f | 100 %% |\n\n", total / n);
  std::printf("tracking: %.1f frames per second of tracking work, %.1f points tracked of %.1f sampled per frame, "
              "%d frames uncertain, %d lost\n",
              total > 0 ? 1000 * n / total : 0.0, totals.points_matched / n, totals.points_sampled / n,
              totals.uncertain, totals.lost);
  for (int r = 1; r < edgetrack::kStatusReasonCount; ++r)
    if (totals.reasons[r] > 0)
      std::printf("  %d frames: %s\n", totals.reasons[r], edgetrack::reason_name(static_cast<edgetrack::StatusReason>(r)));
}

/// One stderr line for a frame the tracker did not report tracked: its status, the reason and
/// the measures the rule read.
void print_status(int frame, const edgetrack::FrameResult& result) {
  const edgetrack::FrameMeasures& m = result.measures;
  std::fprintf(stderr, "frame %d %s (%s): %d of %d visible points matched, %d kept; residual scale %.2f px over "
               "range %u px; correction %.1f px; pose change %.1f mm %.1f deg; %llu saturations\n",
               frame, edgetrack::status_name(result.status), edgetrack::reason_name(result.reason), m.matched,
               m.visible, m.kept, static_cast<double>(m.residual_scale), m.range,
               static_cast<double>(m.correction_px), static_cast<double>(m.translation_change_mm),
               static_cast<double>(m.rotation_change_deg), static_cast<unsigned long long>(m.saturations));
}

/// The initial pose from a .init file and the image positions of its points (full-size pixels).
Result<Se3> initial_pose_from_points(const std::string& init_path, const std::string& points_path,
                                     const PinholeCamera& camera) {
  auto points = read_init_points(init_path);
  if (!points.ok()) return points.error();
  auto pixels = read_image_points(points_path);
  if (!pixels.ok()) return pixels.error();
  auto pose = pose_from_points(points.value(), pixels.value(), camera, points_path);
  if (!pose.ok()) return pose.error();
  std::fprintf(stderr, "initial pose from %zu points, reprojection error %.2f px rms\n", points.value().size(),
               pose.value().rms_px);
  return pose.value().camera_from_model;
}

int track_main(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {
      {"--model", true, "model, ViSP .cao or Wavefront .obj (metres)"},
      {"--camera", true, "ViSP XML read as ViSP's loadConfigFile: <camera>, <ecm>, <face>, <lod> (docs/APP.md)"},
      {"--init-pose", true, "initial camera_from_model, a ViSP .pos file"},
      {"--init", true, "ViSP .init file of 3D points, with --init-points: initial pose from points"},
      {"--init-points", true, "image positions of the .init points, one 'u v' line each (pixels)"},
      {"--init-click", true, "ViSP .init file whose points are clicked on the first frame in a window (host, display)"},
      {"--init-auto", false, "no initial pose: detect the model on the first frame and after each lost one"},
      {"--init-distance", true, "with --init-auto: MIN:MAX camera distances (metres) its templates cover"},
      {"--templates", true, "with --init-auto: templates made by `edgetrack templates` for this model and camera"},
      {"--save-clicks", true, "with --init-click: write the clicked positions (an --init-points file)"},
      {"--save-pose", true, "with --init-click: write the accepted initial pose (a .pos file for --init-pose)"},
      {"--visibility", true, "Edge-ID renderer: soft (portable, the default) or gl (OSMesa, host)"},
      {"--images", true, "printf pattern (seq/frame%04d.pgm), directory, or video file (host)"},
      {"--camera-device", true, "track a live camera (host) instead of --images"},
      {"--first", true, "first frame number"},
      {"--last", true, "last frame number (inclusive)"},
      {"--raw-size", true, "WIDTHxHEIGHT of raw RGB565 frames (.rgb565, .raw)"},
      {"--downscale", true, "track frames N times smaller (640x480 -> QVGA with 2); the camera, sample step and range follow"},
      {"--poses", true, "write the poses CSV (frame,tx,ty,tz,tux,tuy,tuz,points,ms,status)"},
      {"--overlay", true, "write overlay frames (wireframe and cone) into this directory"},
      {"--video", true, "write the overlay as a video (host)"},
      {"--config", true, "a second ViSP XML whose values override those of --camera, element by element"},
      {"--hypotheses", true, "edge hypotheses per control point, 1 to 4 (default 1): the strongest edge along the "
                             "normal and the next local maxima; the pose step uses the nearest (docs/ME.md)"},
      {"--quiet", false, "no progress line"},
      {"--help", false, "this text"},
  };
  auto parsed = Args::parse(argc, argv, 1, specs);
  if (!parsed.ok()) return report("track", parsed.error()) + 1;
  const Args& a = parsed.value();
  if (a.has("--help")) {
    std::printf("%s", usage("track", kSynopsis, specs).c_str());
    return 0;
  }
  const bool from_points = a.has("--init") && a.has("--init-points");
  const bool clicked = a.has("--init-click");
  const bool saves = a.has("--save-clicks") || a.has("--save-pose");
  const bool automatic = a.has("--init-auto");
  if (!a.has("--model") || !a.has("--camera") || (a.has("--init-pose") + from_points + clicked + automatic != 1) ||
      (saves && !clicked) || (!a.has("--images") && !a.has("--camera-device"))) {
    std::fprintf(stderr, "%s", usage("track", kSynopsis, specs).c_str());
    return 2;
  }
  SourceOptions source_options;
  source_options.images = a.text("--images");
  auto first = a.frame_number("--first"), last = a.frame_number("--last"), device = a.integer("--camera-device", -1);
  auto factor = a.integer("--downscale", 1);
  auto raw = a.size("--raw-size", source_options.raw_width, source_options.raw_height);
  auto hypotheses = a.integer("--hypotheses", edgetrack::TrackerParams{}.hypotheses);
  for (const Error* bad :
       {&first.error(), &last.error(), &device.error(), &factor.error(), &raw.error(), &hypotheses.error()})
    if (!bad->message.empty()) return report("track", *bad) + 1;
  if (factor.value() < 1 || factor.value() > 8) return report("track", {"", 0, "--downscale must be 1..8"}) + 1;
  if (hypotheses.value() < 1 || hypotheses.value() > edgetrack::kMaxHypotheses)
    return report("track", {"", 0, "--hypotheses must be 1.." + std::to_string(edgetrack::kMaxHypotheses)}) + 1;
  source_options.first = first.value();
  source_options.last = last.value();
  source_options.camera_device = device.value();

  // Inputs, each checked with a message naming its file.
  auto model = edgetrack::load_model(a.text("--model"));
  if (!model.ok()) return report("track", model.error());
  auto config = read_configuration(a.text("--camera"), a.text("--config"));
  if (!config.ok()) return report("track", config.error());
  edgetrack::TrackerParams params = config.value().config.params;
  params.hypotheses = hypotheses.value();
  downscale_settings(params, factor.value());  // in pixels of the input frames
  auto source = open_frame_source(source_options);
  if (!source.ok()) return report("track", source.error());
  Frame frame;
  auto got = source.value()->next(frame);
  if (!got.ok()) return report("track", got.error());
  const int full_width = frame.image.width, full_height = frame.image.height;
  PinholeCamera full_camera = config.value().config.camera;
  if (full_camera.width == 0) full_camera.width = full_width;
  if (full_camera.height == 0) full_camera.height = full_height;
  if (full_camera.width != full_width || full_camera.height != full_height)
    return report("track", {frame.name, 0,
                            "image size " + std::to_string(full_width) + "x" + std::to_string(full_height) +
                                " does not match the camera's " + std::to_string(full_camera.width) + "x" +
                                std::to_string(full_camera.height) + " (" + a.text("--camera") + ")"});
  const PinholeCamera camera = downscaled(full_camera, factor.value());
  std::unique_ptr<edgetrack::AutoInitTracker> auto_tracker;
  if (automatic) {
    auto made = auto_init_tracker(a, model.value(), camera, params);
    if (!made.ok()) return report("track", made.error());
    auto_tracker = std::move(made).value();
  }
  const std::string init_source = automatic    ? std::string("--init-auto")
                                  : from_points ? a.text("--init-points")
                                  : clicked     ? a.text("--init-click")
                                                : a.text("--init-pose");
  auto initial = automatic     ? Result<Se3>(auto_tracker->tracker().camera_from_model())
                 : from_points ? initial_pose_from_points(a.text("--init"), a.text("--init-points"), full_camera)
                 : clicked   ? click_initial_pose({a.text("--init-click"), a.text("--save-clicks"), a.text("--save-pose")},
                                                  frame.image, full_camera, model.value())
                             : edgetrack::read_pos(a.text("--init-pose"));
  if (!initial.ok()) return report("track", initial.error());
  auto in_front = check_in_front(model.value(), initial.value(), init_source);
  if (!in_front.ok()) return report("track", in_front.error());
  auto edge_id_source = make_edge_id_source(a.text("--visibility", "soft"), camera);
  if (!edge_id_source.ok()) return report("track", edge_id_source.error()) + 1;
  auto tracker = edgetrack::Tracker::create(model.value(), camera, initial.value(), params);
  if (!tracker.ok()) return report("track", {init_source, 0, tracker.error().message});
  tracker.value().set_edge_id_source(edge_id_source.value().get());
  if (auto_tracker) auto_tracker->tracker().set_edge_id_source(edge_id_source.value().get());

  // Outputs.
  std::unique_ptr<PoseTableWriter> poses;
  if (a.has("--poses")) {
    auto opened = PoseTableWriter::open(a.text("--poses"), true);
    if (!opened.ok()) return report("track", opened.error());
    poses.reset(new PoseTableWriter(std::move(opened).value()));
  }
  std::unique_ptr<Overlay> overlay;
  const std::string overlay_dir = a.text("--overlay");
  if (a.has("--overlay") || a.has("--video")) {
    if (!overlay_dir.empty()) {
      std::error_code error;
      std::filesystem::create_directories(overlay_dir, error);
      if (error) return report("track", {overlay_dir, 0, "cannot create the directory: " + error.message()});
      // Removed when the run ends well: a directory of frames that still holds it is incomplete.
      auto marked = write_text_file(overlay_dir + "/" + kIncompleteMarker,
                                    "edgetrack track is writing these frames, or stopped before the end\n");
      if (!marked.ok()) return report("track", marked.error());
    }
    auto made = make_overlay(camera);
    if (!made.ok()) return report("track", made.error());
    overlay = std::move(made).value();
  }
  std::unique_ptr<VideoOutput> video;
  if (a.has("--video")) {
    auto opened = open_video_output(a.text("--video"), camera.width, camera.height, 15.0);
    if (!opened.ok()) return report("track", opened.error());
    video = std::move(opened).value();
  }
  const Cone cone = cone_on_top_face(model.value(), initial.value());
  const std::string overlay_ext = host_io_available() ? "png" : "ppm";

  RunTotals totals;
  const bool progress = !a.has("--quiet");
  const bool terminal = isatty(2) != 0;
  const auto start = std::chrono::steady_clock::now();
  std::vector<uint16_t> packed;
  for (;;) {
    if (frame.image.width != full_width || frame.image.height != full_height)
      return report("track", {frame.name, 0,
                              "image size " + std::to_string(frame.image.width) + "x" +
                                  std::to_string(frame.image.height) + " does not match the camera's " +
                                  std::to_string(full_width) + "x" + std::to_string(full_height)});
    const RgbImage image = factor.value() > 1 ? downscale(frame.image, factor.value()) : std::move(frame.image);
    to_rgb565(image, packed);
    const edgetrack::FrameResult result =
        auto_tracker ? auto_tracker->track(packed.data()).frame : tracker.value().track(packed.data());
    double ms = 0;
    for (int s = 0; s < edgetrack::kStepCount; ++s) {
      totals.step_ms[s] += result.step_ns[s] / 1e6;
      ms += result.step_ns[s] / 1e6;
    }
    const bool lost = result.status == edgetrack::TrackingStatus::kLost;
    if (progress && result.status != edgetrack::TrackingStatus::kTracked) print_status(frame.index, result);
    ++totals.frames;
    totals.lost += lost ? 1 : 0;
    totals.uncertain += result.status == edgetrack::TrackingStatus::kUncertain ? 1 : 0;
    ++totals.reasons[static_cast<int>(result.reason)];
    totals.points_matched += result.points_matched;
    totals.points_sampled += result.points_sampled;
    if (poses) {
      PoseRow row = pose_row(frame.index, result.camera_from_model);
      row.points = result.points_matched;
      row.ms = ms;
      row.lost = lost;
      row.uncertain = result.status == edgetrack::TrackingStatus::kUncertain;
      poses->write(row);
    }
    if (overlay) {
      const RgbImage drawn = overlay->draw(image, model.value(), result.camera_from_model, cone);
      if (!overlay_dir.empty()) {
        char name[64];
        std::snprintf(name, sizeof name, "/overlay%04d.", frame.index);
        auto written = write_image(overlay_dir + name + overlay_ext, drawn);
        if (!written.ok()) return report("track", written.error());
      }
      if (video) video->write(drawn);
    }
    if (progress && (terminal || totals.frames % 50 == 0)) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "%sframe %d %s (%d done, %d uncertain, %d lost), %.1f frames/s%s", terminal ? "\r" : "",
                   frame.index, edgetrack::status_name(result.status), totals.frames, totals.uncertain, totals.lost, totals.frames / (seconds > 0 ? seconds : 1), terminal ? "   " : "\n");
    }
    frame = Frame{};
    auto more = source.value()->next(frame);
    if (!more.ok()) return report("track", more.error());
    if (!more.value()) break;
  }
  if (progress && terminal) std::fprintf(stderr, "\n");
  if (poses) {
    auto closed = poses->close();
    if (!closed.ok()) return report("track", closed.error());
  }
  if (video) {
    auto closed = video->close();
    if (!closed.ok()) return report("track", closed.error());
  }
  if (!overlay_dir.empty()) std::remove((overlay_dir + "/" + kIncompleteMarker).c_str());
  print_notes(config.value().notes);  // after a run that went through: an error stays one line
  print_table1(totals);
  return 0;
}

}  // namespace

std::vector<Command> tracking_commands() {
  return {{"track", "track a model through frames (files, a directory, video or a camera)", track_main}};
}

}  // namespace edgetrack_app
