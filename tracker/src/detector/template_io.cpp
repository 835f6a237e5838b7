// SPDX-License-Identifier: BSD-3-Clause
/// Reading and writing template files.
#include "edgetrack/detector/template_io.h"

#include <cstdio>

#include "edgetrack/detector/gradient_orientations.h"
#include "edgetrack/number_text.h"

namespace edgetrack {

namespace {

constexpr const char* kMagic = "edgetrack-templates";

/// The words of a template file, read in order, each refusal naming the file and the line.
class WordCursor {
 public:
  WordCursor(const std::vector<Word>& words, const std::string& path) : words_(words), path_(path) {}

  Result<bool> keyword(const char* expected) {
    if (i_ >= words_.size()) return end_error(std::string("'") + expected + "'");
    const Word& w = words_[i_++];
    if (w.text != expected) return Error{path_, w.line, std::string("expected '") + expected + "', found '" + w.text + "'"};
    return true;
  }
  Result<double> number(const FieldRange& range) {
    if (i_ >= words_.size()) return end_error(range.field);
    const Word& w = words_[i_++];
    return parse_field(w.text, range, path_, w.line);
  }
  Result<long long> whole(const FieldRange& range) {
    if (i_ >= words_.size()) return end_error(range.field);
    const Word& w = words_[i_++];
    return parse_whole_field(w.text, range, path_, w.line);
  }
  Result<std::string> text(const char* field) {
    if (i_ >= words_.size()) return end_error(field);
    return words_[i_++].text;
  }
  int line() const { return i_ == 0 ? 1 : words_[i_ - 1].line; }
  bool done() const { return i_ >= words_.size(); }
  const Word& current() const { return words_[i_]; }

