// SPDX-License-Identifier: BSD-3-Clause
/// Tracking from Python: Tracker, AutoTracker (the --init-auto loop) and Detector over numpy
/// frames read in place, the GIL released while the tracker works, one call at a time per object.
#include <atomic>
#include <optional>

#include <pybind11/stl.h>

#include "bindings.h"

namespace edgetrack_python {

using namespace edgetrack;

namespace {

/// The layout given, or the one an H x W array's dtype names (uint8: grey8, uint16: RGB565).
PixelLayout layout_for(const py::array& frame, std::optional<PixelLayout> layout) {
  if (layout) return *layout;
  const bool bytes = frame.dtype().is(py::dtype::of<uint8_t>()), words = frame.dtype().is(py::dtype::of<uint16_t>());
  if (frame.ndim() == 2 && bytes) return PixelLayout::kGrey8;
  if (frame.ndim() == 2 && words) return PixelLayout::kRgb565;
  const std::string got = described(frame);
  if (!bytes && !words) raise("a " + got + ": frames are uint8 arrays (uint16 for RGB565)");
  raise("a " + got + " needs its layout: track(frame, layout=edgetrack.Layout.BGR24), RGB24, RGBA32, BGRA32, NV21 or I420");
}

/// Refuses a second call on the same object while one runs in another thread (the GIL is
/// released while tracking, and a tracker must not be called from two threads at once).
class OneCallAtATime {
 public:
  explicit OneCallAtATime(std::atomic<bool>& busy) : busy_(busy) {
    if (busy_.exchange(true)) raise("this tracker is already tracking a frame in another thread: use one tracker per thread");
  }
  ~OneCallAtATime() { busy_ = false; }
  OneCallAtATime(const OneCallAtATime&) = delete;
  OneCallAtATime& operator=(const OneCallAtATime&) = delete;

