// SPDX-License-Identifier: BSD-3-Clause
/// What the parts of the `edgetrack` Python module share: the exception every refusal raises,
/// numpy frames seen as FrameViews, and each part's registration.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "edgetrack/edgetrack.h"

namespace edgetrack_python {

namespace py = pybind11;

/// Raises edgetrack.Error with the command line's one line, `file:line: message`.
[[noreturn]] void raise(const edgetrack::Error& error);
/// Raises edgetrack.Error with `message`.
[[noreturn]] void raise(const std::string& message);

/// The value of `result`, or edgetrack.Error with its error's text.
template <class T>
T value_or_raise(edgetrack::Result<T> result) {
  if (!result.ok()) raise(result.error());
  return std::move(result.value());
}

/// A numpy array (or any buffer) read in place as a frame of `layout`: the array must stay alive
/// and unchanged while the view is used. Raises edgetrack.Error for a dtype, shape or strides
/// the layout cannot be read from.
/// "uint8 array of shape (480, 640)", for messages.
std::string described(const py::array& array);
edgetrack::FrameView frame_view_of(const py::array& array, edgetrack::PixelLayout layout);

/// A real as a Python float, and back.
inline double to_float(const real& x) { return static_cast<double>(x); }

/// A pose as the 4x4 float64 homogeneous matrix [R t; 0 0 0 1], and back (checked as a start
/// pose by the caller).
py::array_t<double> matrix_of(const edgetrack::Se3& pose);
py::array_t<double> vector_of(const edgetrack::Vec3& v);
edgetrack::Se3 pose_of(const py::array_t<double, py::array::forcecast>& matrix);

/// One frame's result as Python sees it: the FrameResult and the tracker's control points of
/// that frame (sampled, and matched with the pose step's outliers marked), for drawing.
struct TrackedFrame {
  edgetrack::FrameResult result;
  std::vector<edgetrack::Vec2> sampled;
  std::vector<edgetrack::Vec2> matched;
  std::vector<bool> outlier;
};
/// What `tracker` did on the frame it returned `result` for.
TrackedFrame tracked_frame(const edgetrack::FrameResult& result, const edgetrack::Tracker& tracker);

void bind_inputs(py::module_& m);    // files, text, camera and settings
void bind_results(py::module_& m);   // FrameResult, measures, enums
void bind_tracking(py::module_& m);  // Tracker, AutoInitTracker, Detector

}  // namespace edgetrack_python
