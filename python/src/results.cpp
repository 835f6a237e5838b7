// SPDX-License-Identifier: BSD-3-Clause
/// A frame's result from Python: every FrameResult field as a read-only property (one `field`
/// line each, converted by to_py), the status enums, and the control points as N x 2 arrays.
#include "bindings.h"

namespace edgetrack_python {

using namespace edgetrack;

namespace {

py::object to_py(bool v) { return py::bool_(v); }
py::object to_py(int v) { return py::int_(v); }
py::object to_py(unsigned v) { return py::int_(v); }
py::object to_py(std::uint64_t v) { return py::int_(v); }
#if !defined(EDGETRACK_REAL_DOUBLE)
py::object to_py(const real& v) { return py::float_(to_float(v)); }
#else
py::object to_py(double v) { return py::float_(v); }
#endif
py::object to_py(const Se3& v) { return matrix_of(v); }
py::object to_py(TrackingStatus v) { return py::cast(v); }
py::object to_py(StatusReason v) { return py::cast(v); }
py::object to_py(const FrameMeasures& v) { return py::cast(v); }
py::object to_py(const PoseSolution& v) { return py::cast(v); }
/// The step times, by step name.
py::object to_py(const int64_t (&v)[kStepCount]) {
  py::dict d;
  for (int s = 0; s < kStepCount; ++s) d[step_name(static_cast<Step>(s))] = v[s];
  return d;
}

/// Read-only properties of the Python class `cls`, one `field` call each: the Python name, a
/// member of the struct Part (the bound object itself, or a struct it holds, reached by `part`)
/// and the docstring; each value converted by to_py when read.
template <class Bound, class Part>
class Fields {
 public:
  using PartOf = const Part& (*)(const Bound&);
  Fields(py::class_<Bound>& cls, PartOf part) : cls_(cls), part_(part) {}

  template <class Member>
  Fields& field(const char* name, Member Part::*member, const char* doc) {
    const PartOf part = part_;
    cls_.def_property_readonly(name, [part, member](const Bound& o) { return to_py(part(o).*member); }, doc);
    return *this;
  }

 private:
  py::class_<Bound>& cls_;
  PartOf part_;
};

/// The rows of a struct bound as itself.
template <class T>
Fields<T, T> fields(py::class_<T>& cls) {
  return {cls, [](const T& o) -> const T& { return o; }};
}

py::array_t<double> points_of(const std::vector<Vec2>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t(2)});
  auto a = out.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i) {
    a(i, 0) = to_float(points[i].x);
    a(i, 1) = to_float(points[i].y);
  }
  return out;
}

}  // namespace

TrackedFrame tracked_frame(const FrameResult& result, const Tracker& tracker) {
  TrackedFrame out{result, {}, {}, {}};
  out.sampled.reserve(tracker.control_points().size());
  for (const ControlPoint& p : tracker.control_points()) out.sampled.push_back(p.pixel);
  out.matched.reserve(tracker.matches().size());
  out.outlier.reserve(tracker.matches().size());
  for (const EdgeMatch& m : tracker.matches()) {
    out.matched.push_back(m.found);
    out.outlier.push_back(m.outlier);
  }
  return out;
}