 private:
  std::atomic<bool>& busy_;
};

/// `frame` as a numpy array: itself, or a view of any object with the buffer protocol.
py::array array_of(const py::object& frame) {
  py::array array = py::array::ensure(frame);
  if (!array) {
    PyErr_Clear();
    raise("a frame is a numpy array or an object with the buffer protocol, not a " +
          std::string(py::str(py::type::of(frame).attr("__name__"))));
  }
  return array;
}

/// Runs `work(view)` on `frame` read in place, without the GIL, and returns what it returned.
template <class Work>
auto run_on_frame(std::atomic<bool>& busy, const py::object& object, std::optional<PixelLayout> layout, Work work) {
  const py::array frame = array_of(object);
  const FrameView view = frame_view_of(frame, layout_for(frame, layout));
  OneCallAtATime one(busy);
  std::optional<decltype(work(view))> done;
  {
    py::gil_scoped_release release;
    done.emplace(work(view));
  }
  if (!done->ok()) raise(done->error());
  return std::move(done->value());
}

Se3 checked_pose(const py::array_t<double, py::array::forcecast>& matrix, const char* what) {
  const Se3 pose = pose_of(matrix);
  if (std::optional<std::string> refused = check_start_pose(pose)) raise(std::string(what) + " " + *refused);
  return pose;
}

struct PyTracker {
  Tracker tracker;
  std::atomic<bool> busy{false};
};

struct PyAutoTracker {
  AutoInitTracker tracker;
  std::atomic<bool> busy{false};
};

struct PyDetector {
  Detector detector;
  std::atomic<bool> busy{false};
};

const char* const kFrameDoc =
    "`frame`: a numpy array read in place (no copy), any row stride: uint8 H x W (grey8), H x W x 3 (RGB24, BGR24), "
    "H x W x 4 (RGBA32, BGRA32), (3H/2) x W (NV21, I420), uint16 H x W (RGB565). `layout`: an edgetrack.Layout; "
    "by default grey8 for uint8 H x W and RGB565 for uint16 H x W.";

/// The templates of `params`, checked, made with the GIL released (it takes seconds).
TemplateSet templates_made(const EdgeModel& model, const PinholeCamera& camera, const TemplateParams& params) {
  value_or_raise(check_template_params(params));
  std::optional<Result<TemplateSet>> made;
  {
    py::gil_scoped_release release;
    made.emplace(make_template_set(model, camera, params));
  }
  return value_or_raise(std::move(*made));
}

}  // namespace

void bind_tracking(py::module_& m) {
  py::enum_<PixelLayout>(m, "Layout", "How a frame's pixels are laid out (frame_view.h).")
      .value("GREY8", PixelLayout::kGrey8)
      .value("RGB565", PixelLayout::kRgb565)
      .value("RGB24", PixelLayout::kRgb24)
      .value("BGR24", PixelLayout::kBgr24)
      .value("RGBA32", PixelLayout::kRgba32)
      .value("BGRA32", PixelLayout::kBgra32)
      .value("NV21", PixelLayout::kNv21)
      .value("NV12", PixelLayout::kNv12)
      .value("I420", PixelLayout::kI420);

  py::class_<PyTracker>(m, "Tracker", "The edge tracker from a known initial pose; one tracker per thread.")
      .def(py::init([](const EdgeModel& model, const TrackerConfig& config, const py::array_t<double, py::array::forcecast>& initial_pose) {
             const Se3 initial = pose_of(initial_pose);
             return std::unique_ptr<PyTracker>(
                 new PyTracker{value_or_raise(Tracker::create(model, config.camera, initial, config.params))});
           }),
           py::arg("model"), py::arg("config"), py::arg("initial_pose"),
           "A tracker of `model` seen by `config.camera` with `config.params`, starting from `initial_pose` "
           "(camera_from_model, 4x4). Raises edgetrack.Error naming the input refused.")
      .def(
          "track",
          [](PyTracker& t, const py::object& frame, std::optional<PixelLayout> layout) {
            const FrameResult r =
                run_on_frame(t.busy, frame, layout, [&](const FrameView& view) { return t.tracker.track(view); });
            return tracked_frame(r, t.tracker);
          },
          py::arg("frame"), py::arg("layout") = py::none(),
          (std::string("Tracks one frame of the camera's size; returns an edgetrack.FrameResult. ") + kFrameDoc +
           " Raises edgetrack.Error, the tracker unchanged, for a frame it cannot read.")
              .c_str())
      .def_property_readonly("pose", [](const PyTracker& t) { return matrix_of(t.tracker.camera_from_model()); },
                             "The pose the next frame starts from, 4x4 float64.")
      .def(
          "reset",
          [](PyTracker& t, const py::array_t<double, py::array::forcecast>& pose, bool detected) {
            const Se3 start = checked_pose(pose, "the reset pose");
            OneCallAtATime one(t.busy);
            t.tracker.reset(start, detected ? Tracker::StartPose::kDetected : Tracker::StartPose::kGiven);
          },
          py::arg("pose"), py::arg("detected") = false,
          "Continues from `pose` (4x4) at rest at the next frame (a new initialisation); `detected=True` for a "
          "detector's pose, which the status trusts once a tracked frame confirms it. Raises edgetrack.Error, the "
          "tracker unchanged, for a pose it refuses.")
      .def_property_readonly("params", [](const PyTracker& t) { return t.tracker.params(); }, "A copy of the settings.")
      .def(
          "set_params",
          [](PyTracker& t, const TrackerParams& params) {
            OneCallAtATime one(t.busy);
            if (std::optional<Error> refused = t.tracker.set_params(params)) raise(*refused);
          },
          py::arg("params"),
          "Tracks the next frames with `params` (an edgetrack.Params, or a Config's .params); raises edgetrack.Error, "
          "nothing changed, when they are refused.");

  py::class_<TemplateSet>(m, "Templates", "The detector's templates, made from the model and the camera alone.")
      .def("__len__", [](const TemplateSet& s) { return s.templates.size(); }, "How many templates.");
  m.def(
      "make_templates",
      [](const EdgeModel& model, const PinholeCamera& camera, double distance_min, double distance_max) {
        TemplateParams params;
        params.views.distance_min = real(distance_min);
        params.views.distance_max = real(distance_max);
        return templates_made(model, camera, params);
      },
      py::arg("model"), py::arg("camera"), py::arg("distance_min") = 0.0, py::arg("distance_max") = 0.0,
      "Templates for detecting `model` with `camera` (its image size needed), over camera distances in metres "
      "(0, 0: from the camera and the model's size), as `edgetrack templates` makes them.");
  m.def(
      "auto_init_templates",
      [](const EdgeModel& model, const PinholeCamera& camera) {
        TemplateParams params;
        params.views = auto_init_views(camera, model_extent(model));
        return templates_made(model, camera, params);
      },
      py::arg("model"), py::arg("camera"),
      "Templates over the distances `edgetrack track --init-auto` searches when none is given: wherever the "
      "model spans between the whole of the image's shorter side and a tenth of it.");
  m.def(
      "read_templates",
      [](const std::string& path, const EdgeModel& model, const PinholeCamera& camera) {
        return value_or_raise(read_templates(path, model, camera));
      },
      py::arg("path"), py::arg("model"), py::arg("camera"), "Templates from a file of `edgetrack templates`, checked against the model and camera.");

  py::class_<Detection>(m, "Detection", "What the detector found in one frame.")
      .def_property_readonly("found", [](const Detection& d) { return d.found; }, "Whether the model was found.")
      .def_property_readonly("camera_from_model", [](const Detection& d) { return matrix_of(d.camera_from_model); },
                             "The refined pose, 4x4 float64 (meaningful when found).")
      .def_property_readonly("score", [](const Detection& d) { return to_float(d.score); }, "The winner's kept share.")
      .def_property_readonly("match_share", [](const Detection& d) { return to_float(d.match_share); },
                             "The winner's template score share.")
      .def_property_readonly("template_index", [](const Detection& d) { return d.template_index; }, "The winner's template.")
      .def_property_readonly("points_searched", [](const Detection& d) { return d.points_searched; },
                             "Control points of every screening and refining frame.")
      .def_property_readonly("frames", [](const Detection& d) { return d.frames; },
                             "Screening and refining frames run.")
      .def_property_readonly("cut_short", [](const Detection& d) { return d.cut_short; },
                             "The work budget ended the search with no confident candidate: then not found.");

  py::class_<PyDetector>(m, "Detector", "Finds the model in a frame with no initial pose.")
      .def(py::init([](const EdgeModel& model, const TrackerConfig& config, const TemplateSet& templates) {
             return std::unique_ptr<PyDetector>(new PyDetector{
                 value_or_raise(Detector::create(model, config.camera, templates, config.detector, config.params))});
           }),
           py::arg("model"), py::arg("config"), py::arg("templates"),
           "A detector of `model` with `config`'s camera and settings (its .detector for the detection's own).")
      .def_property_readonly("points_budget", [](const PyDetector& d) { return d.detector.points_budget(); },
                             "The work budget of one detection in control points, scaled to the frame's pixels "
                             "(0: no limit).")
      .def(
          "detect",
          [](PyDetector& d, const py::object& frame, std::optional<PixelLayout> layout) {
            return run_on_frame(d.busy, frame, layout, [&](const FrameView& view) { return d.detector.detect(view); });
          },
          py::arg("frame"), py::arg("layout") = py::none(),
          (std::string("Detects the model in one frame; returns an edgetrack.Detection. ") + kFrameDoc).c_str());

  py::class_<PyAutoTracker>(m, "AutoTracker",
                            "Tracking with no initial pose (edgetrack track --init-auto): detects on the first frame "
                            "and on each frame lost or long doubted, then tracks.")
      .def(py::init([](const EdgeModel& model, const TrackerConfig& config, const TemplateSet& templates) {
             return std::unique_ptr<PyAutoTracker>(new PyAutoTracker{value_or_raise(
                 AutoInitTracker::create(model, config.camera, templates, config.detector, config.params))});
           }),
           py::arg("model"), py::arg("config"), py::arg("templates"), "An automatic tracker of `model` with `config`.")
      .def(
          "track",
          [](PyAutoTracker& t, const py::object& frame, std::optional<PixelLayout> layout) {
            const FrameResult r =
                run_on_frame(t.busy, frame, layout, [&](const FrameView& view) { return t.tracker.track(view); });
            return tracked_frame(r, t.tracker.tracker());
          },
          py::arg("frame"), py::arg("layout") = py::none(),
          (std::string("Tracks one frame, detecting first when needed; returns an edgetrack.FrameResult. ") + kFrameDoc)
              .c_str())
      .def_property_readonly("detected", [](const PyAutoTracker& t) { return t.tracker.detected(); },
                             "The detector ran on the last frame.")
      .def_property_readonly("found", [](const PyAutoTracker& t) { return t.tracker.found(); },
                             "It ran and found the model.")
      .def_property_readonly("confirmed", [](const PyAutoTracker& t) { return t.tracker.confirmed(); },
                             "A frame was tracked since the last detection.")
      .def_property_readonly("pose", [](PyAutoTracker& t) { return matrix_of(t.tracker.tracker().camera_from_model()); },
                             "The pose the next frame starts from, 4x4 float64.");
}

}  // namespace edgetrack_python
