// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack track`: the paper's tracker over a sequence, with the poses CSV, the AR overlay
/// and the Table 1 summary of the run. It drives the tracker through the public API alone
/// (edgetrack/edgetrack.h, docs/API.md), in named steps: parse, open the inputs, open the
/// outputs, run the frames, close and summarise.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "args.h"
#include "atomic_output.h"
#include "click_init.h"
#include "commands.h"
#include "configuration.h"
#include "count_markers.h"
#include "detection_options.h"
#include "downscaled_tracking.h"
#include "edgetrack/edgetrack.h"
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
    "--model FILE --camera FILE (--init-pose FILE | --init FILE --init-points FILE | --init-click FILE "
    "[--save-clicks FILE] [--save-pose FILE] | --init-auto [--init-distance MIN:MAX] [--templates FILE]) "
    "(--images PATTERN|DIR|VIDEO | --camera-device N) [options]";

/// Per-step totals over a run, for the Table 1 summary.
struct RunTotals {
  int frames = 0;
  int lost = 0;
  int uncertain = 0;
  int retried = 0;        ///< frames tracked again from the last trusted pose (FrameResult::retried)
  int retry_tracked = 0;  ///< of those, the ones the retry tracked
  int reasons[edgetrack::kStatusReasonCount] = {};  ///< frames per edgetrack::StatusReason
  int64_t step_ns[edgetrack::kStepCount] = {0, 0, 0, 0};
  int64_t points_matched = 0;
  int64_t points_sampled = 0;
  int detections = 0;        ///< --init-auto: frames the detector ran on
  int found = 0;             ///< of those, the frames it found the model on
  int64_t detection_ns = 0;  ///< those frames' whole time, their tracking included
};

void print_table1(const RunTotals& totals) {
  const double n = totals.frames > 0 ? totals.frames : 1;
  double step_ms[edgetrack::kStepCount], total = 0;
  for (int s = 0; s < edgetrack::kStepCount; ++s) total += step_ms[s] = totals.step_ns[s] / 1e6;
  std::printf("\nTable 1 for this run (%d frames, real = %s, steady clock of the machine running it; under QEMU, the emulator's):\n\n", totals.frames, real_name());
  std::printf("| step | ms per frame | share |\n|---|---:|---:|\n");
  for (int s = 0; s < edgetrack::kStepCount; ++s)
    std::printf("| %s | %.3f | %.1f %% |\n", edgetrack::step_name(static_cast<edgetrack::Step>(s)), step_ms[s] / n,
                total > 0 ? 100 * step_ms[s] / total : 0.0);
  std::printf("| total | %.3f | 100 %% |\n\n", total / n);
  std::printf("tracking: %.1f frames per second of tracking work, %.1f points tracked of %.1f sampled per frame, "
              "%d frames uncertain, %d lost\n",
              total > 0 ? 1000 * n / total : 0.0, static_cast<double>(totals.points_matched) / n,
              static_cast<double>(totals.points_sampled) / n,
              totals.uncertain, totals.lost);
  if (totals.retried > 0)
    std::printf("  %d frames retried from the last trusted pose, %d of them tracked so\n", totals.retried,
                totals.retry_tracked);
  for (int r = 1; r < edgetrack::kStatusReasonCount; ++r)
    if (totals.reasons[r] > 0)
      std::printf("  %d frames: %s\n", totals.reasons[r], edgetrack::reason_name(static_cast<edgetrack::StatusReason>(r)));
}

/// --init-auto: how often the detector ran and found the model, and what those frames cost
/// (not in Table 1, whose steps are the tracker's).
void print_detections(const RunTotals& totals) {
  std::printf("detection: ran on %d frames, found the model on %d, %.1f ms per detection frame (its tracking included)\n",
              totals.detections, totals.found, totals.detections > 0 ? totals.detection_ns / 1e6 / totals.detections : 0.0);
}