void bind_results(py::module_& m) {
  py::enum_<TrackingStatus>(m, "Status", "A frame's status (tracking_status.h).")
      .value("TRACKED", TrackingStatus::kTracked)
      .value("UNCERTAIN", TrackingStatus::kUncertain)
      .value("LOST", TrackingStatus::kLost);
  py::enum_<StatusReason> reason(m, "Reason", "Why a frame has its status (tracking_status.h).");
  reason.value("NONE", StatusReason::kNone)
      .value("TOO_FEW_VISIBLE", StatusReason::kTooFewVisible)
      .value("POSE_FAILED", StatusReason::kPoseFailed)
      .value("CHANCE_RESIDUALS", StatusReason::kChanceResiduals)
      .value("FEW_MATCHED", StatusReason::kFewMatched)
      .value("MANY_OUTLIERS", StatusReason::kManyOutliers)
      .value("FEW_TO_CHECK", StatusReason::kFewToCheck)
      .value("LOOSE_FIT", StatusReason::kLooseFit)
      .value("NOT_REACQUIRED", StatusReason::kNotReacquired)
      .value("SATURATED", StatusReason::kSaturated)
      .value("NOT_DETECTED", StatusReason::kNotDetected)
      .value("UNCONFIRMED", StatusReason::kUnconfirmed)
      .value("POSE_UNCONSTRAINED", StatusReason::kPoseUnconstrained)
      .value("POSE_UNDETERMINED", StatusReason::kPoseUndetermined)
      .value("UNSUPPORTED", StatusReason::kUnsupported)
      .value("OVER_LIMIT", StatusReason::kOverLimit)
      .value("DRIFT", StatusReason::kDrift);
  m.def("status_name", [](TrackingStatus s) { return status_name(s); }, py::arg("status"),
        "The status as the poses CSV spells it: tracked, uncertain or lost.");
  m.def("reason_name", [](StatusReason r) { return reason_name(r); }, py::arg("reason"), "The reason in words.");

  py::class_<FrameMeasures> measures(m, "Measures", "What the status rule read of a frame.");
  fields(measures)
      .field("visible", &FrameMeasures::visible, "Visible control points.")
      .field("matched", &FrameMeasures::matched, "Of those, the ones the moving edges found.")
      .field("kept", &FrameMeasures::kept, "Of those, the ones the robust pose solve kept.")
      .field("solved", &FrameMeasures::solved, "The pose step solved.")
      .field("matched_share", &FrameMeasures::matched_share, "kept / visible.")
      .field("inlier_share", &FrameMeasures::inlier_share, "kept / matched.")
      .field("residual_scale", &FrameMeasures::residual_scale, "Robust residual scale, pixels.")
      .field("correction_px", &FrameMeasures::correction_px, "Largest control point move, pixels.")
      .field("translation_change_mm", &FrameMeasures::translation_change_mm, "Solved against predicted, mm.")
      .field("rotation_change_deg", &FrameMeasures::rotation_change_deg, "Solved against predicted, degrees.")
      .field("range", &FrameMeasures::range, "Moving-edge range searched, pixels.")
      .field("after_loss", &FrameMeasures::after_loss, "The previous frame was lost.")
      .field("saturations", &FrameMeasures::saturations, "Fixed-point saturations during the frame.")
      .field("pose_uncertainty_px", &FrameMeasures::pose_uncertainty_px, "Overlay standard deviation, pixels.")
      .field("support_share", &FrameMeasures::support_share, "Share of the visible outline the image gradient supports.")
      .field("gradient_angle_deg", &FrameMeasures::gradient_angle_deg,
       "Mean angle between image gradient and edge normal, degrees (the quality figure).");

  py::class_<PoseSolution> pose(m, "PoseSolution", "The pose step's residuals and counts.");
  fields(pose)
      .field("start_rms", &PoseSolution::start_rms, "RMS point-to-line distance before, pixels.")
      .field("end_rms", &PoseSolution::end_rms, "RMS point-to-line distance after, pixels.")
      .field("evaluations", &PoseSolution::evaluations, "Residual evaluations.")
      .field("iterations", &PoseSolution::iterations, "Jacobian evaluations.")
      .field("outliers", &PoseSolution::outliers, "Matches given weight 0 in the last robust solve.")
      .field("residual_scale", &PoseSolution::residual_scale, "Robust residual scale, pixels.")
      .field("solved", &PoseSolution::solved, "Whether the solve succeeded.");

  py::class_<TrackedFrame> frame(m, "FrameResult", "What one frame did: pose, status, measures, times, points.");
  Fields<TrackedFrame, FrameResult>(frame, [](const TrackedFrame& f) -> const FrameResult& { return f.result; })
      .field("camera_from_model", &FrameResult::camera_from_model,
       "The pose as a 4x4 float64 matrix (on a lost frame, the prediction the next frame starts from).")
      .field("status", &FrameResult::status, "edgetrack.Status.")
      .field("reason", &FrameResult::reason, "edgetrack.Reason.")
      .field("measures", &FrameResult::measures, "edgetrack.Measures: what the status read.")
      .field("step_ns", &FrameResult::step_ns, "Nanoseconds of each of the paper's four steps, by name.")
      .field("points_sampled", &FrameResult::points_sampled, "Visible control points.")
      .field("points_matched", &FrameResult::points_matched, "Of those, matched and kept.")
      .field("grey_pixels", &FrameResult::grey_pixels, "Pixels the grey step converted.")
      .field("pose", &FrameResult::pose, "edgetrack.PoseSolution.")
      .field("retried", &FrameResult::retried, "Tracked again from the last trusted pose.");
  frame
      .def_property_readonly("translation", [](const TrackedFrame& f) { return vector_of(f.result.camera_from_model.translation()); },
                             "The pose's translation, metres, a float64 array of 3.")
      .def_property_readonly("theta_u", [](const TrackedFrame& f) { return vector_of(f.result.camera_from_model.theta_u()); },
                             "The pose's rotation as theta-u, radians, a float64 array of 3.")
      .def_property_readonly("status_name", [](const TrackedFrame& f) { return status_name(f.result.status); },
                             "The status as the poses CSV spells it.")
      .def_property_readonly("reason_name", [](const TrackedFrame& f) { return reason_name(f.result.reason); },
                             "The reason in words.")
      .def_property_readonly("ms", [](const TrackedFrame& f) {
        long long ns = 0;
        for (int64_t s : f.result.step_ns) ns += s;
        return ns / 1e6;
      }, "The four steps' time together, milliseconds (the poses CSV's ms).")
      .def_property_readonly("sampled_points", [](const TrackedFrame& f) { return points_of(f.sampled); },
                             "The visible control points, N x 2 float64 (x, y pixels).")
      .def_property_readonly("matched_points", [](const TrackedFrame& f) { return points_of(f.matched); },
                             "The edge points the moving edges found, M x 2 float64 (x, y pixels).")
      .def_property_readonly("outliers", [](const TrackedFrame& f) {
        py::array_t<bool> out(static_cast<py::ssize_t>(f.outlier.size()));
        auto a = out.mutable_unchecked<1>();
        for (size_t i = 0; i < f.outlier.size(); ++i) a(i) = f.outlier[i];
        return out;
      }, "For each matched point, whether the pose step gave it no weight.");
}

}  // namespace edgetrack_python
