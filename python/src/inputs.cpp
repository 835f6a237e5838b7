// SPDX-License-Identifier: BSD-3-Clause
/// The inputs of a tracker from Python: models (files or text), the ViSP XML configuration
/// (file or text), calibration files, pose files; the camera and the settings as objects.
#include <array>
#include <cmath>
#include <optional>

#include <pybind11/stl.h>

#include "bindings.h"

namespace edgetrack_python {

using namespace edgetrack;

namespace {

py::dict notes_of(const ConfigNotes& notes) {
  py::dict d;
  d["camera_block"] = notes.camera_block;
  d["not_applied"] = notes.not_applied;
  d["cut_to_whole"] = notes.cut_to_whole;
  return d;
}

/// A setting of TrackerParams as a read-write property of Params; the tracker checks it at
/// create and set_params (check_tracker_params), not here.
template <class Get, class Set>
void setting(py::class_<TrackerParams>& cls, const char* name, Get get, Set set, const char* doc) {
  cls.def_property(name, get, set, doc);
}

}  // namespace

py::array_t<double> vector_of(const Vec3& v) {
  py::array_t<double> out(3);
  auto a = out.mutable_unchecked<1>();
  a(0) = to_float(v.x);
  a(1) = to_float(v.y);
  a(2) = to_float(v.z);
  return out;
}

py::array_t<double> matrix_of(const Se3& pose) {
  py::array_t<double> out({4, 4});
  auto m = out.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = r == 3 ? (c == 3 ? 1.0 : 0.0) : 0.0;
  const Mat33& rotation = pose.rotation();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = to_float(rotation.m[r][c]);
  }
  m(0, 3) = to_float(pose.translation().x);
  m(1, 3) = to_float(pose.translation().y);
  m(2, 3) = to_float(pose.translation().z);
  return out;
}

Se3 pose_of(const py::array_t<double, py::array::forcecast>& matrix) {
  if (matrix.ndim() != 2 || matrix.shape(0) != 4 || matrix.shape(1) != 4)
    raise("a pose is a 4x4 homogeneous matrix (camera_from_model), not an array of shape " +
          std::string(py::str(py::tuple(matrix.attr("shape")))));
  auto m = matrix.unchecked<2>();
  // Checked here, in double: a fixed-point `real` has no NaN to carry the fault to the tracker's door.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(m(r, c))) raise("a pose matrix's values must be finite (row " + std::to_string(r) + ", column " + std::to_string(c) + ")");
  for (int c = 0; c < 4; ++c)
    if (!(std::fabs(m(3, c) - (c == 3 ? 1.0 : 0.0)) <= kPoseMatrixTolerance))
      raise("a pose matrix's last row must be 0 0 0 1");
  Mat33 rotation;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) rotation.m[r][c] = real(m(r, c));
  return Se3(rotation, Vec3{real(m(0, 3)), real(m(1, 3)), real(m(2, 3))});
}

