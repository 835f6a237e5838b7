// SPDX-License-Identifier: BSD-3-Clause
/// Line charts of a run with OpenCV: time per frame (Fig. 4) and camera position per axis (Fig. 5).
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plots.h"

using edgetrack::Error;
using edgetrack::Result;

namespace edgetrack_app {
namespace {

struct Series {
  std::vector<double> x, y;
  cv::Scalar colour;
  std::string label;
  bool dashed = false;
};

/// A "nice" tick step covering `span` in about `count` steps: 1, 2 or 5 times a power of ten.
double tick_step(double span, int count) {
  const double raw = span / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", std::fabs(v) < 1e-12 ? 0.0 : v);
  return text;
}

/// Draws one chart into `area` of `canvas`: axes with ticks, the series, a legend and labels.
void draw_chart(cv::Mat& canvas, const cv::Rect& area, const std::vector<Series>& series, const std::string& title,
                const std::string& x_label, const std::string& y_label) {
  const cv::Scalar black(0, 0, 0), grid(225, 225, 225);
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  const cv::Rect plot(area.x + 70, area.y + 30, area.width - 90, area.height - 75);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Series& s : series)
    for (size_t i = 0; i < s.x.size(); ++i) {
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 - y0 < 1e-9) {
    y0 -= 1;
    y1 += 1;
  }
  const double pad = 0.08 * (y1 - y0);
  y0 -= pad;
  y1 += pad;
  const double ystep = tick_step(y1 - y0, 6), xstep = tick_step(x1 - x0, 8);
  y0 = std::floor(y0 / ystep) * ystep;
  y1 = std::ceil(y1 / ystep) * ystep;
  auto to_px = [&](double x, double y) {
    return cv::Point(plot.x + static_cast<int>(std::lround((x - x0) / (x1 - x0) * plot.width)),
                     plot.y + plot.height - static_cast<int>(std::lround((y - y0) / (y1 - y0) * plot.height)));
  };
  for (double y = y0; y <= y1 + ystep / 2; y += ystep) {
    const cv::Point p = to_px(x0, y);
    cv::line(canvas, p, {plot.x + plot.width, p.y}, grid, 1);
    cv::putText(canvas, format(y), {area.x + 8, p.y + 5}, font, 0.42, black, 1, cv::LINE_AA);
  }
  for (double x = std::ceil(x0 / xstep) * xstep; x <= x1 + xstep / 2; x += xstep) {
    const cv::Point p = to_px(x, y0);
    cv::line(canvas, p, {p.x, plot.y}, grid, 1);
    cv::putText(canvas, format(x), {p.x - 8, p.y + 18}, font, 0.42, black, 1, cv::LINE_AA);
  }
  cv::rectangle(canvas, plot, black, 1);
  for (const Series& s : series) {
    for (size_t i = 1; i < s.x.size(); ++i) {
      if (s.dashed && i % 2 == 0) continue;
      cv::line(canvas, to_px(s.x[i - 1], s.y[i - 1]), to_px(s.x[i], s.y[i]), s.colour, 2, cv::LINE_AA);
    }
    for (size_t i = 0; i < s.x.size() && !s.dashed; ++i) cv::circle(canvas, to_px(s.x[i], s.y[i]), 2, s.colour, -1, cv::LINE_AA);
  }
  cv::putText(canvas, title, {plot.x, area.y + 20}, font, 0.55, black, 1, cv::LINE_AA);
  cv::putText(canvas, x_label, {plot.x + plot.width / 2 - 20, area.y + area.height - 12}, font, 0.45, black, 1, cv::LINE_AA);
  cv::putText(canvas, y_label, {area.x + 8, plot.y - 8}, font, 0.42, black, 1, cv::LINE_AA);
  int legend_y = plot.y + 18;
  for (const Series& s : series) {
    const int lx = plot.x + plot.width - 150;
    cv::line(canvas, {lx, legend_y - 4}, {lx + 25, legend_y - 4}, s.colour, 2, cv::LINE_AA);
    cv::putText(canvas, s.label, {lx + 32, legend_y}, font, 0.42, black, 1, cv::LINE_AA);
    legend_y += 18;
  }
}

Result<bool> save(const std::string& path, const cv::Mat& canvas) {
  bool ok = false;
  try {
    ok = cv::imwrite(path, canvas);
  } catch (const cv::Exception& e) {
    return Error{path, 0, std::string("cannot write the plot: ") + e.what()};
  }
  if (!ok) return Error{path, 0, "cannot write the plot"};
  return true;
}

}  // namespace

Result<bool> write_plots(const std::string& dir, const Evaluation& evaluation) {
  const cv::Scalar blue(200, 90, 30), red(40, 40, 220);
  Series time{{}, {}, blue, "tracking", false};
  for (const FrameError& f : evaluation.frames) {
    time.x.push_back(f.frame);
    time.y.push_back(f.ms);
  }
  cv::Mat fig4(360, 720, CV_8UC3, cv::Scalar(255, 255, 255));
  draw_chart(fig4, {0, 0, 720, 360}, {time}, "Fig. 4: total computation time per frame", "frame", "ms");
  auto saved = save(dir + "/fig4_time_per_frame.png", fig4);
  if (!saved.ok()) return saved;

  const char* axes[3] = {"x", "y", "z"};
  cv::Mat fig5(3 * 300, 720, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int a = 0; a < 3; ++a) {
    Series tracked{{}, {}, blue, "tracked", false}, truth{{}, {}, red, "ground truth", true};
    for (const FrameError& f : evaluation.frames) {
      tracked.x.push_back(f.frame);
      tracked.y.push_back(f.position[a]);
      truth.x.push_back(f.frame);
      truth.y.push_back(f.true_position[a]);
    }
    draw_chart(fig5, {0, a * 300, 720, 300}, {truth, tracked},
               std::string("Fig. 5") + char('a' + a) + ": camera position, " + axes[a] + " axis (object frame)", "frame", "mm");
  }
  return save(dir + "/fig5_camera_position.png", fig5);
}

}  // namespace edgetrack_app