 private:
  Error end_error(const std::string& what) const {
    return Error{path_, words_.empty() ? 1 : words_.back().line, "the file ends where " + what + " was expected"};
  }
  const std::vector<Word>& words_;
  const std::string& path_;
  size_t i_ = 0;
};

double d(const real& value) { return static_cast<double>(value); }

bool write_header(std::FILE* file, const TemplateSet& set) {
  const ViewRange& v = set.params.views;
  bool ok = std::fprintf(file, "%s %d\nmodel %s\ncamera %s\n", kMagic, kTemplateFormatVersion,
                         set.model_fingerprint.c_str(), camera_description(set.camera).c_str()) > 0;
  ok = ok && std::fprintf(file, "views %d %.9g %.9g %.9g %.9g %d %.9g %.9g %.9g\n", v.subdivisions, d(v.axis.x),
                          d(v.axis.y), d(v.axis.z), d(v.max_angle), v.in_plane_steps, d(v.distance_min),
                          d(v.distance_max), d(v.distance_ratio)) > 0;
  ok = ok && std::fprintf(file, "features %d %d %d %.9g\n", set.params.downscale, set.params.features,
                          set.params.min_features, d(set.params.sample_step)) > 0;
  ok = ok && std::fprintf(file, "extent %.9g %.9g %.9g %.9g\ndistances %d\ntemplates %zu\n", d(set.extent.centre.x),
                          d(set.extent.centre.y), d(set.extent.centre.z), d(set.extent.radius), set.distance_count,
                          set.templates.size()) > 0;
  return ok;
}

bool write_template(std::FILE* file, const TemplateSet& set, const Template& t) {
  const Vec3& tu = t.theta_u;
  bool ok = std::fprintf(file, "t %d %.9g %.9g %.9g %.9g %.9g %.9g %d %d %d", t.distance_index, d(t.distance),
                         d(tu.x), d(tu.y), d(tu.z), d(t.anchor.x),
                         d(t.anchor.y), t.width, t.height, t.count) > 0;
  for (int f = t.first; f < t.first + t.count && ok; ++f) {
    const TemplateFeature& feature = set.features[static_cast<size_t>(f)];
    ok = std::fprintf(file, " %d %d %d", feature.x, feature.y, feature.bin) > 0;
  }
  return ok && std::fputc('\n', file) != EOF;
}


/// Reads numbers into `out` in order; the first refusal is returned.
Result<bool> read_numbers(WordCursor& in, const FieldRange* ranges, int count, double* out) {
  for (int i = 0; i < count; ++i) {
    auto value = in.number(ranges[i]);
    if (!value.ok()) return value.error();
    out[i] = value.value();
  }
  return true;
}

Result<bool> read_whole_numbers(WordCursor& in, const FieldRange* ranges, int count, long long* out) {
  for (int i = 0; i < count; ++i) {
    auto value = in.whole(ranges[i]);
    if (!value.ok()) return value.error();
    out[i] = value.value();
  }
  return true;
}

/// The header's identity: magic, version, model, camera; checked against the ones in use.
Result<bool> read_identity(WordCursor& in, const std::string& path, const EdgeModel& model,
                           const PinholeCamera& camera, TemplateSet& set) {
  auto magic = in.text("the file type");
  if (!magic.ok()) return magic.error();
  if (magic.value() != kMagic) return Error{path, in.line(), "not an edgetrack template file (no 'edgetrack-templates' header)"};
  auto version = in.whole({"format version", 0, 1e6});
  if (!version.ok()) return version.error();
  if (version.value() != kTemplateFormatVersion && version.value() != 1)
    return Error{path, in.line(), "template format version " + std::to_string(version.value()) +
                                      ", this edgetrack reads version " + std::to_string(kTemplateFormatVersion)};
  const int version_line = in.line();
  auto key = in.keyword("model");
  if (!key.ok()) return key.error();
  auto fingerprint = in.text("the model fingerprint");
  if (!fingerprint.ok()) return fingerprint.error();
  if (fingerprint.value() != model_fingerprint(model))
    return Error{path, in.line(), "made for another model (" + fingerprint.value() + ", the model given is " +
                                      model_fingerprint(model) + "): make them again with edgetrack templates"};
  key = in.keyword("camera");
  if (!key.ok()) return key.error();
  static const FieldRange kCamera[4] = {{"px", 1e-3, 1e7}, {"py", 1e-3, 1e7}, {"u0", -1e7, 1e7}, {"v0", -1e7, 1e7}};
  static const FieldRange kSize[2] = {{"width", 16, 16384}, {"height", 16, 16384}};
  double c[4];
  long long size[2];
  auto numbers = read_numbers(in, kCamera, 4, c);
  if (!numbers.ok()) return numbers.error();
  numbers = read_whole_numbers(in, kSize, 2, size);
  if (!numbers.ok()) return numbers.error();
  set.camera = {real(c[0]), real(c[1]), real(c[2]), real(c[3]), static_cast<int>(size[0]), static_cast<int>(size[1])};
  if (camera_description(set.camera) != camera_description(camera))
    return Error{path, in.line(), "made for another camera (" + camera_description(set.camera) +
                                      ", the camera given is " + camera_description(camera) + ")"};
  // Version 1 made templates at the camera's full size; for a camera detection reduces they are
  // not the ones this version would match, for any other the very same.
  if (version.value() == 1 && detection_reduction(set.camera) > 1)
    return Error{path, version_line, "template format version 1 for frames above " + std::to_string(kMaxDetectionSide) +
                                         " px on their shorter side, made at full size; this edgetrack detects such "
                                         "frames reduced (version " + std::to_string(kTemplateFormatVersion) +
                                         "): make them again with edgetrack templates"};
  return true;
}

/// The parameters, the model's extent and the counts.
Result<bool> read_parameters(WordCursor& in, const std::string& path, TemplateSet& set, long long& templates) {
  auto key = in.keyword("views");
  if (!key.ok()) return key.error();
  static const FieldRange kViews[9] = {{"subdivisions", 0, 4},        {"axis x", -1e3, 1e3},     {"axis y", -1e3, 1e3},
                                       {"axis z", -1e3, 1e3},         {"cone angle (rad)", 0, 4}, {"in-plane steps", 1, 360},
                                       {"nearest distance (m)", 0, 1e3}, {"farthest distance (m)", 0, 1e3},
                                       {"distance ratio", 1, 4}};
  double v[9];
  auto numbers = read_numbers(in, kViews, 9, v);
  if (!numbers.ok()) return numbers.error();
  ViewRange& views = set.params.views;
  views.subdivisions = static_cast<int>(v[0]);
  views.axis = {real(v[1]), real(v[2]), real(v[3])};
  views.max_angle = real(v[4]);
  views.in_plane_steps = static_cast<int>(v[5]);
  views.distance_min = real(v[6]);
  views.distance_max = real(v[7]);
  views.distance_ratio = real(v[8]);
  key = in.keyword("features");
  if (!key.ok()) return key.error();
  static const FieldRange kFeatures[4] = {{"downscale", 1, 4}, {"features", 4, 63}, {"min features", 4, 63},
                                          {"sample step (px)", 1, 20}};
  double f[4];
  numbers = read_numbers(in, kFeatures, 4, f);
  if (!numbers.ok()) return numbers.error();
  set.params.downscale = static_cast<int>(f[0]);
  set.params.features = static_cast<int>(f[1]);
  set.params.min_features = static_cast<int>(f[2]);
  set.params.sample_step = real(f[3]);
  auto checked = check_template_params(set.params);
  if (!checked.ok()) return Error{path, in.line(), checked.error().message};
  key = in.keyword("extent");
  if (!key.ok()) return key.error();
  static const FieldRange kExtent[4] = {{"centre x (m)", -1e3, 1e3}, {"centre y (m)", -1e3, 1e3},
                                        {"centre z (m)", -1e3, 1e3}, {"radius (m)", 1e-6, 1e3}};
  double e[4];
  numbers = read_numbers(in, kExtent, 4, e);
  if (!numbers.ok()) return numbers.error();
  set.extent.centre = {real(e[0]), real(e[1]), real(e[2])};
  set.extent.radius = real(e[3]);
  static const FieldRange kCounts[2] = {{"distances", 1, 1000}, {"templates", 1, 1e6}};
  long long counts[2];
  key = in.keyword("distances");
  if (!key.ok()) return key.error();
  numbers = read_whole_numbers(in, kCounts, 1, counts);
  if (!numbers.ok()) return numbers.error();
  key = in.keyword("templates");
  if (!key.ok()) return key.error();
  numbers = read_whole_numbers(in, kCounts + 1, 1, counts + 1);
  if (!numbers.ok()) return numbers.error();
  set.distance_count = static_cast<int>(counts[0]);
  templates = counts[1];
  return true;
}

/// One template line: "t", its view and its features.
Result<bool> read_template(WordCursor& in, TemplateSet& set) {
  auto key = in.keyword("t");
  if (!key.ok()) return key.error();
  const FieldRange index_range{"distance index", 0, static_cast<double>(set.distance_count - 1)};
  auto index = in.whole(index_range);
  if (!index.ok()) return index.error();
  static const FieldRange kView[6] = {{"distance (m)", 1e-6, 1e3}, {"tux (rad)", -7, 7},
                                      {"tuy (rad)", -7, 7},        {"tuz (rad)", -7, 7},
                                      {"anchor x (px)", -1e4, 1e4}, {"anchor y (px)", -1e4, 1e4}};
  double v[6];
  auto numbers = read_numbers(in, kView, 6, v);
  if (!numbers.ok()) return numbers.error();
  const FieldRange kShape[3] = {{"width (px)", 1, 256}, {"height (px)", 1, 256},
                                {"feature count", 1, static_cast<double>(set.params.features)}};
  long long shape[3];
  numbers = read_whole_numbers(in, kShape, 3, shape);
  if (!numbers.ok()) return numbers.error();
  Template t;
  t.distance_index = static_cast<int>(index.value());
  t.distance = real(v[0]);
  t.theta_u = {real(v[1]), real(v[2]), real(v[3])};
  t.anchor = {real(v[4]), real(v[5])};
  t.width = static_cast<int>(shape[0]);
  t.height = static_cast<int>(shape[1]);
  t.first = static_cast<int>(set.features.size());
  t.count = static_cast<int>(shape[2]);
  const FieldRange kFeature[3] = {{"feature x (px)", 0, static_cast<double>(t.width - 1)},
                                  {"feature y (px)", 0, static_cast<double>(t.height - 1)},
                                  {"feature orientation bin", 0, kOrientationBins - 1}};
  for (int f = 0; f < t.count; ++f) {
    long long xyb[3];
    numbers = read_whole_numbers(in, kFeature, 3, xyb);
    if (!numbers.ok()) return numbers.error();
    set.features.push_back({static_cast<uint8_t>(xyb[0]), static_cast<uint8_t>(xyb[1]), static_cast<uint8_t>(xyb[2])});
  }
  set.templates.push_back(t);
  return true;
}

}  // namespace

std::string camera_description(const PinholeCamera& c) {
  char text[192];
  std::snprintf(text, sizeof text, "%.6f %.6f %.6f %.6f %d %d", d(c.px), d(c.py), d(c.u0), d(c.v0), c.width, c.height);
  return text;
}

Result<bool> write_templates(const std::string& path, const TemplateSet& set) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return Error{path, 0, "cannot open the file for writing"};
  bool ok = write_header(file, set);
  for (const Template& t : set.templates) ok = ok && write_template(file, set, t);
  ok = (std::fclose(file) == 0) && ok;
  if (!ok) return Error{path, 0, "write failed"};
  return true;
}

Result<TemplateSet> read_templates(const std::string& path, const EdgeModel& model, const PinholeCamera& camera) {
  auto words = read_words(path);
  if (!words.ok()) return words.error();
  WordCursor in(words.value(), path);
  TemplateSet set;
  auto step = read_identity(in, path, model, camera, set);
  if (!step.ok()) return step.error();
  long long count = 0;
  step = read_parameters(in, path, set, count);
  if (!step.ok()) return step.error();
  set.model_fingerprint = model_fingerprint(model);
  for (long long k = 0; k < count; ++k) {
    step = read_template(in, set);
    if (!step.ok()) return step.error();
  }
  if (!in.done())
    return Error{path, in.current().line, "more than the " + std::to_string(count) + " templates the header states"};
  return set;
}

}  // namespace edgetrack
