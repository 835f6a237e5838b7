// SPDX-License-Identifier: BSD-3-Clause
/// `edgetrack synth` (host): renders a ground-truth sequence with OSMesa, the paper's OGRE step:
/// the model lit over a cluttered backdrop, anti-aliased, with optional noise, blur and a moving
/// occluder; writes the frames, truth.csv, the first pose (.pos) and the camera XML.
#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <filesystem>

#include "args.h"
#include "commands.h"
#include "configuration.h"
#include "edgetrack/model_io.h"
#include "edgetrack/pose_io.h"
#include "frame_source.h"
#include "gl_renderer.h"
#include "host_io.h"
#include "pose_table.h"
#include "trajectory.h"

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

int synth_main(int argc, char** argv) {
  const std::string synopsis =
      "--out DIR [--model M.cao|.obj] [--camera C.xml --size WxH] [--trajectory paper|FILE] [--frames N] "
      "[--noise S] [--blur S] [--occluder] [--rgb565]";
  const std::vector<OptionSpec> specs = {
      {"--out", true, "output directory (frames/, truth.csv, first.pos, camera.xml)"},
      {"--model", true, "model (default data/models/cube60.cao, the paper's 60 mm cube)"},
      {"--camera", true, "ViSP camera XML (default: QVGA, px = py = 220, centre 160,120)"},
      {"--size", true, "image size for --camera, WIDTHxHEIGHT (default 320x240)"},
      {"--trajectory", true, "paper (default) or a CSV with the header of truth.csv"},
      {"--frames", true, "number of frames (default 60)"},
      {"--noise", true, "Gaussian noise, grey levels sigma (default 2)"},
      {"--blur", true, "Gaussian blur, pixels sigma (default 0.6)"},
      {"--occluder", false, "a dark bar crossing the view in front of the model"},
      {"--rgb565", false, "write raw RGB565 frames (.rgb565) instead of PPM"},
      {"--supersample", true, "samples per pixel along each axis (default 4)"},
      {"--seed", true, "seed of the backdrop and the noise (default 1)"},
      {"--help", false, "this text"},
  };
  auto parsed = Args::parse(argc, argv, 1, specs);
  if (!parsed.ok()) return report("synth", parsed.error()) + 1;
  const Args& a = parsed.value();
  if (a.has("--help")) {
    std::printf("%s", usage("synth", synopsis, specs).c_str());
    return 0;
  }
  if (!a.has("--out")) {
    std::fprintf(stderr, "%s", usage("synth", synopsis, specs).c_str());
    return 2;
  }
  auto frames = a.integer("--frames", 60);
  auto noise = a.number("--noise", 2.0);
  auto blur = a.number("--blur", 0.6);
  auto supersample = a.integer("--supersample", 4);
  auto seed = a.integer("--seed", 1);
  for (const auto* bad : {&frames.error(), &noise.error(), &blur.error(), &supersample.error(), &seed.error()})
    if (!bad->message.empty()) return report("synth", *bad) + 1;
  if (frames.value() <= 0) return report("synth", {"", 0, "--frames must be positive"}) + 1;
  if (supersample.value() < 1 || supersample.value() > 8) return report("synth", {"", 0, "--supersample must be 1..8"}) + 1;

  const std::string model_path = a.text("--model", data_dir() + "/models/cube60.cao");
  auto model = edgetrack::load_model(model_path);
  if (!model.ok()) return report("synth", model.error());
  // The paper's cube at 150 mm shows about 60 control points with this QVGA camera (72 degrees wide).
  PinholeCamera camera{real(220), real(220), real(160), real(120), 320, 240};
  if (a.has("--camera")) {
    int width = 320, height = 240;
    auto size = a.size("--size", width, height);
    if (!size.ok()) return report("synth", size.error()) + 1;
    auto read = read_camera(a.text("--camera"), width, height);
    if (!read.ok()) return report("synth", read.error());
    camera = read.value();
  }
  auto poses = make_trajectory(a.text("--trajectory", "paper"), frames.value());
  if (!poses.ok()) return report("synth", poses.error());
  for (size_t k = 0; k < poses.value().size(); ++k) {
    auto in_front = check_in_front(model.value(), poses.value()[k], a.text("--trajectory", "paper") + " frame " + std::to_string(k));
    if (!in_front.ok()) return report("synth", in_front.error());
  }

  const std::string out = a.text("--out");
  std::error_code error;
  std::filesystem::create_directories(out + "/frames", error);
  if (error) return report("synth", {out, 0, "cannot create the directory: " + error.message()});
  auto renderer = GlRenderer::create(camera, supersample.value());
  if (!renderer.ok()) return report("synth", renderer.error());

  // The backdrop: a plane 80 mm behind the model's centre, facing the first camera position.
  const RgbImage backdrop = clutter_texture(1024, static_cast<uint64_t>(seed.value()));
  const edgetrack::EdgeModel& m = model.value();
  Vec3 centre;
  for (const Vec3& v : m.vertices) centre = centre + v;
  centre = real(1.0 / m.vertices.size()) * centre;
  const Vec3 towards_camera = edgetrack::normalized(poses.value()[0].inverse().translation() - centre);
  SceneExtras extras;
  extras.backdrop = &backdrop;
  extras.backdrop_normal = towards_camera;
  extras.backdrop_centre = centre - real(0.08) * towards_camera;
  extras.backdrop_size = 0.6;
  extras.occluder = a.has("--occluder");

  auto truth = PoseTableWriter::open(out + "/truth.csv", false);
  if (!truth.ok()) return report("synth", truth.error());
  const bool rgb565 = a.has("--rgb565");
  const std::string pattern = out + (rgb565 ? "/frames/frame%04d.rgb565" : "/frames/frame%04d.ppm");
  std::vector<uint16_t> packed;
  for (int k = 0; k < frames.value(); ++k) {
    const Se3& pose = poses.value()[k];
    // The occluder sweeps from left to right across the middle third of the sequence.
    extras.occluder_x = -0.03 + 0.06 * (k - frames.value() / 3.0) / (frames.value() / 3.0);
    RgbImage image = renderer.value()->render_scene(m, pose, extras);
    degrade(image, noise.value(), blur.value(), static_cast<uint64_t>(seed.value()) * 7919u + static_cast<uint64_t>(k));
    const std::string path = expand_pattern(pattern, k);
    Result<bool> written = true;
    if (rgb565) {
      to_rgb565(image, packed);
      written = write_raw_rgb565(path, packed);
    } else {
      written = write_ppm(path, image);
    }
    if (!written.ok()) return report("synth", written.error());
    truth.value().write(pose_row(k, pose));
  }
  auto closed = truth.value().close();
  if (!closed.ok()) return report("synth", closed.error());
  auto pos = edgetrack::write_pos(out + "/first.pos", poses.value()[0]);
  if (!pos.ok()) return report("synth", pos.error());
  auto xml = write_camera_xml(out + "/camera.xml", camera);
  if (!xml.ok()) return report("synth", xml.error());
  std::printf("synth: %d frames of %dx%d in %s, largest image motion %.2f px/frame\n", frames.value(), camera.width,
              camera.height, pattern.c_str(), largest_vertex_motion(m, camera, poses.value()));
  std::printf("synth: truth %s/truth.csv, first pose %s/first.pos, camera %s/camera.xml\n", out.c_str(), out.c_str(),
              out.c_str());
  return 0;
}

}  // namespace

std::vector<Command> host_commands() {
  return {{"synth", "render a ground-truth sequence with OSMesa (frames, truth.csv, first pose, camera)", synth_main},
          {"edgeid", "portable Edge-ID against Edge-ID through GL; colour-code approximation in RGB565", edgeid_main}};
}

}  // namespace edgetrack_app