/// One stderr line for a frame the tracker did not report tracked: its status, the reason and
/// the measures the rule read.
void print_status(int frame, const edgetrack::FrameResult& result) {
  const edgetrack::FrameMeasures& m = result.measures;
  std::fprintf(stderr, "frame %d %s (%s): %d of %d visible points matched, %d kept; residual scale %.2f px over "
               "range %u px; correction %.1f px; pose change %.1f mm %.1f deg; %llu saturations; "
               "pose uncertainty %.2f px; edge support %.2f, edge angle %.1f deg%s\n",
               frame, edgetrack::status_name(result.status), edgetrack::reason_name(result.reason), m.matched,
               m.visible, m.kept, static_cast<double>(m.residual_scale), m.range,
               static_cast<double>(m.correction_px), static_cast<double>(m.translation_change_mm),
               static_cast<double>(m.rotation_change_deg), static_cast<unsigned long long>(m.saturations),
               static_cast<double>(m.pose_uncertainty_px), static_cast<double>(m.support_share),
               static_cast<double>(m.gradient_angle_deg), result.retried ? "; retried from the last trusted pose" : "");
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

/// --status NAME=VALUE,...: each setting over `status`, checked.
Result<bool> apply_status_option(const std::string& text, edgetrack::StatusParams& status) {
  return apply_named_settings("--status", text, [&status](const std::string& name, double value) {
    std::string problem = edgetrack::set_status_param(status, name, value);
    return problem.empty() ? edgetrack::check_status_params(status) : problem;
  });
}

/// --thin-lines NAME=VALUE,...: each setting over `lines`, checked.
Result<bool> apply_thin_lines_option(const std::string& text, edgetrack::ThinLineParams& lines) {
  return apply_named_settings("--thin-lines", text, [&lines](const std::string& name, double value) {
    return edgetrack::set_thin_line_param(lines, name, value);
  });
}

/// What the command line asks for.
struct TrackRequest {
  Args args;
  SourceOptions source;
  int factor = 1;  ///< --downscale
  int hypotheses = 1;
  std::optional<double> readout;  ///< --readout, over the configuration's
  bool from_points = false;  ///< --init with --init-points
  bool clicked = false;      ///< --init-click
  bool automatic = false;    ///< --init-auto
  bool progress = true;
};

/// What the run reads: the model, the settings, the frames and the tracker made of them.
struct TrackInputs {
  edgetrack::EdgeModel model;
  std::vector<std::string> notes;  ///< about the configuration, printed after a good run
  std::unique_ptr<FrameSource> source;
  Frame frame;  ///< the frame to track next
  int full_width = 0, full_height = 0;
  PinholeCamera camera;  ///< the tracked frames' (downscaled) camera
  Se3 initial;
  std::unique_ptr<edgetrack::EdgeIdSource> edge_ids;
  std::optional<edgetrack::Tracker> tracker;
  std::unique_ptr<edgetrack::AutoInitTracker> auto_tracker;  ///< --init-auto: tracks instead of `tracker`
};

/// What the run writes.
struct TrackOutputs {
  std::unique_ptr<PoseTableWriter> poses;
  std::unique_ptr<Overlay> overlay;
  std::string overlay_dir;
  std::string overlay_ext;
  std::unique_ptr<VideoOutput> video;
  Cone cone;
};

const CommandLine& track_command_line() {
  static const CommandLine line = {
      "track",
      kSynopsis,
      {
          {"--model", "FILE", "model, ViSP .cao or Wavefront .obj (metres)", ""},
          {"--camera", "FILE", "ViSP XML read as ViSP's loadConfigFile: <camera>, <ecm>, <face>, <lod> (docs/APP.md)", ""},
          intrinsics_specs()[0],
          intrinsics_specs()[1],
          {"--init-pose", "FILE", "initial camera_from_model, a ViSP pose file: .pos (6 numbers) or a 4x4 homogeneous matrix", ""},
          {"--init", "FILE", "ViSP .init file of 3D points, with --init-points: initial pose from points", ""},
          {"--init-points", "FILE", "image positions of the .init points, one 'u v' line each (pixels)", ""},
          {"--init-click", "FILE", "ViSP .init file whose points are clicked on the first frame in a window (host, display)", ""},
          {"--init-auto", "", "no initial pose: detect the model on the first frame and after each lost one", ""},
          {"--init-distance", "MIN:MAX", "with --init-auto: camera distances (metres) its templates cover (default: from "
                                        "the camera and the model's size)", ""},
          {"--templates", "FILE", "with --init-auto: templates made by `edgetrack templates` for this model and camera", ""},
          {"--save-clicks", "FILE", "with --init-click: write the clicked positions (an --init-points file)", ""},
          {"--save-pose", "FILE", "with --init-click: write the accepted initial pose (a .pos file for --init-pose)", ""},
          {"--visibility", "soft|gl", "Edge-ID renderer: soft (portable) or gl (OSMesa, host)", "soft"},
          {"--images", "PATTERN|DIR|VIDEO", "printf pattern (seq/frame%04d.pgm), directory, or video file (host)", ""},
          {"--camera-device", "N", "track a live camera (host) instead of --images", ""},
          {"--first", "N", "first frame number (default: 0, or 1 when a pattern has no frame 0)", ""},
          {"--last", "N", "last frame number, inclusive (default: the last frame)", ""},
          {"--raw-size", "WIDTHxHEIGHT", "size of raw RGB565 frames (.rgb565, .raw)", ""},
          {"--downscale", "N", "track frames N times smaller (640x480 -> QVGA with 2); the camera, sample step and range follow", "1"},
          {"--poses", "FILE", "write the poses CSV (frame,tx,ty,tz,tux,tuy,tuz,points,ms,status,edge_angle_deg)", ""},
          {"--overlay", "DIR", "write overlay frames (wireframe and cone) into this directory", ""},
          {"--video", "FILE", "write the overlay as a video (host)", ""},
          {"--config", "FILE", "a second ViSP XML whose values override those of --camera, element by element", ""},
          {"--hypotheses", "N", "edge hypotheses per control point, 1 to 4: the strongest edge along the normal and the next "
                                "local maxima; the pose step uses the nearest (docs/ME.md)",
           std::to_string(edgetrack::TrackerParams{}.hypotheses)},
          {"--readout", "T", "rolling shutter: the rows are read over T frame intervals, top first (negative: bottom "
                             "first), -1..1; the readout time times the frame rate (default: the configuration's "
                             "<edgetrack><camera><readout>, else 0, a global shutter)", ""},
          {"--status", "NAME=VALUE[,NAME=VALUE...]",
           "status rule settings over the configuration's, named as in its <status> block (docs/APP.md)", ""},
          {"--thin-lines", "NAME=VALUE[,NAME=VALUE...]",
           "the thin-line test's settings over the configuration's, named as in its <edgetrack><thin_lines> block "
           "(docs/APP.md); enabled=0 turns it off", ""},
          detector_option_spec(),
          {"--quiet", "", "no progress line", ""},
      },
      {"--model", "--camera"},
      {{"--init-pose", "--init", "--init-click", "--init-auto"}, {"--images", "--camera-device"}},
      {{"--init", "--init-points"}, {"--init-points", "--init"}, {"--save-clicks", "--init-click"},
       {"--save-pose", "--init-click"}, {"--init-distance", "--init-auto"}, {"--templates", "--init-auto"},
       {"--detector", "--init-auto"}},
  };
  return line;
}

/// Step 1: the options, checked. Returns the exit status when the run stops here.
std::optional<int> parse_request(int argc, char** argv, TrackRequest& request) {
  if (auto stop = parse_command_line(track_command_line(), argc, argv, request.args)) return stop;
  const Args& a = request.args;
  request.from_points = a.has("--init");
  request.clicked = a.has("--init-click");
  request.automatic = a.has("--init-auto");
  std::vector<std::pair<std::string, std::string>> outputs;
  for (const char* option : {"--poses", "--video", "--overlay", "--save-clicks", "--save-pose"})
    if (a.has(option)) outputs.emplace_back(option, a.text(option));
  if (auto clash = check_output_names(outputs)) return report("track", *clash) + 1;
  SourceOptions& source = request.source;
  source.images = a.text("--images");
  auto first = a.frame_number("--first"), last = a.frame_number("--last"), device = a.has("--camera-device") ? a.integer("--camera-device") : Result<int>(-1);
  auto factor = a.integer("--downscale");
  auto raw = a.size("--raw-size", source.raw_width, source.raw_height);
  auto hypotheses = a.integer("--hypotheses");
  for (const Error* bad :
       {&first.error(), &last.error(), &device.error(), &factor.error(), &raw.error(), &hypotheses.error()})
    if (!bad->message.empty()) return report("track", *bad) + 1;
  if (factor.value() < 1 || factor.value() > 8) return report("track", {"", 0, "--downscale must be 1..8"}) + 1;
  edgetrack::TrackerParams with_hypotheses;
  with_hypotheses.hypotheses = hypotheses.value();
  if (auto refused = edgetrack::check_tracker_params(with_hypotheses))
    return report("track", {"--hypotheses", 0, refused->message}) + 1;
  if (a.has("--readout")) {
    auto readout = a.number("--readout");
    if (!readout.ok()) return report("track", readout.error()) + 1;
    edgetrack::TrackerParams with_readout;
    with_readout.readout = real(readout.value());  // set-up time conversion
    if (auto refused = edgetrack::check_tracker_params(with_readout))
      return report("track", {"--readout", 0, refused->message}) + 1;
    request.readout = readout.value();
  }
  source.first = first.value();
  source.last = last.value();
  source.camera_device = device.value();
  request.factor = factor.value();
  request.hypotheses = hypotheses.value();
  request.progress = !a.has("--quiet");
  return std::nullopt;
}

/// The file the initial pose comes from, for messages.
std::string init_source(const TrackRequest& request) {
  const Args& a = request.args;
  if (request.automatic) return "--init-auto";
  return request.from_points ? a.text("--init-points") : request.clicked ? a.text("--init-click") : a.text("--init-pose");
}

/// The initial pose the options name, checked to put the model in front of the camera.
Result<Se3> initial_pose(const TrackRequest& request, const TrackInputs& in, const PinholeCamera& full_camera) {
  const Args& a = request.args;
  if (in.auto_tracker) return in.auto_tracker->tracker().camera_from_model();  // a placeholder until found
  auto initial =
      request.from_points ? initial_pose_from_points(a.text("--init"), a.text("--init-points"), full_camera)
      : request.clicked   ? click_initial_pose({a.text("--init-click"), a.text("--save-clicks"), a.text("--save-pose")},
                                               to_rgb_image(in.frame.pixels.view()), full_camera, in.model)
                          : edgetrack::read_pos(a.text("--init-pose"));
  if (!initial.ok()) return initial.error();
  auto in_front = check_in_front(in.model, initial.value(), init_source(request));
  if (!in_front.ok()) return in_front.error();
  return initial.value();
}

/// Step 2: the model, the settings, the first frame, the initial pose and the tracker, each
/// checked with a message naming its file.
std::optional<int> open_inputs(const TrackRequest& request, TrackInputs& in) {
  const Args& a = request.args;
  auto model = edgetrack::load_model(a.text("--model"));
  if (!model.ok()) return report("track", model.error());
  in.model = std::move(model).value();
  auto config = read_configuration(a.text("--camera"), a.text("--config"));
  if (!config.ok()) return report("track", config.error());
  in.notes = config.value().notes;
  edgetrack::TrackerParams params = config.value().config.params;
  params.hypotheses = request.hypotheses;
  if (request.readout) params.readout = real(*request.readout);  // set-up time conversion
  auto status = apply_status_option(a.text("--status"), params.status);
  if (!status.ok()) return report("track", status.error()) + 1;
  auto thin_lines = apply_thin_lines_option(a.text("--thin-lines"), params.thin_lines);
  if (!thin_lines.ok()) return report("track", thin_lines.error()) + 1;
  downscale_settings(params, request.factor);  // in pixels of the input frames
  if (auto refused = edgetrack::check_tracker_params(params))
    return report("track", {"--downscale " + std::to_string(request.factor), 0, refused->message});
  auto source = open_frame_source(request.source);
  if (!source.ok()) return report("track", source.error());
  in.source = std::move(source).value();
  auto got = in.source->next(in.frame);
  if (!got.ok()) return report("track", got.error());
  in.full_width = in.frame.pixels.width;
  in.full_height = in.frame.pixels.height;
  PinholeCamera full_camera = config.value().config.camera;
  if (full_camera.width == 0) full_camera.width = in.full_width;
  if (full_camera.height == 0) full_camera.height = in.full_height;
  auto calibrated = apply_intrinsics(a, full_camera);
  if (!calibrated.ok()) return report("track", calibrated.error());
  full_camera = calibrated.value();
  if (full_camera.width != in.full_width || full_camera.height != in.full_height)
    return report("track", {in.frame.name, 0,
                            "image size " + std::to_string(in.full_width) + "x" + std::to_string(in.full_height) +
                                " does not match the camera's " + std::to_string(full_camera.width) + "x" +
                                std::to_string(full_camera.height) + " (" + a.text("--camera") + ")"});
  if (auto refused = edgetrack::check_camera(full_camera)) return report("track", {a.text("--camera"), 0, refused->message});
  in.camera = edgetrack::downscaled_camera(full_camera, request.factor);
  if (in.camera.width == 0 || in.camera.height == 0)
    return report("track", {"--downscale " + std::to_string(request.factor), 0,
                            "leaves no pixel of a " + std::to_string(in.full_width) + "x" +
                                std::to_string(in.full_height) + " frame"});
  if (auto refused = edgetrack::check_camera(in.camera))
    return report("track", {"--downscale " + std::to_string(request.factor), 0, refused->message});
  if (auto refused = edgetrack::check_tracked_model(in.model))
    return report("track", {a.text("--model"), 0, refused->message});
  if (request.automatic) {
    auto detection = detector_params_from(a, config.value().config.detector);
    if (!detection.ok()) return report("track", detection.error()) + 1;
    auto made = auto_init_tracker(a, in.model, in.camera, params, detection.value());
    if (!made.ok()) return report("track", made.error());
    in.auto_tracker = std::move(made).value();
    print_detection_reduction(in.camera, "track");
  }
  auto initial = initial_pose(request, in, full_camera);
  if (!initial.ok()) return report("track", initial.error());
  in.initial = initial.value();
  if (auto refused = edgetrack::check_start_pose(in.initial))
    return report("track", {init_source(request), 0, "the initial pose " + *refused});
  auto edge_ids = make_edge_id_source(a.text("--visibility"), in.camera);
  if (!edge_ids.ok()) return report("track", edge_ids.error()) + 1;
  in.edge_ids = std::move(edge_ids).value();
  auto tracker = edgetrack::Tracker::create(in.model, in.camera, in.initial, params);
  if (!tracker.ok()) return report("track", tracker.error());
  in.tracker.emplace(std::move(tracker).value());
  in.tracker->set_edge_id_source(in.edge_ids.get());
  if (in.auto_tracker) in.auto_tracker->tracker().set_edge_id_source(in.edge_ids.get());
  return std::nullopt;
}

/// Step 3: the poses table, the overlay frames and the video the options ask for.
std::optional<int> open_outputs(const TrackRequest& request, const TrackInputs& in, TrackOutputs& out) {
  const Args& a = request.args;
  if (a.has("--poses")) {
    auto opened = PoseTableWriter::open(a.text("--poses"), true);
    if (!opened.ok()) return report("track", opened.error());
    out.poses.reset(new PoseTableWriter(std::move(opened).value()));
  }
  out.overlay_dir = a.text("--overlay");
  if (a.has("--overlay") || a.has("--video")) {
    if (!out.overlay_dir.empty()) {
      if (auto refused = prepare_overlay_directory(out.overlay_dir, kIncompleteMarker)) return report("track", *refused);
      // Removed when the run ends well: a directory of frames that still holds it is incomplete.
      auto marked = write_text_file(out.overlay_dir + "/" + kIncompleteMarker,
                                    "edgetrack track is writing these frames, or stopped before the end\n");
      if (!marked.ok()) return report("track", marked.error());
    }
    auto made = make_overlay(in.camera);
    if (!made.ok()) return report("track", made.error());
    out.overlay = std::move(made).value();
  }
  if (a.has("--video")) {
    auto opened = open_video_output(a.text("--video"), in.camera.width, in.camera.height, 15.0);
    if (!opened.ok()) return report("track", opened.error());
    out.video = std::move(opened).value();
  }
  out.cone = cone_on_top_face(in.model, in.initial);
  out.overlay_ext = host_io_available() ? "png" : "ppm";
  return std::nullopt;
}

/// Adds one frame's result to the run's totals.
void count(const edgetrack::FrameResult& result, RunTotals& totals) {
  for (int s = 0; s < edgetrack::kStepCount; ++s) totals.step_ns[s] += result.step_ns[s];
  ++totals.frames;
  totals.lost += result.status == edgetrack::TrackingStatus::kLost ? 1 : 0;
  totals.uncertain += result.status == edgetrack::TrackingStatus::kUncertain ? 1 : 0;
  ++totals.reasons[static_cast<int>(result.reason)];
  totals.retried += result.retried ? 1 : 0;
  totals.retry_tracked += result.retried && result.status == edgetrack::TrackingStatus::kTracked ? 1 : 0;
  totals.points_matched += result.points_matched;
  totals.points_sampled += result.points_sampled;
}

/// Writes the frame's row and draws its overlay; `tracked` is the frame the tracker read.
Result<bool> write_frame(int index, const edgetrack::FrameView& tracked, const edgetrack::FrameResult& result,
                         const TrackInputs& in, TrackOutputs& out) {
  if (out.poses) out.poses->write(edgetrack::poses_csv_row(index, result));
  if (!out.overlay) return true;
  const RgbImage drawn = out.overlay->draw(to_rgb_image(tracked), in.model, result.camera_from_model, out.cone);
  if (!out.overlay_dir.empty()) {
    char name[64];
    std::snprintf(name, sizeof name, "/overlay%04d.", index);
    auto written = write_image(out.overlay_dir + name + out.overlay_ext, drawn);
    if (!written.ok()) return written.error();
  }
  if (out.video) out.video->write(drawn);
  return true;
}

/// The camera distances the detector's templates cover, as "A to B m".
std::string searched_distances(const edgetrack::AutoInitTracker& tracker) {
  double nearest = 0, farthest = 0;
  for (const edgetrack::Template& t : tracker.detector().templates().templates) {
    const double d = static_cast<double>(t.distance);
    if (nearest == 0 || d < nearest) nearest = d;
    if (d > farthest) farthest = d;
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.3f to %.3f m", nearest, farthest);
  return text;
}

/// Adds a frame the detector ran on to the totals and, with progress lines, says what it found.
void count_detection(int index, const edgetrack::AutoInitTracker& tracker, std::chrono::steady_clock::duration spent,
                     bool progress, RunTotals& totals) {
  ++totals.detections;
  totals.found += tracker.found() ? 1 : 0;
  totals.detection_ns += std::chrono::duration_cast<std::chrono::nanoseconds>(spent).count();
  if (!progress) return;
  if (tracker.found()) std::fprintf(stderr, "frame %d detection: found\n", index);
  else std::fprintf(stderr, "frame %d detection: not found (camera distances %s searched)\n", index,
                    searched_distances(tracker).c_str());
}

/// --init-auto: an error line, and 1, when no frame of the run was tracked.
int check_auto_run(const edgetrack::AutoInitTracker& tracker, const RunTotals& totals) {
  if (totals.frames > totals.lost + totals.uncertain) return 0;
  const std::string frames = std::to_string(totals.frames);
  if (totals.found == 0)
    return report("track", {"", 0, "--init-auto did not find the model in any of " + frames + " frames (camera distances " +
                                       searched_distances(tracker) + " searched); give --init-distance MIN:MAX or "
                                       "--templates for the scene"});
  return report("track", {"", 0, "--init-auto found the model on " + std::to_string(totals.found) +
                                     " frames, but no frame of " + frames + " was tracked"});
}

/// The progress line: on a terminal after every frame, else every 50 frames.
void print_progress(int index, edgetrack::TrackingStatus status, const RunTotals& totals, double seconds) {
  const bool terminal = isatty(2) != 0;
  if (!terminal && totals.frames % 50 != 0) return;
  std::fprintf(stderr, "%sframe %d %s (%d done, %d uncertain, %d lost), %.1f frames/s%s", terminal ? "\r" : "", index,
               edgetrack::status_name(status), totals.frames, totals.uncertain, totals.lost,
               totals.frames / (seconds > 0 ? seconds : 1), terminal ? "   " : "\n");
}

/// Step 4: every frame, in the layout its file holds (downscaled: grey8 or RGB24), tracked,
/// written and drawn.
std::optional<int> run_frames(const TrackRequest& request, TrackInputs& in, TrackOutputs& out, RunTotals& totals) {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const FramePixels& pixels = in.frame.pixels;
    if (pixels.width != in.full_width || pixels.height != in.full_height)
      return report("track", {in.frame.name, 0,
                              "image size " + std::to_string(pixels.width) + "x" + std::to_string(pixels.height) +
                                  " does not match the camera's " + std::to_string(in.full_width) + "x" +
                                  std::to_string(in.full_height)});
    FramePixels small;
    const edgetrack::FrameView tracked = tracked_frame(pixels, request.factor, small);
    const auto frame_start = std::chrono::steady_clock::now();
    edgetrack_count_begin();  // the tracker's own share of the frame (QEMU counter, tests/bench/app)
    auto result = in.auto_tracker ? in.auto_tracker->track(tracked) : in.tracker->track(tracked);
    edgetrack_count_end();
    if (!result.ok()) return report("track", {in.frame.name, 0, result.error().message});
    const edgetrack::FrameResult& r = result.value();
    count(r, totals);
    if (in.auto_tracker && in.auto_tracker->detected()) {
      count_detection(in.frame.index, *in.auto_tracker, std::chrono::steady_clock::now() - frame_start, request.progress,
                      totals);
      // The cone goes on the face on top at the first found pose (the placeholder's is anywhere).
      if (in.auto_tracker->found() && totals.found == 1) out.cone = cone_on_top_face(in.model, r.camera_from_model);
    }
    if (request.progress && r.status != edgetrack::TrackingStatus::kTracked) print_status(in.frame.index, r);
    auto written = write_frame(in.frame.index, tracked, r, in, out);
    if (!written.ok()) return report("track", written.error());
    if (request.progress)
      print_progress(in.frame.index, r.status, totals,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    auto more = in.source->next(in.frame);
    if (!more.ok()) return report("track", more.error());
    if (!more.value()) break;
  }
  if (request.progress && isatty(2) != 0) std::fprintf(stderr, "\n");
  return std::nullopt;
}

/// Step 5: the outputs closed (a table or video that did not close well is an error).
std::optional<int> close_outputs(TrackOutputs& out) {
  if (out.poses) {
    auto closed = out.poses->close();
    if (!closed.ok()) return report("track", closed.error());
  }
  if (out.video) {
    auto closed = out.video->close();
    if (!closed.ok()) return report("track", closed.error());
  }
  if (!out.overlay_dir.empty()) std::remove((out.overlay_dir + "/" + kIncompleteMarker).c_str());
  return std::nullopt;
}

/// The run as named steps, in the shape of M3T's Tracker::RunTrackerProcess; each step returns
/// the exit status when the run stops there.
int track_main(int argc, char** argv) {
  TrackRequest request;
  if (auto stop = parse_request(argc, argv, request)) return *stop;
  TrackInputs inputs;
  if (auto stop = open_inputs(request, inputs)) return *stop;
  TrackOutputs outputs;
  if (auto stop = open_outputs(request, inputs, outputs)) return *stop;
  RunTotals totals;
  if (auto stop = run_frames(request, inputs, outputs, totals)) return *stop;
  if (auto stop = close_outputs(outputs)) return *stop;
  print_notes(inputs.notes);  // after a run that went through: an error stays one line
  print_table1(totals);
  if (!inputs.auto_tracker) return 0;
  print_detections(totals);
  return check_auto_run(*inputs.auto_tracker, totals);
}

}  // namespace

std::vector<Command> tracking_commands() {
  return {{"track", "track a model through frames (files, a directory, video or a camera)", track_main}};
}

}  // namespace edgetrack_app