void bind_inputs(py::module_& m) {
  py::class_<EdgeModel>(m, "Model", "A wireframe model (ViSP .cao or Wavefront .obj), in metres.")
      .def_property_readonly("vertex_count", [](const EdgeModel& e) { return e.vertices.size(); }, "Points of the model.")
      .def_property_readonly("edge_count", [](const EdgeModel& e) { return e.edges.size(); },
                             "Straight edges the tracker follows (contour edges of the faces, and lines).")
      .def_property_readonly(
          "vertices",
          [](const EdgeModel& e) {
            py::array_t<double> out({static_cast<py::ssize_t>(e.vertices.size()), py::ssize_t(3)});
            auto a = out.mutable_unchecked<2>();
            for (size_t i = 0; i < e.vertices.size(); ++i) {
              a(i, 0) = to_float(e.vertices[i].x);
              a(i, 1) = to_float(e.vertices[i].y);
              a(i, 2) = to_float(e.vertices[i].z);
            }
            return out;
          },
          "The points as an N x 3 float64 array, metres.")
      .def_property_readonly(
          "edges",
          [](const EdgeModel& e) {
            py::array_t<int> out({static_cast<py::ssize_t>(e.edges.size()), py::ssize_t(2)});
            auto a = out.mutable_unchecked<2>();
            for (size_t i = 0; i < e.edges.size(); ++i) {
              a(i, 0) = e.edges[i].a;
              a(i, 1) = e.edges[i].b;
            }
            return out;
          },
          "The edges as an M x 2 array of indices into vertices.");

  m.def("load_model", [](const std::string& path) { return value_or_raise(load_model(path)); }, py::arg("path"),
        "Reads a ViSP .cao (load() includes relative to the file) or a Wavefront .obj, by its extension.");
  m.def(
      "load_model_text",
      [](const std::string& text, const std::string& name, std::optional<std::string> base_dir) {
        return value_or_raise(load_model_text(text, name, base_dir));
      },
      py::arg("text"), py::arg("name") = "model.cao", py::arg("base_dir") = py::none(),
      "Reads a model from its text. `name` (ending in .cao or .obj) gives the format and stands for the file in "
      "errors; a relative load() line resolves against `base_dir`, and is refused at its line when none is given.");

  py::class_<PinholeCamera>(m, "Camera", "A pinhole camera in pixels, with the lens of a calibration file if any.")
      .def(py::init([](double px, double py_, double u0, double v0, int width, int height) {
             return PinholeCamera(real(px), real(py_), real(u0), real(v0), width, height);
           }),
           py::arg("px"), py::arg("py"), py::arg("u0"), py::arg("v0"), py::arg("width") = 0, py::arg("height") = 0,
           "Focal lengths and principal point in pixels; an image size of 0 x 0 takes the first frame's.")
      .def_property_readonly("px", [](const PinholeCamera& c) { return to_float(c.px); }, "Focal length along x, pixels.")
      .def_property_readonly("py", [](const PinholeCamera& c) { return to_float(c.py); }, "Focal length along y, pixels.")
      .def_property_readonly("u0", [](const PinholeCamera& c) { return to_float(c.u0); }, "Principal point x, pixels.")
      .def_property_readonly("v0", [](const PinholeCamera& c) { return to_float(c.v0); }, "Principal point y, pixels.")
      .def_readwrite("width", &PinholeCamera::width, "Image width, pixels (0: the first frame's).")
      .def_readwrite("height", &PinholeCamera::height, "Image height, pixels (0: the first frame's).")
      .def_property_readonly("distorted", &PinholeCamera::distorted, "Whether it carries a lens distortion.");

  m.def(
      "read_camera_file",
      [](const std::string& path, const std::string& name, int width, int height) {
        return value_or_raise(read_camera_file(path, CameraChoice{name, width, height}));
      },
      py::arg("path"), py::arg("name") = "", py::arg("width") = 0, py::arg("height") = 0,
      "Reads a ViSP camera file (vpXmlParserCamera) or an OpenCV calibration (YAML/XML), lens included; of a ViSP "
      "file with several cameras, the one named `name` of width x height (any when empty or 0).");

  py::class_<TrackerParams> params(m, "Params",
                                   "The tracker's settings (ViSP's defaults); checked when a tracker is created or "
                                   "given them with set_params.");
  params.def(py::init<>(), "ViSP's defaults for the edge tracker.");
  setting(params, "range", [](const TrackerParams& p) { return p.me.range; },
          [](TrackerParams& p, unsigned v) { p.me.range = v; }, "Moving edges: pixels searched either side (vpMe range).");
  setting(params, "threshold", [](const TrackerParams& p) { return to_float(p.me.threshold); },
          [](TrackerParams& p, double v) { p.me.threshold = real(v); }, "Moving edges: least mask response (vpMe threshold).");
  setting(params, "mask_size", [](const TrackerParams& p) { return p.me.mask_size; },
          [](TrackerParams& p, unsigned v) { p.me.mask_size = v; }, "Moving edges: mask side, pixels.");
  setting(params, "mask_number", [](const TrackerParams& p) { return p.me.mask_number; },
          [](TrackerParams& p, unsigned v) { p.me.mask_number = v; }, "Moving edges: oriented masks.");
  setting(params, "mu1", [](const TrackerParams& p) { return to_float(p.me.mu1); },
          [](TrackerParams& p, double v) { p.me.mu1 = real(v); }, "Moving edges: contrast tolerance below.");
  setting(params, "mu2", [](const TrackerParams& p) { return to_float(p.me.mu2); },
          [](TrackerParams& p, double v) { p.me.mu2 = real(v); }, "Moving edges: contrast tolerance above.");
  setting(params, "sample_step", [](const TrackerParams& p) { return to_float(p.me.sample_step); },
          [](TrackerParams& p, double v) { p.me.sample_step = real(v); }, "Pixels between control points.");
  setting(params, "hypotheses", [](const TrackerParams& p) { return p.hypotheses; },
          [](TrackerParams& p, int v) { p.hypotheses = v; }, "Edge hypotheses kept per control point.");
  setting(params, "border", [](const TrackerParams& p) { return p.border; },
          [](TrackerParams& p, int v) { p.border = v; }, "Control points nearer the image border are dropped, pixels.");
  setting(params, "whole_frame_grey", [](const TrackerParams& p) { return p.grey == GreyScaling::kWholeFrame; },
          [](TrackerParams& p, bool v) { p.grey = v ? GreyScaling::kWholeFrame : GreyScaling::kOnDemand; },
          "Convert every pixel to grey (the paper's way) instead of the searched boxes only.");

  py::class_<DetectorParams>(m, "DetectorParams",
                             "The detector's settings that a configuration's <edgetrack><detector> block sets; "
                             "checked when a Detector or an AutoTracker is created.")
      .def(py::init<>(), "The detector's defaults.")
      .def_property(
          "max_points_searched", [](const DetectorParams& p) { return p.max_points_searched; },
          [](DetectorParams& p, int v) { p.max_points_searched = v; },
          "The work budget of one detection: control points its screening and refining frames may search on a "
          "QVGA frame, scaled by the frame's pixels (0: no limit; docs/APP.md).");

  py::class_<TrackerConfig>(m, "Config", "A camera and the tracker's settings, as a ViSP XML configuration gives them.")
      .def(py::init<>(), "ViSP's default camera (no image size) and settings.")
      .def_readwrite("camera", &TrackerConfig::camera, "The camera (replace it with read_camera_file's).")
      .def_readwrite("params", &TrackerConfig::params, "The settings (a copy: assign it back after changing it).")
      .def_readwrite("detector", &TrackerConfig::detector,
                     "The detector's settings, for Detector and AutoTracker (a copy: assign it back after changing it).")
      .def(
          "apply_file", [](TrackerConfig& c, const std::string& path) { return notes_of(value_or_raise(apply_visp_config(path, c))); },
          py::arg("path"),
          "Applies a ViSP model-based tracker XML on top (as loadConfigFile); returns the notes (elements not applied, "
          "numbers cut to whole). Nothing changes when it is refused.")
      .def(
          "apply_text",
          [](TrackerConfig& c, const std::string& xml, const std::string& name) {
            return notes_of(value_or_raise(apply_visp_config_text(xml, name, c)));
          },
          py::arg("xml"), py::arg("name") = "config.xml", "The same for the XML's text; `name` stands for the file in errors.");

  m.def(
      "read_config",
      [](const std::string& path) {
        TrackerConfig config;
        value_or_raise(apply_visp_config(path, config));
        return config;
      },
      py::arg("path"), "A Config read from a ViSP model-based tracker XML file.");
  m.def(
      "read_config_text",
      [](const std::string& xml, const std::string& name) {
        TrackerConfig config;
        value_or_raise(apply_visp_config_text(xml, name, config));
        return config;
      },
      py::arg("xml"), py::arg("name") = "config.xml", "A Config read from the text of a ViSP XML; `name` stands for the file.");

  m.def("read_pose", [](const std::string& path) { return matrix_of(value_or_raise(read_pos(path))); }, py::arg("path"),
        "camera_from_model as a 4x4 float64 matrix, from a ViSP .pos file (tx ty tz tux tuy tuz) or a 4x4 matrix file.");
  m.def(
      "pose_from_theta_u",
      [](const std::array<double, 3>& t, const std::array<double, 3>& tu) {
        return matrix_of(Se3::from_theta_u(Vec3{real(t[0]), real(t[1]), real(t[2])}, Vec3{real(tu[0]), real(tu[1]), real(tu[2])}));
      },
      py::arg("translation"), py::arg("theta_u"), "The 4x4 matrix of a translation (metres) and a theta-u rotation (radians).");
  m.def(
      "theta_u_of",
      [](const py::array_t<double, py::array::forcecast>& matrix) {
        const Se3 pose = pose_of(matrix);
        return py::make_tuple(vector_of(pose.translation()), vector_of(pose.theta_u()));
      },
      py::arg("matrix"), "The (translation, theta_u) of a 4x4 pose matrix, as two float64 arrays of 3.");
}

}  // namespace edgetrack_python
