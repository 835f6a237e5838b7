// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack synth` (host): renders a ground-truth sequence with OSMesa, the paper's OGRE step:
/// the model lit over a cluttered backdrop, anti-aliased, with optional noise, blur and a moving
/// occluder, a lens and a camera's effects (camera_timing.h, camera_response.h); writes the frames,
/// truth.csv, the first pose (.pos) and the camera XML.
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "args.h"
#include "camera_response.h"
#include "camera_timing.h"
#include "commands.h"
#include "configuration.h"
#include "edgetrack/lens_resampling.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/scene_extras.h"
#include "frame_source.h"
#include "gl_renderer.h"
#include "host_io.h"
#include "pose_table.h"
#include "trajectory.h"
#include "visp_lens_fit.h"

using edgetrack::Error;
using edgetrack::PinholeCamera;
using edgetrack::Result;
using edgetrack::Se3;
using edgetrack::Vec3;

namespace edgetrack_app {
namespace {

/// A cluttered texture: overlapping rectangles, discs and strokes in many colours.
RgbImage clutter_texture(int size, uint64_t seed) {
  cv::Mat canvas(size, size, CV_8UC3);
  cv::RNG rng(seed);
  canvas.setTo(cv::Scalar(rng.uniform(60, 140), rng.uniform(60, 140), rng.uniform(60, 140)));
  for (int i = 0; i < 320; ++i) {
    const cv::Scalar colour(rng.uniform(20, 235), rng.uniform(20, 235), rng.uniform(20, 235));
    const cv::Point p(rng.uniform(0, size), rng.uniform(0, size));
    switch (rng.uniform(0, 3)) {
      case 0:
        cv::rectangle(canvas, p, p + cv::Point(rng.uniform(8, size / 8), rng.uniform(8, size / 8)), colour, -1, cv::LINE_AA);
        break;
      case 1:
        cv::circle(canvas, p, rng.uniform(4, size / 16), colour, -1, cv::LINE_AA);
        break;
      default:
        cv::line(canvas, p, cv::Point(rng.uniform(0, size), rng.uniform(0, size)), colour, rng.uniform(1, 5), cv::LINE_AA);
    }
  }
  RgbImage image = make_image(size, size);
  std::copy(canvas.data, canvas.data + image.rgb.size(), image.rgb.begin());
  return image;
}

/// The occluder's covered share of the object's image over the frames.
struct CoverStats {
  double sum = 0, low = 1, high = 0;
  void add(double share) {
    sum += share;
    low = std::min(low, share);
    high = std::max(high, share);
  }
};

/// Adds Gaussian noise (sigma grey levels) and a Gaussian blur (sigma pixels), in place.
void degrade(RgbImage& image, double noise, double blur, uint64_t seed) {
  cv::Mat mat(image.height, image.width, CV_8UC3, image.rgb.data());
  if (blur > 0) cv::GaussianBlur(mat, mat, cv::Size(0, 0), blur);
  if (noise > 0) {
    cv::Mat n(mat.size(), CV_16SC3);
    cv::RNG rng(seed);
    rng.fill(n, cv::RNG::NORMAL, 0, noise);
    cv::Mat wide;
    mat.convertTo(wide, CV_16SC3);
    wide += n;
    wide.convertTo(mat, CV_8UC3);
  }
}

/// What synth was asked for, read and checked.
struct SynthOptions {
  std::string out, model_path, trajectory;
  PinholeCamera camera;
  int frames = 60, supersample = 4, seed = 1;
  int hide_first = -1, hide_last = -1;  ///< --hide: frames the board covers the whole object on
  double speed = 1, noise = 2, blur = 0.6, cover = 0, clutter_mm = 0;
  bool occluder = false, rgb565 = false, pgm = false, reverse = false;
  SensorTiming timing;        ///< --shutter, --readout: motion blur and rolling shutter
  ExposureSchedule exposure;  ///< --exposure: brightness over the sequence
  int jpeg_quality = 0;       ///< --jpeg: 0 for none
};

/// The image `pinhole` (drawn with lens.pinhole_camera()) as `camera`'s lens shows it.
RgbImage through_lens(const edgetrack::LensResampling& lens, const PinholeCamera& camera, const RgbImage& pinhole) {
  RgbImage seen;
  seen.width = camera.width;
  seen.height = camera.height;
  seen.rgb.resize(static_cast<size_t>(seen.width) * seen.height * 3);
  const int64_t scale = int64_t(lens.samples()) * lens.samples() * edgetrack::LensResampling::kWeightOne *
                        edgetrack::LensResampling::kWeightOne;
  for (int y = 0; y < seen.height; ++y)
    for (int x = 0; x < seen.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const int64_t sum = lens.weighted_sum(x, y, [&](int32_t i) { return pinhole.rgb[static_cast<size_t>(i) * 3 + c]; }, 0);
        seen.pixel(x, y)[c] = static_cast<uint8_t>((sum + scale / 2) / scale);
      }
  return seen;
}

/// --shutter, --readout, --exposure and --jpeg into `o`.
Result<bool> read_camera_effects(const Args& a, SynthOptions& o) {
  auto shutter = a.number("--shutter"), readout = a.number("--readout");
  auto jpeg = a.integer("--jpeg");
  for (const auto* bad : {&shutter.error(), &readout.error(), &jpeg.error()})
    if (!bad->message.empty()) return *bad;
  o.timing = {shutter.value(), readout.value()};
  // A shutter open longer than the frame interval, or rows read over more than one, is no camera.
  if (o.timing.shutter < 0 || o.timing.shutter > 1) return Error{"", 0, "--shutter must be 0..1 frame intervals"};
  if (o.timing.readout < 0 || o.timing.readout > 1) return Error{"", 0, "--readout must be 0..1 frame intervals"};
  o.jpeg_quality = jpeg.value();
  if (o.jpeg_quality < 0 || o.jpeg_quality > 100) return Error{"", 0, "--jpeg must be a quality 1..100, or 0 for none"};
  if (a.has("--exposure")) {
    auto exposure = ExposureSchedule::parse(a.text("--exposure"));
    if (!exposure.ok()) return exposure.error();
    o.exposure = exposure.value();
  }
  return true;
}

/// The options, or an Error: one naming no file is a bad option value (exit status 2), one
/// naming a file (the camera XML) a bad input (exit status 1).
Result<SynthOptions> read_options(const Args& a) {
  SynthOptions o;
  o.out = a.text("--out");
  o.model_path = a.text("--model");
  o.trajectory = a.text("--trajectory");
  o.occluder = a.has("--occluder");
  o.reverse = a.has("--reverse");
  o.rgb565 = a.has("--rgb565");
  o.pgm = a.has("--pgm");
  if (o.rgb565 && o.pgm) return Error{"", 0, "--rgb565 and --pgm name two frame formats: give one"};
  auto frames = a.integer("--frames"), supersample = a.integer("--supersample"), seed = a.integer("--seed");
  auto speed = a.number("--speed"), noise = a.number("--noise"), blur = a.number("--blur");
  auto cover = a.number("--cover"), clutter_mm = a.number("--clutter");
  for (const auto* bad : {&frames.error(), &noise.error(), &blur.error(), &supersample.error(), &seed.error(),
                          &speed.error(), &cover.error(), &clutter_mm.error()})
    if (!bad->message.empty()) return *bad;
  o.frames = frames.value(), o.supersample = supersample.value(), o.seed = seed.value();
  o.speed = speed.value(), o.noise = noise.value(), o.blur = blur.value();
  o.cover = cover.value(), o.clutter_mm = clutter_mm.value();
  if (o.frames <= 0 || o.frames > 100000) return Error{"", 0, "--frames must be 1..100000"};
  // Past 255 grey levels noise is only saturation; past 50 px a blur leaves no edge to track,
  // and its cost grows with its width.
  if (o.noise < 0 || o.noise > 255) return Error{"", 0, "--noise must be 0..255 grey levels"};
  if (o.blur < 0 || o.blur > 50) return Error{"", 0, "--blur must be 0..50 pixels"};
  if (o.speed < 1 || o.speed > 16) return Error{"", 0, "--speed must be 1..16"};
  if (o.cover < 0 || o.cover >= 1) return Error{"", 0, "--cover must be a share in [0, 1)"};
  if (o.clutter_mm < 0 || o.clutter_mm > 50) return Error{"", 0, "--clutter must be 0..50 mm"};
  if (o.supersample < 1 || o.supersample > 8) return Error{"", 0, "--supersample must be 1..8"};
  if (a.has("--hide")) {
    char end = 0;
    if (std::sscanf(a.text("--hide").c_str(), "%d:%d%c", &o.hide_first, &o.hide_last, &end) != 2 ||
        o.hide_first < 0 || o.hide_last < o.hide_first)
      return Error{"", 0, "--hide '" + a.text("--hide") + "': expected FIRST:LAST frame numbers, 0 <= FIRST <= LAST"};
  }
  // The paper's cube at 150 mm shows about 60 control points with this QVGA camera (72 degrees wide).
  o.camera = PinholeCamera{real(220), real(220), real(160), real(120), 320, 240};
  if (a.has("--camera")) {
    int width = 320, height = 240;
    auto size = a.size("--size", width, height);
    if (!size.ok()) return size.error();
    auto read = read_camera(a.text("--camera"), width, height);
    if (!read.ok()) return read.error();
    o.camera = read.value();
  }
  if (a.has("--kud") && a.has("--intrinsics"))
    return Error{"", 0, "--kud and --intrinsics both give the lens: give one"};
  auto calibrated = apply_intrinsics(a, o.camera);
  if (!calibrated.ok()) return calibrated.error();
  o.camera = calibrated.value();
  if (a.has("--kud")) {
    auto kud = a.number("--kud");
    if (!kud.ok()) return kud.error();
    // Beyond 0.5 a QVGA corner folds back (no inverse); a wide lens's is about -0.1 to -0.3.
    if (kud.value() < -0.5 || kud.value() > 0.5) return Error{"", 0, "--kud must be -0.5..0.5"};
    o.camera.lens = edgetrack::LensDistortion{};
    o.camera.lens.model = edgetrack::LensModel::kVisp;
    o.camera.lens.kud = real(kud.value());
    o.camera.lens.kdu = real(fitted_kdu(o.camera));
  }
  auto camera_effects = read_camera_effects(a, o);
  if (!camera_effects.ok()) return camera_effects.error();
  if (o.camera.distorted() && (o.cover > 0 || a.has("--hide")))
    return Error{"", 0, "--cover and --hide draw their board in image columns: not through a lens (--kud, --intrinsics)"};
  if (!usable_image_size(static_cast<long long>(o.camera.width) * o.supersample,
                         static_cast<long long>(o.camera.height) * o.supersample))
    return Error{"", 0, "the image rendered at --supersample " + std::to_string(o.supersample) + " would be " +
                            std::to_string(static_cast<long long>(o.camera.width) * o.supersample) + "x" +
                            std::to_string(static_cast<long long>(o.camera.height) * o.supersample) +
                            ": at most " + std::to_string(kMaxImageSide) + " pixels a side and " +
                            std::to_string(kMaxImagePixels >> 20) + " M pixels"};
  return o;
}

/// The trajectory at the asked speed (with --reverse, its first half there and back), each pose
/// checked to keep the model in front.
Result<std::vector<Se3>> synth_poses(const SynthOptions& o, const edgetrack::EdgeModel& model) {
  const int forward_frames = o.reverse ? o.frames / 2 + 1 : o.frames;
  const int slow_frames = static_cast<int>(std::ceil(o.speed * (forward_frames - 1))) + 1;
  auto slow = make_trajectory(o.trajectory, slow_frames);
  if (!slow.ok()) return slow.error();
  std::vector<Se3> poses = edgetrack::faster_poses(slow.value(), real(o.speed), forward_frames);
  if (static_cast<int>(poses.size()) < forward_frames)
    return Error{o.trajectory, 0, "fewer than --frames times --speed poses"};
  if (o.reverse) {
    poses = edgetrack::there_and_back(poses);
    poses.resize(static_cast<size_t>(o.frames));
  }
  for (size_t k = 0; k < poses.size(); ++k) {
    auto in_front = check_in_front(model, poses[k], o.trajectory + " frame " + std::to_string(k));
    if (!in_front.ok()) return in_front.error();
  }
  return poses;
}

/// The backdrop: a plane 80 mm behind the model's centre, facing the first camera position.
SceneExtras backdrop_scene(const edgetrack::EdgeModel& m, const Se3& first_pose, const RgbImage& backdrop) {
  Vec3 centre;
  for (const Vec3& v : m.vertices) centre = centre + v;
  centre = real(1.0 / m.vertices.size()) * centre;
  const Vec3 towards_camera = edgetrack::normalized(first_pose.inverse().translation() - centre);
  SceneExtras extras;
  extras.backdrop = &backdrop;
  extras.backdrop_normal = towards_camera;
  extras.backdrop_centre = centre - real(0.08) * towards_camera;
  extras.backdrop_size = 0.6;
  return extras;
}

/// Renders and writes every frame and the truth rows; returns the occluder's covered shares.
Result<CoverStats> write_frames(const SynthOptions& o, const edgetrack::EdgeModel& m, const std::vector<Se3>& poses,
                                const ExposurePlan& plan, SceneExtras extras, const std::string& pattern) {
  // Through a lens: GL draws the pinhole image with a margin at twice the size, read through the
  // lens at 2 x 2 samples a pixel.
  std::optional<edgetrack::LensResampling> lens;
  if (o.camera.distorted()) lens.emplace(o.camera, 2, 2);
  auto renderer = GlRenderer::create(lens ? lens->pinhole_camera() : o.camera, o.supersample);
  if (!renderer.ok()) return renderer.error();
  auto truth = PoseTableWriter::open(o.out + "/truth.csv", false);
  if (!truth.ok()) return truth.error();
  CoverStats covered;
  std::vector<uint8_t> mask;
  std::vector<int> columns;
  std::vector<uint16_t> packed;
  for (int k = 0; k < o.frames; ++k) {
    const Se3& pose = poses[static_cast<size_t>(k)];
    // The occluder sweeps from left to right across the middle third of the sequence.
    extras.occluder_x = -0.03 + 0.06 * (k - o.frames / 3.0) / (o.frames / 3.0);
    const bool hidden = k >= o.hide_first && k <= o.hide_last;
    extras.band = {};
    if (o.cover > 0 || hidden) {
      edgetrack::silhouette_columns(m, o.camera, pose, mask, columns);
      const int centre = edgetrack::sweeping_centre(columns, k, o.frames);
      extras.band = edgetrack::occluder_band(columns, centre, hidden ? real(1) : real(o.cover));
      if (hidden && extras.band.x_end > extras.band.x_begin) {  // past the outline's anti-aliased columns
        extras.band.x_begin = std::max(0, extras.band.x_begin - 2);
        extras.band.x_end = std::min(o.camera.width, extras.band.x_end + 2);
      }
      if (o.cover > 0) covered.add(static_cast<double>(extras.band.covered_share));
    }
    RgbImage image = expose(plan, [&](double offset) {
      RgbImage render = renderer.value()->render_scene(m, pose_at_time(poses, k + offset), extras);
      return lens ? through_lens(*lens, o.camera, render) : render;
    });
    if (!o.exposure.empty()) apply_exposure(image, o.exposure.factor(k));
    degrade(image, o.noise, o.blur, static_cast<uint64_t>(o.seed) * 7919u + static_cast<uint64_t>(k));
    if (o.jpeg_quality > 0) {
      auto compressed = jpeg_round_trip(image, o.jpeg_quality);
      if (!compressed.ok()) return compressed.error();
      image = std::move(compressed.value());
    }
    const std::string path = expand_pattern(pattern, k);
    Result<bool> written = true;
    if (o.rgb565) {
      to_rgb565(image, packed);
      written = write_raw_rgb565(path, packed);
    } else if (o.pgm) {
      written = write_pgm(path, image);
    } else {
      written = write_ppm(path, image);
    }
    if (!written.ok()) return written.error();
    truth.value().write(pose_row(k, pose));
  }
  auto closed = truth.value().close();
  if (!closed.ok()) return closed.error();
  return covered;
}

int synth_main(int argc, char** argv) {
  const CommandLine line = {
      "synth",
      "--out DIR [--model FILE] [--camera FILE --size WIDTHxHEIGHT] [--intrinsics FILE | --kud K] [--trajectory paper|FILE] "
      "[--frames N] "
      "[--speed K] [--reverse] [--noise SIGMA] [--blur SIGMA] [--occluder] [--cover SHARE] [--hide FIRST:LAST] "
      "[--clutter MM] [--shutter T] [--readout T] [--exposure FRAME:FACTOR,...] [--jpeg Q] [--rgb565 | --pgm]",
      {
          {"--out", "DIR", "output directory (frames/, truth.csv, first.pos, camera.xml)", ""},
          {"--model", "FILE", "model, .cao or .obj (the default is the paper's 60 mm cube)", data_dir() + "/models/cube60.cao"},
          {"--camera", "FILE", "ViSP camera XML (default: QVGA, px = py = 220, centre 160,120)", ""},
          {"--size", "WIDTHxHEIGHT", "image size for --camera (default: 320x240)", ""},
          intrinsics_specs()[0],
          intrinsics_specs()[1],
          {"--kud", "K", "frames through ViSP's radial lens x_d = x (1 + kud r^2), -0.5..0.5; writes intrinsics.xml "
                            "(default: no lens)", ""},
          {"--trajectory", "paper|FILE", "paper or a CSV with the header of truth.csv", "paper"},
          {"--frames", "N", "number of frames", "60"},
          {"--speed", "K", "the same path K times faster: frame k shows trajectory pose K k, interpolated", "1"},
          {"--reverse", "", "the path runs forwards for the first half of the frames and back over the same poses "
                            "for the rest: the motion reverses at once", ""},
          {"--noise", "SIGMA", "Gaussian noise, grey levels sigma", "2"},
          {"--blur", "SIGMA", "Gaussian blur, pixels sigma", "0.6"},
          {"--occluder", "", "a dark bar crossing the view in front of the model", ""},
          {"--cover", "SHARE", "a dark board in front covering this share of the object's image (0.3: 30 %), sweeping "
                               "across it", "0"},
          {"--hide", "FIRST:LAST", "on these frames the board covers the whole object (it leaves the view and comes back)", ""},
          {"--clutter", "MM", "dark lines parallel to every model edge, this many mm beside it, away from the model's centre", "0"},
          {"--shutter", "T", "motion blur: the exposure lasts T frame intervals (0..1), centred on the frame's time", "0"},
          {"--readout", "T", "rolling shutter: rows read top to bottom over T frame intervals (0..1), the middle row at "
                             "the frame's time", "0"},
          {"--exposure", "FRAME:FACTOR,...", "brightness factors at key frames, linear between them (keys on consecutive "
                                             "frames: a sudden step)", ""},
          {"--jpeg", "Q", "each frame compressed as a JPEG of quality Q (1..100) and decoded; 0: none", "0"},
          {"--rgb565", "", "write raw RGB565 frames (.rgb565) instead of PPM", ""},
          {"--pgm", "", "write 8-bit grey PGM frames (.pgm, the luma of vpImageConvert's rule) instead of PPM", ""},
          {"--supersample", "N", "samples per pixel along each axis", "4"},
          {"--seed", "N", "seed of the backdrop and the noise", "1"},
      },
      {"--out"},
      {},
      {{"--size", "--camera"}, {"--intrinsics-name", "--intrinsics"}},
  };
  Args a;
  if (auto stop = parse_command_line(line, argc, argv, a)) return *stop;
  auto options = read_options(a);
  if (!options.ok()) return report("synth", options.error()) + (options.error().file.empty() ? 1 : 0);
  const SynthOptions& o = options.value();
  auto model = edgetrack::load_model(o.model_path);
  if (!model.ok()) return report("synth", model.error());
  const edgetrack::EdgeModel& m = model.value();
  auto poses = synth_poses(o, m);
  if (!poses.ok()) return report("synth", poses.error());
  std::error_code error;
  std::filesystem::create_directories(o.out + "/frames", error);
  if (error) return report("synth", {o.out, 0, "cannot create the directory: " + error.message()});

  const RgbImage backdrop = clutter_texture(1024, static_cast<uint64_t>(o.seed));
  SceneExtras extras = backdrop_scene(m, poses.value()[0], backdrop);
  extras.occluder = o.occluder;
  const std::vector<edgetrack::Segment3> clutter = edgetrack::parallel_clutter(m, real(o.clutter_mm / 1000));
  if (o.clutter_mm > 0) extras.clutter = &clutter;
  const std::string pattern = o.out + (o.rgb565 ? "/frames/frame%04d.rgb565" : o.pgm ? "/frames/frame%04d.pgm" : "/frames/frame%04d.ppm");
  const double motion_px = largest_vertex_motion(m, o.camera, poses.value());
  const ExposurePlan plan = plan_exposure(o.timing, o.camera.height, motion_px);
  auto covered = write_frames(o, m, poses.value(), plan, extras, pattern);
  if (!covered.ok()) return report("synth", covered.error());
  auto pos = edgetrack::write_pos(o.out + "/first.pos", poses.value()[0]);
  if (!pos.ok()) return report("synth", pos.error());
  auto xml = write_camera_xml(o.out + "/camera.xml", o.camera);
  if (!xml.ok()) return report("synth", xml.error());
  if (o.camera.lens.model == edgetrack::LensModel::kVisp) {
    auto intrinsics = write_visp_camera_file(o.out + "/intrinsics.xml", o.camera);
    if (!intrinsics.ok()) return report("synth", intrinsics.error());
    std::printf("synth: through ViSP's lens kud = %.6g (kdu = %.6g fitted): %s/intrinsics.xml for --intrinsics\n",
                static_cast<double>(o.camera.lens.kud), static_cast<double>(o.camera.lens.kdu), o.out.c_str());
  }
  std::printf("synth: %d frames of %dx%d in %s, largest image motion %.2f px/frame\n", o.frames, o.camera.width,
              o.camera.height, pattern.c_str(), motion_px);
  if (plan.times.size() > 1)
    std::printf("synth: shutter open %.3g and rows read over %.3g frame intervals: %zu renders per frame, %.3g px apart\n",
                o.timing.shutter, o.timing.readout, plan.times.size(),
                motion_px * (plan.times[1] - plan.times[0]));
  if (!o.exposure.empty())
    std::printf("synth: brightness factor %.3g on the first frame, %.3g on the last\n", o.exposure.factor(0),
                o.exposure.factor(o.frames - 1));
  if (o.jpeg_quality > 0) std::printf("synth: frames through JPEG at quality %d\n", o.jpeg_quality);
  if (o.cover > 0)
    std::printf("synth: occluder covers %.1f %% of the object's image on average (%.1f to %.1f %%)\n",
                100 * covered.value().sum / o.frames, 100 * covered.value().low, 100 * covered.value().high);
  if (o.clutter_mm > 0)
    std::printf("synth: %zu clutter lines %.1f mm beside the edges, %.1f px off them on average in the first frame\n",
                clutter.size(), o.clutter_mm,
                static_cast<double>(edgetrack::clutter_image_offset(m, clutter, o.camera, poses.value()[0])));
  std::printf("synth: truth %s/truth.csv, first pose %s/first.pos, camera %s/camera.xml\n", o.out.c_str(),
              o.out.c_str(), o.out.c_str());
  return 0;
}

}  // namespace

std::vector<Command> host_commands() {
  std::vector<Command> commands = {
      {"synth", "render a ground-truth sequence with OSMesa (frames, truth.csv, first pose, camera)", synth_main},
      {"edgeid", "portable Edge-ID against Edge-ID through GL; colour-code approximation in RGB565", edgeid_main}};
  for (const Command& c : calibration_commands()) commands.push_back(c);
  return commands;
}

}  // namespace edgetrack_app
