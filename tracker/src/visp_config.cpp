// SPDX-License-Identifier: BSD-3-Clause
/// ViSP's configuration blocks read onto the camera and the tracker settings. Facts from
/// vpMbtXmlGenericParser (ViSP 3.5): each block's children are looked up by name and unknown
/// ones are passed over; a block may come more than once and each occurrence applies in turn;
/// the sample step is read as an integer, inside <ecm> or (older files) beside it.
#include "edgetrack/visp_config.h"

#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstdlib>
#include <string>

#include "edgetrack/image_limits.h"
#include "edgetrack/angles.h"
#include "edgetrack/tracker_inputs.h"
#include "edgetrack/tracker_params.h"
#include "edgetrack/xml_document.h"

namespace edgetrack {
namespace {

/// Reads one file's elements onto a copy of the configuration.
class Reading {
 public:
  Reading(const std::string& path, const TrackerConfig& start) : path_(path), config_(start) {}

  Result<bool> root(const XmlElement& root) {
    // ViSP reads the root's children only; a file whose root is the camera block itself (as
    // edgetrack's older camera files) would keep ViSP's default camera, so it is read as one.
    if (root.name == "camera") return camera(root);
    for (const XmlElement& block : root.children) {
      Result<bool> read = true;
      if (block.name == "camera") read = camera(block);
      else if (block.name == "ecm") read = ecm(block);
      else if (block.name == "sample") read = sample(block, "sample");
      else if (block.name == "face") read = face(block);
      else if (block.name == "lod") read = lod(block);
      else if (block.name == "status") read = status(block, "<status>");
      else if (block.name == "edgetrack") read = edgetrack_block(block);
      else if (block.name == "projection_error")
        note("<projection_error> (ViSP's projection-error diagnostic, which edgetrack does not compute)");
      if (!read.ok()) return read;
    }
    return true;
  }
  const TrackerConfig& config() const { return config_; }
  ConfigNotes& notes() { return notes_; }

 private:
  Error bad(const XmlElement& e, const std::string& where, const std::string& what) const {
    return Error{path_, e.line, where + " " + what};
  }

  /// The element's text as a number; `where` names it in an error ("<ecm><range><tracking>").
  Result<double> number(const XmlElement& e, const std::string& where) const {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(e.text.c_str(), &end);
    if (e.text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value))
      return bad(e, where, "is not a number: '" + e.text + "'");
    return value;
  }
  /// The element's text as a whole number, where ViSP reads an integer. ViSP's reading stops at
  /// the first character that is not a digit, so a decimal fraction ("4.5") counts as its whole
  /// part; it is taken so, and named in the notes. Any other text is refused.
  Result<long> whole(const XmlElement& e, const std::string& where) {
    errno = 0;
    char* end = nullptr;
    const long value = std::strtol(e.text.c_str(), &end, 10);
    const bool digits_before = end != e.text.c_str() && std::isdigit(static_cast<unsigned char>(end[-1]));
    const char* fraction = end;
    if (digits_before && *fraction == '.')
      while (std::isdigit(static_cast<unsigned char>(*++fraction))) {
      }
    if (e.text.empty() || !digits_before || *fraction != '\0' || errno == ERANGE)
      return bad(e, where, "is not a whole number: '" + e.text + "'");
    if (fraction != end) notes_.cut_to_whole.push_back(where + " '" + e.text + "' is read as " + std::to_string(value) +
                                                        ", as ViSP reads a whole number there");
    return value;
  }
  /// A whole number that must not be negative (ViSP reads these as unsigned).
  Result<unsigned> count(const XmlElement& e, const std::string& where) {
    auto value = whole(e, where);
    if (!value.ok()) return value.error();
    if (value.value() < 0 || value.value() > 1000000) return bad(e, where, "must be a count, not " + e.text);
    return static_cast<unsigned>(value.value());
  }

  /// After each value: the settings must stay within their limits, reported at element `e`.
  Result<bool> check(const XmlElement& e) const {
    const auto problem = check_tracker_params(config_.params);
    if (problem) return Error{path_, e.line, problem->message};
    return true;
  }
  void note(const std::string& what) {
    for (const std::string& seen : notes_.not_applied)
      if (seen == what) return;
    notes_.not_applied.push_back(what);
  }

