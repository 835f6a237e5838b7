// SPDX-License-Identifier: BSD-3-Clause
/// Clicking the initial points in an OpenCV (highgui) window on the host.
#include "click_init.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <opencv2/highgui.hpp>
#include <opencv2/imgproc.hpp>

#include "edgetrack/contours.h"
#include "edgetrack/pose_io.h"
#include "pose_from_points.h"

// Last: Xlib defines macros (Status, None, Bool) that other headers use as names.
#include <X11/Xlib.h>

using edgetrack::Error;
using edgetrack::Face;
using edgetrack::Result;
using edgetrack::Se3;
using edgetrack::Vec2;
using edgetrack::Vec3;

namespace edgetrack_app {
namespace {

const char* const kWindow = "edgetrack: click the initial points";
const char* const kInstead = "; give the points' image positions with --init I.init --init-points P.txt instead";

/// Checked first: without a reachable X display, highgui's toolkit aborts the whole process.
Result<bool> check_display() {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0')
    return Error{"", 0, std::string("--init-click needs a display (DISPLAY is not set)") + kInstead};
  Display* display = XOpenDisplay(name);
  if (display == nullptr)
    return Error{"", 0, std::string("--init-click cannot open the display '") + name + "'" + kInstead};
  XCloseDisplay(display);
  return true;
}

struct Clicks {
  std::vector<cv::Point> points;
  size_t wanted = 0;
};

void on_mouse(int event, int x, int y, int, void* user) {
  Clicks& clicks = *static_cast<Clicks*>(user);
  if (event == cv::EVENT_LBUTTONDOWN && clicks.points.size() < clicks.wanted) clicks.points.emplace_back(x, y);
}

/// Text lines on a darkened band at the top of the view.
void caption(cv::Mat& view, const std::vector<std::string>& lines) {
  const int band = 10 + 20 * static_cast<int>(lines.size());
  cv::Mat top = view(cv::Rect(0, 0, view.cols, std::min(band, view.rows)));
  top *= 0.35;
  for (size_t i = 0; i < lines.size(); ++i)
    cv::putText(view, lines[i], {8, 22 + 20 * static_cast<int>(i)}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {255, 255, 255}, 1,
                cv::LINE_AA);
}

void draw_clicks(cv::Mat& view, const std::vector<cv::Point>& points) {
  for (size_t i = 0; i < points.size(); ++i) {
    cv::circle(view, points[i], 6, {0, 0, 255}, 2, cv::LINE_AA);
    cv::putText(view, std::to_string(i + 1), points[i] + cv::Point(8, -8), cv::FONT_HERSHEY_SIMPLEX, 0.55, {0, 0, 255},
                2, cv::LINE_AA);
  }
}

void draw_model(cv::Mat& view, const edgetrack::EdgeModel& model, const edgetrack::PinholeCamera& camera,
                const Se3& pose) {
  auto pixel = [&](const Vec3& p, cv::Point2d& out) {
    const Vec3 c = pose * p;
    if (static_cast<double>(c.z) <= 1e-3) return false;
    const Vec2 uv = camera.project(c);
    out = {static_cast<double>(uv.x), static_cast<double>(uv.y)};
    return true;
  };
  for (const auto& edge : model.edges) {
    cv::Point2d a, b;
    if (pixel(model.vertices[edge.a], a) && pixel(model.vertices[edge.b], b))
      cv::line(view, a, b, {0, 255, 0}, 1, cv::LINE_AA);
  }
  std::vector<edgetrack::ContourSegment> curved;
  edgetrack::curved_contours(model, pose, curved);
  for (const edgetrack::ContourSegment& segment : curved) {
    cv::Point2d a, b;
    if (pixel(segment.a, a) && pixel(segment.b, b)) cv::line(view, a, b, {0, 255, 0}, 1, cv::LINE_AA);
  }
}

/// A small orthographic drawing of the model in the top-right corner, the .init points on it
/// and the one to click next (`current`) in red: where on the object that point is. It is seen
/// from the side the .init points are on (they are meant to be visible), tilted a little so
/// that no face is seen edge-on; edges of faces turned away are drawn dim on a closed model.
void draw_sketch(cv::Mat& view, const edgetrack::EdgeModel& model, const std::vector<Vec3>& points, size_t current) {
  auto point3 = [](const Vec3& p) {
    return cv::Point3d(static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z));
  };
  cv::Point3d model_centre(0, 0, 0), points_centre(0, 0, 0);
  for (const Vec3& v : model.vertices) model_centre += point3(v) * (1.0 / static_cast<double>(model.vertices.size()));
  for (const Vec3& p : points) points_centre += point3(p) * (1.0 / static_cast<double>(points.size()));
  cv::Point3d towards_viewer = points_centre - model_centre;
  if (cv::norm(towards_viewer) < 1e-9) towards_viewer = {1, -1, 1};
  towards_viewer *= 1.0 / cv::norm(towards_viewer);
  // The model axes from least to most aligned with the view: the first tilts it, the second is up.
  std::vector<cv::Point3d> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::sort(axes.begin(), axes.end(), [&](const cv::Point3d& a, const cv::Point3d& b) {
    return std::fabs(a.dot(towards_viewer)) < std::fabs(b.dot(towards_viewer));
  });
  towards_viewer += 0.45 * axes[0];
  towards_viewer *= 1.0 / cv::norm(towards_viewer);
  const cv::Point3d forward = -towards_viewer;  // the sketch's camera looks along +z
  cv::Point3d down = -(axes[1] - axes[1].dot(forward) * forward);
  down *= 1.0 / cv::norm(down);
  const cv::Point3d right = down.cross(forward);
  auto turn = [&](const Vec3& p) {
    const cv::Point3d q = point3(p);
    return cv::Point3d(right.dot(q), down.dot(q), forward.dot(q));
  };
  cv::Point3d low(1e30, 1e30, 0), high(-1e30, -1e30, 0), centre(0, 0, 0);
  for (const Vec3& v : model.vertices) {
    const cv::Point3d t = turn(v);
    low = {std::min(low.x, t.x), std::min(low.y, t.y), 0};
    high = {std::max(high.x, t.x), std::max(high.y, t.y), 0};
    centre += t * (1.0 / static_cast<double>(model.vertices.size()));
  }
  const int box = std::min(160, std::min(view.cols, view.rows) / 3), margin = 12;
  const cv::Rect area(view.cols - box - 8, 58, box, box);
  if (model.vertices.empty() || area.y + box > view.rows) return;
  const double scale = (box - 2 * margin) / std::max(1e-9, std::max(high.x - low.x, high.y - low.y));
  auto pixel = [&](const cv::Point3d& t) {
    return cv::Point2d(area.x + margin + (t.x - low.x) * scale, area.y + margin + (t.y - low.y) * scale);
  };
  // Faces turned towards the viewer (looking along +z), with outward normals: the normals of a
  // closed model all point out or all in, which the sum over faces of n . (face - centre) tells.
  std::vector<double> towards(model.faces.size(), 0.0);
  double outward = 0;
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const Face& face = model.faces[f];
    if (face.vertices.empty()) continue;
    cv::Point3d middle(0, 0, 0);
    for (int v : face.vertices) middle += turn(model.vertices[v]) * (1.0 / static_cast<double>(face.vertices.size()));
    const cv::Point3d normal = turn(face.normal);
    outward += normal.dot(middle - centre);
    towards[f] = -normal.z;
  }
  cv::Mat inset = view(area);
  inset *= 0.3;
  for (const auto& edge : model.edges) {
    bool seen = !model.closed;
    for (int f : edge.faces) seen = seen || f < 0 || (outward >= 0 ? towards[f] : -towards[f]) > 1e-9;
    cv::line(view, pixel(turn(model.vertices[edge.a])), pixel(turn(model.vertices[edge.b])),
             seen ? cv::Scalar(240, 240, 240) : cv::Scalar(90, 90, 90), 1, cv::LINE_AA);
  }
  for (size_t i = 0; i < points.size(); ++i) {
    const cv::Point2d at = pixel(turn(points[i]));
    const cv::Scalar colour = i == current ? cv::Scalar(0, 0, 255) : cv::Scalar(0, 200, 255);
    cv::circle(view, at, i == current ? 5 : 3, colour, cv::FILLED, cv::LINE_AA);
    cv::putText(view, std::to_string(i + 1), at + cv::Point2d(6, 14), cv::FONT_HERSHEY_SIMPLEX,
                i == current ? 0.5 : 0.4, colour, 1, cv::LINE_AA);
  }
}

