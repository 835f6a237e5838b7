// SPDX-License-Identifier: BSD-3-Clause
/// The vector kernels against their scalar reference (real/vector_kernels.h): the same sequence
/// tracked with the widest vectors, with the build's baseline vectors and with the scalar code
/// gives every frame's control points, matches (found, contrast, alternatives, outlier, chosen)
/// and pose to the last bit. The generated cube, the wood toy with clutter lines and 3 hypotheses
/// (alternatives on most matches), and ViSP's mbt/cube at its cube.xml settings (range 7: paths
/// longer than a vector chunk, real texture).
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "edgetrack/model_io.h"
#include "edgetrack/scene_extras.h"
#include "edgetrack/scene_renderer.h"
#include "edgetrack/tracker.h"
#include "real/vector_kernels.h"
#include "synthetic_sequence.h"
#include "testlib/testlib_test.h"
#include "visp_sequence.h"

using namespace edgetrack;
using namespace edgetrack_test;

namespace {

/// Frames per run: each sequence is tracked three times, under QEMU too.
constexpr int kFrames = 12;

/// Every control point, match and pose of a run, as the bytes of their values, one record per frame.
class RunDump {
 public:
  void add_frame(const Tracker& tracker) {
    starts_.push_back(bytes_.size());
    add(static_cast<int>(tracker.control_points().size()));
    for (const ControlPoint& p : tracker.control_points()) add(p);
    add(static_cast<int>(tracker.matches().size()));
    for (const EdgeMatch& m : tracker.matches()) {
      add(m.point);
      add(m.found);
      add(m.contrast);
      add(m.alternative_count);
      for (int a = 0; a < m.alternative_count; ++a) add(m.alternatives[a]);
      add(m.outlier ? 1 : 0);
      add(m.chosen);
    }
    const Se3& pose = tracker.camera_from_model();
    add(pose.translation());
    for (int r = 0; r < 3; ++r) add(Vec3{pose.rotation().m[r][0], pose.rotation().m[r][1], pose.rotation().m[r][2]});
  }
  int frames() const { return static_cast<int>(starts_.size()); }
  int matches_with_alternatives = 0;

  /// The first frame whose record differs from `other`'s, or -1 when the runs are the same.
  int first_difference(const RunDump& other) const {
    for (int f = 0; f < frames() || f < other.frames(); ++f)
      if (f >= frames() || f >= other.frames() || record(f) != other.record(f)) return f;
    return -1;
  }

 private:
  template <class T>
  void add_bytes(const T& value) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    bytes_.insert(bytes_.end(), b, b + sizeof(T));
  }
  void add(int v) { add_bytes(v); }
  void add(const real& v) { add_bytes(v); }
  void add(const Vec2& v) {
    add(v.x);
    add(v.y);
  }
  void add(const Vec3& v) {
    add(v.x);
    add(v.y);
    add(v.z);
  }
  void add(const ControlPoint& p) {
    add(p.edge);
    add(p.point_in_model);
    add(p.pixel);
    add(p.direction);
    add(p.normal);
  }
  std::vector<unsigned char> record(int f) const {
    const size_t end = f + 1 < frames() ? starts_[static_cast<size_t>(f) + 1] : bytes_.size();
    return {bytes_.begin() + static_cast<std::ptrdiff_t>(starts_[static_cast<size_t>(f)]),
            bytes_.begin() + static_cast<std::ptrdiff_t>(end)};
  }

  std::vector<unsigned char> bytes_;
  std::vector<size_t> starts_;
};

/// A run of the generated scene (rendered in-process, clutter lines `clutter` metres beside
/// every edge, 0: none) with the kernels `choice`.
RunDump generated_run(Scene scene, const TrackerParams& params, real clutter, vector_kernels::Choice choice) {
  RunDump dump;
  const Result<EdgeModel> model = load_model(model_path(scene));
  if (!model.ok()) return dump;
  const PinholeCamera camera = qvga_camera();
  const std::vector<Se3> truth = true_poses(scene, kFrames);
  Result<Tracker> tracker = Tracker::create(model.value(), camera, truth[0], params);
  if (!tracker.ok()) return dump;
  SceneRenderer renderer(camera, SceneStyle{});
  const std::vector<Segment3> lines = parallel_clutter(model.value(), clutter);
  SceneAdditions additions;
  if (clutter > real(0)) additions.clutter = &lines;
  Rgb565Frame frame;
  vector_kernels::choose(choice);
  for (int k = 0; k < kFrames; ++k) {
    renderer.render(model.value(), truth[k], static_cast<uint32_t>(1000 + k), additions, frame);
    if (!tracker.value().track(rgb565_view(frame)).ok()) break;
    dump.add_frame(tracker.value());
    for (const EdgeMatch& m : tracker.value().matches()) dump.matches_with_alternatives += m.alternative_count > 0;
  }
  vector_kernels::choose(vector_kernels::Choice::kWidest);
  return dump;
}

/// mbt/cube's first frames at its cube.xml settings with the kernels `choice`.
RunDump visp_cube_run(vector_kernels::Choice choice) {
  RunDump dump;
  vector_kernels::choose(choice);
  run_visp_cube(EDGETRACK_VISP_IMAGES, kFrames, [&dump](const Tracker& tracker) { dump.add_frame(tracker); });
  vector_kernels::choose(vector_kernels::Choice::kWidest);
  return dump;
}

/// The widest and the baseline kernels' runs against the scalar reference's.
void compare_choices(const std::string& name, const std::function<RunDump(vector_kernels::Choice)>& run) {
  const RunDump scalar = run(vector_kernels::Choice::kScalar);
  const RunDump baseline = run(vector_kernels::Choice::kBaseline);
  const RunDump widest = run(vector_kernels::Choice::kWidest);
  TEST((name + ": every frame is tracked with each choice").c_str(),
       scalar.frames() == kFrames && baseline.frames() == kFrames && widest.frames() == kFrames, true);
  std::printf("%s, %s: AVX2 %s, %d matches with alternatives in the scalar run\n", name.c_str(), real_name(),
              vector_kernels::avx2() ? "run" : "not run", scalar.matches_with_alternatives);
  TEST((name + ": the baseline vectors' control points, matches and poses are the scalar reference's, bit for bit, "
               "frame (-1: none) differing")
           .c_str(),
       baseline.first_difference(scalar), -1);
  TEST((name + ": the widest vectors' control points, matches and poses are the scalar reference's, bit for bit, "
               "frame (-1: none) differing")
           .c_str(),
       widest.first_difference(scalar), -1);
}

}  // namespace

static void test_vector_kernels() {
  TEST("the widest kernels are the default", vector_kernels::chosen() == vector_kernels::Choice::kWidest, true);
  compare_choices("generated cube", [](vector_kernels::Choice c) {
    return generated_run(Scene::kCube, TrackerParams{}, real(0), c);
  });
  TrackerParams three;
  three.hypotheses = 3;
  compare_choices("wood toy, clutter lines 4 mm beside the edges, 3 hypotheses", [&three](vector_kernels::Choice c) {
    return generated_run(Scene::kWoodToy, three, real(0.004), c);
  });
  compare_choices("mbt/cube, cube.xml", visp_cube_run);
}

TESTMAIN(test_vector_kernels)