  Result<bool> camera(const XmlElement& block) {
    notes_.camera_block = true;
    for (const XmlElement& e : block.children) {
      const std::string where = "<camera><" + e.name + ">";
      // vpXmlParserCamera's layout: its intrinsics sit inside <model>, where a tracker
      // configuration has none, so reading on would keep the default camera unnoticed.
      if (e.name == "model")
        return bad(e, where, "is a camera-calibration file's (vpXmlParserCamera): give that file as --intrinsics "
                             "(read_camera_file), or px, py, u0, v0 directly in <camera>");
      real* value = e.name == "px" ? &config_.camera.px : e.name == "py" ? &config_.camera.py
                    : e.name == "u0" ? &config_.camera.u0 : e.name == "v0" ? &config_.camera.v0 : nullptr;
      int* size = e.name == "width" || e.name == "image_width"     ? &config_.camera.width
                  : e.name == "height" || e.name == "image_height" ? &config_.camera.height : nullptr;
      if (value) {
        auto got = number(e, where);
        if (!got.ok()) return got.error();
        *value = real(got.value());  // set-up time conversion
        if (auto refused = check_intrinsics(config_.camera)) return Error{path_, e.line, where + ": " + refused->message};
      } else if (size) {
        auto got = whole(e, where);
        if (!got.ok()) return got.error();
        if (got.value() <= 0 || got.value() > kMaxImageSide)
          return bad(e, where, "must be 1.." + std::to_string(kMaxImageSide) + " pixels, not " + e.text);
        *size = static_cast<int>(got.value());
        if (static_cast<long long>(config_.camera.width) * config_.camera.height > kMaxImagePixels)
          return bad(e, where, "makes an image of more than " + std::to_string(kMaxImagePixels >> 20) + " M pixels");
      }
    }
    return true;
  }

  Result<bool> ecm(const XmlElement& block) {
    MovingEdgeParams& me = config_.params.me;
    for (const XmlElement& group : block.children) {
      if (group.name == "sample") {
        auto read = sample(group, "ecm><sample");
        if (!read.ok()) return read;
        continue;
      }
      for (const XmlElement& e : group.children) {
        const std::string where = "<ecm><" + group.name + "><" + e.name + ">";
        if (group.name == "mask" && (e.name == "size" || e.name == "nb_mask")) {
          auto got = count(e, where);
          if (!got.ok()) return got.error();
          (e.name == "size" ? me.mask_size : me.mask_number) = got.value();
        } else if (group.name == "range" && e.name == "tracking") {
          auto got = count(e, where);
          if (!got.ok()) return got.error();
          me.range = got.value();
        } else if (group.name == "contrast" && (e.name == "edge_threshold" || e.name == "mu1" || e.name == "mu2")) {
          auto got = number(e, where);
          if (!got.ok()) return got.error();
          (e.name == "edge_threshold" ? me.threshold : e.name == "mu1" ? me.mu1 : me.mu2) =
              real(got.value());  // set-up time conversion
        } else {
          continue;
        }
        auto checked = check(e);
        if (!checked.ok()) return checked;
      }
    }
    return true;
  }

  /// <sample><step>, inside <ecm> or beside it; `where` is the block's path without brackets.
  Result<bool> sample(const XmlElement& block, const std::string& where) {
    for (const XmlElement& e : block.children) {
      if (e.name != "step") continue;
      auto got = whole(e, "<" + where + "><step>");
      if (!got.ok()) return got.error();
      config_.params.me.sample_step = real(static_cast<double>(got.value()));  // set-up time conversion
      auto checked = check(e);
      if (!checked.ok()) return checked;
    }
    return true;
  }

  /// A whole number read as a switch: non-zero is on, as ViSP reads it.
  Result<bool> flag(const XmlElement& e, const std::string& where, bool& out) {
    auto got = whole(e, where);
    if (!got.ok()) return got.error();
    out = got.value() != 0;
    return true;
  }
  /// A number times `scale` into `out`, then the limits.
  Result<bool> measure(const XmlElement& e, const std::string& where, double scale, real& out) {
    auto got = number(e, where);
    if (!got.ok()) return got.error();
    out = real(got.value() * scale);  // set-up time conversion
    return check(e);
  }

  Result<bool> face(const XmlElement& block) {
    FaceVisibilityParams& faces = config_.params.faces;
    for (const XmlElement& e : block.children) {
      const std::string where = "<face><" + e.name + ">";
      Result<bool> read = true;
      if (e.name == "fov_clipping") {
        read = flag(e, where, faces.fov_clipping);
      } else if (e.name == "angle_appear") {
        read = measure(e, where, kRadiansPerDegree, faces.angle_appear);
      } else if (e.name == "angle_disappear") {
        read = measure(e, where, kRadiansPerDegree, faces.angle_disappear);
      } else if (e.name == "near_clipping") {
        faces.near_clipping = true;
        read = measure(e, where, 1, faces.near_distance);
      } else if (e.name == "far_clipping") {
        faces.far_clipping = true;
        read = measure(e, where, 1, faces.far_distance);
      }
      if (!read.ok()) return read;
    }
    return true;
  }