bool window_closed() { return cv::getWindowProperty(kWindow, cv::WND_PROP_VISIBLE) < 1; }

std::string point_text(size_t i, size_t n, const Vec3& p) {
  char text[160];
  std::snprintf(text, sizeof text, "click point %zu of %zu: (%.3f, %.3f, %.3f) m in the model frame", i + 1, n,
                static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z));
  return text;
}

enum class Answer { kAccept, kAgain, kCancel };

/// Collects one click per 3D point (Backspace or u undoes the last one, h hides the sketch in
/// case it covers a point); false on cancel.
bool collect_clicks(const cv::Mat& frame, const edgetrack::EdgeModel& model, const std::vector<Vec3>& points,
                    const std::string& note, Clicks& clicks) {
  clicks.points.clear();
  if (!note.empty()) std::fprintf(stderr, "%s\n", note.c_str());
  size_t shown = SIZE_MAX;
  bool sketch = true;
  for (;;) {
    const size_t n = clicks.points.size();
    if (n != shown) {
      shown = n;
      if (n == points.size()) return true;
      const std::string prompt = point_text(n, points.size(), points[n]);
      std::vector<std::string> lines = {prompt,
                                        "Backspace or u: undo the last click   h: hide/show the sketch   Esc: cancel"};
      if (!note.empty()) lines.insert(lines.begin(), note);
      cv::Mat view = frame.clone();
      caption(view, lines);
      if (sketch) draw_sketch(view, model, points, n);
      draw_clicks(view, clicks.points);
      cv::imshow(kWindow, view);
      std::fprintf(stderr, "%s\n", prompt.c_str());
    }
    const int key = cv::waitKey(30);
    if (key == 27 || window_closed()) return false;
    if ((key == 8 || key == 'u') && !clicks.points.empty()) clicks.points.pop_back();
    if (key == 'h') {
      sketch = !sketch;
      shown = SIZE_MAX;
    }
  }
}