  Result<bool> lod(const XmlElement& block) {
    FaceVisibilityParams& faces = config_.params.faces;
    for (const XmlElement& e : block.children) {
      const std::string where = "<lod><" + e.name + ">";
      Result<bool> read = true;
      if (e.name == "use_lod") read = flag(e, where, faces.use_lod);
      else if (e.name == "min_line_length_threshold") read = measure(e, where, 1, faces.min_line_length);
      else if (e.name == "min_polygon_area_threshold") read = measure(e, where, 1, faces.min_polygon_area);
      if (!read.ok()) return read;
    }
    return true;
  }

  /// edgetrack's own settings, which ViSP passes over: <edgetrack><status>, <thin_lines>, <camera>
  /// and <detector>.
  Result<bool> edgetrack_block(const XmlElement& block) {
    for (const XmlElement& e : block.children) {
      Result<bool> read = true;
      if (e.name == "status") read = status(e, "<edgetrack><status>");
      else if (e.name == "thin_lines") read = thin_lines(e, "<edgetrack><thin_lines>");
      else if (e.name == "camera") read = camera_timing(e);
      else if (e.name == "detector") read = detector(e);
      if (!read.ok()) return read;
    }
    return true;
  }

  /// The camera's timing, which ViSP's pinhole has none of: <edgetrack><camera><readout>. An
  /// element that names no setting is refused, as in <status>.
  Result<bool> camera_timing(const XmlElement& block) {
    for (const XmlElement& e : block.children) {
      const std::string where = "<edgetrack><camera><" + e.name + ">";
      if (e.name != "readout") return bad(e, where, "is no camera setting of edgetrack's (readout is)");
      auto read = measure(e, where, 1, config_.params.readout);
      if (!read.ok()) return read;
    }
    return true;
  }

  /// The detector's settings a file may give (set_detector_param), each element named as its
  /// field; a name that is none is refused, as in <status>.
  Result<bool> detector(const XmlElement& block) {
    for (const XmlElement& e : block.children) {
      const std::string where = "<edgetrack><detector><" + e.name + ">";
      auto got = number(e, where);
      if (!got.ok()) return got.error();
      const std::string problem = set_detector_param(config_.detector, e.name, got.value());
      if (!problem.empty()) return bad(e, where, "'" + e.text + "' is refused: " + problem);
    }
    return true;
  }

  /// The thin-line test's settings (ThinLineParams), each element named as its field.
  Result<bool> thin_lines(const XmlElement& block, const std::string& where_block) {
    for (const XmlElement& e : block.children) {
      const std::string where = where_block + "<" + e.name + ">";
      auto got = number(e, where);
      if (!got.ok()) return got.error();
      const std::string problem = set_thin_line_param(config_.params.thin_lines, e.name, got.value());
      if (!problem.empty()) return bad(e, where, "'" + e.text + "' is refused: " + problem);
    }
    return true;
  }

  /// The status rule's settings (StatusParams), each element named as its field; a name that
  /// is none is refused (the block is edgetrack's own: a misspelt setting would go unnoticed).
  Result<bool> status(const XmlElement& block, const std::string& where_block) {
    StatusParams& p = config_.params.status;
    for (const XmlElement& e : block.children) {
      const std::string where = where_block + "<" + e.name + ">";
      auto got = number(e, where);
      if (!got.ok()) return got.error();
      std::string problem = set_status_param(p, e.name, got.value());
      if (problem.empty()) problem = check_status_params(p);
      if (!problem.empty()) return bad(e, where, "'" + e.text + "' is refused: " + problem);
    }
    return true;
  }

  const std::string& path_;
  TrackerConfig config_;
  ConfigNotes notes_;
};

}  // namespace

namespace {

Result<ConfigNotes> apply_document(const Result<XmlElement>& document, const std::string& path, TrackerConfig& config) {
  if (!document.ok()) return document.error();
  Reading reading(path, config);
  auto read = reading.root(document.value());
  if (!read.ok()) return read.error();
  config = reading.config();
  return reading.notes();
}

}  // namespace

Result<ConfigNotes> apply_visp_config(const std::string& path, TrackerConfig& config) {
  return apply_document(read_xml_file(path), path, config);
}

Result<ConfigNotes> apply_visp_config_text(const std::string& xml, const std::string& name, TrackerConfig& config) {
  return apply_document(parse_xml(xml, name), name, config);
}

}  // namespace edgetrack