/// Shows the model at `pose` over the clicks and waits for the user's answer.
Answer confirm(const cv::Mat& frame, const edgetrack::EdgeModel& model, const edgetrack::PinholeCamera& camera,
               const PointPose& pose, const std::vector<Vec3>& points, const Clicks& clicks) {
  cv::Mat view = frame.clone();
  draw_model(view, model, camera, pose.camera_from_model);
  draw_clicks(view, clicks.points);
  for (const Vec3& p : points) {
    const Vec2 uv = camera.project(pose.camera_from_model * p);
    cv::drawMarker(view,
                   {static_cast<int>(std::lround(static_cast<double>(uv.x))),
                    static_cast<int>(std::lround(static_cast<double>(uv.y)))},
                   {0, 255, 255}, cv::MARKER_CROSS, 10, 1);
  }
  char error[128];
  std::snprintf(error, sizeof error, "the model at the pose from the clicks (reprojection error %.2f px rms)",
                pose.rms_px);
  caption(view, {error, "Enter or Space: accept   r: click again   Esc: cancel"});
  cv::imshow(kWindow, view);
  std::fprintf(stderr, "%s; press Enter or Space to accept, r to click again, Esc to cancel\n", error);
  for (;;) {
    const int key = cv::waitKey(30);
    if (key == 13 || key == 10 || key == ' ') return Answer::kAccept;
    if (key == 'r') return Answer::kAgain;
    if (key == 27 || window_closed()) return Answer::kCancel;
  }
}

Result<bool> save_clicks(const std::string& path, const std::string& init_path, const std::vector<cv::Point>& points) {
  FILE* out = std::fopen(path.c_str(), "w");
  if (out == nullptr) return Error{path, 0, "cannot write the file"};
  std::fprintf(out, "# u v (pixels) of the points of %s, clicked on the first frame\n", init_path.c_str());
  for (const cv::Point& p : points) std::fprintf(out, "%d %d\n", p.x, p.y);
  if (std::fclose(out) != 0) return Error{path, 0, "cannot write the file"};
  return true;
}

}  // namespace

Result<Se3> click_initial_pose(const ClickInitOptions& options, const RgbImage& frame,
                               const edgetrack::PinholeCamera& camera, const edgetrack::EdgeModel& model) {
  auto points = read_init_points(options.init_path);
  if (!points.ok()) return points.error();
  auto display = check_display();
  if (!display.ok()) return display.error();

  cv::Mat bgr;
  cv::cvtColor(cv::Mat(frame.height, frame.width, CV_8UC3, const_cast<uint8_t*>(frame.rgb.data())), bgr,
               cv::COLOR_RGB2BGR);
  cv::namedWindow(kWindow, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);  // no toolbar: clicks land on image pixels
  Clicks clicks;
  clicks.wanted = points.value().size();
  cv::setMouseCallback(kWindow, on_mouse, &clicks);
  std::string note;
  Result<PointPose> pose = Error{options.init_path, 0, "no pose"};
  for (;;) {
    if (!collect_clicks(bgr, model, points.value(), note, clicks)) {
      cv::destroyWindow(kWindow);
      return Error{options.init_path, 0, "clicking the initial points was cancelled"};
    }
    std::vector<Vec2> pixels;
    for (const cv::Point& p : clicks.points) pixels.push_back({real(p.x), real(p.y)});
    pose = pose_from_points(points.value(), pixels, camera, "the clicked points");
    if (!pose.ok()) {
      note = "no pose from these clicks (" + pose.error().message + "): click again";
      continue;
    }
    const Answer answer = confirm(bgr, model, camera, pose.value(), points.value(), clicks);
    if (answer == Answer::kAccept) break;
    if (answer == Answer::kCancel) {
      cv::destroyWindow(kWindow);
      return Error{options.init_path, 0, "clicking the initial points was cancelled"};
    }
    note.clear();
  }
  cv::destroyWindow(kWindow);
  cv::waitKey(1);
  std::fprintf(stderr, "initial pose from %zu clicked points, reprojection error %.2f px rms\n", clicks.points.size(),
               pose.value().rms_px);
  if (!options.save_points.empty()) {
    auto saved = save_clicks(options.save_points, options.init_path, clicks.points);
    if (!saved.ok()) return saved.error();
  }
  if (!options.save_pose.empty()) {
    auto saved = edgetrack::write_pos(options.save_pose, pose.value().camera_from_model);
    if (!saved.ok()) return saved.error();
  }
  return pose.value().camera_from_model;
}

}  // namespace edgetrack_app
