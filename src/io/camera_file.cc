#include "hecal/io/camera_file.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "hecal/io/atomic_file.h"
#include "hecal/io/import_types.h"
#include "import_yaml.h"
#include "visp_camera_xml.h"
#include "yaml_map.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::LineOf;

constexpr const char* kLayouts =
    "write fx, fy, cx, cy and distortion (hecal), or camera_matrix and distortion_coefficients "
    "(OpenCV FileStorage / ROS camera_info), or give a ViSP camera XML; see docs/targets.md";
constexpr long kLargestImageSide = 1 << 20;  // pixels; bounds the numbers, not real cameras

YAML::Node Require(const internal::YamlMap& entries, const std::string& key,
                   const std::string& source, int line, const std::string& fix) {
  const std::optional<YAML::Node> node = entries.Find(key);
  if (!node) Fail(source, line, "the camera file has no '" + key + "'", fix);
  return *node;
}

double CameraNumber(const YAML::Node& node, const std::string& source, const std::string& what) {
  return import_internal::ScalarNumber(node, source, what).value;
}

// k1, k2, p1, p2, k3 from OpenCV's 4, 5, 8, 12 or 14 coefficients (see the header).
std::array<double, 5> PlumbBob(const YAML::Node& node, const std::string& source,
                               const std::string& what) {
  const import_internal::Matrix m = import_internal::ReadMatrix(node, source, what);
  const size_t count = m.values.size();
  if (!(m.rows == 1 || m.cols == 1) ||
      !(count == 4 || count == 5 || count == 8 || count == 12 || count == 14)) {
    Fail(source, m.line,
         what + " is " + std::to_string(m.rows) + "x" + std::to_string(m.cols) +
             ", not a list of 4, 5, 8, 12 or 14 coefficients",
         "give k1, k2, p1, p2, k3 (plumb_bob)");
  }
  std::array<double, 5> coefficients = {0.0, 0.0, 0.0, 0.0, 0.0};
  for (size_t k = 0; k < count; ++k) {
    if (!std::isfinite(m.values[k])) {
      Fail(source, m.line, what + "[" + std::to_string(k) + "] is not finite",
           "give finite distortion coefficients");
    }
    if (k < 5) {
      coefficients[k] = m.values[k];
    } else if (m.values[k] != 0.0) {
      static constexpr const char* kNames[] = {"k4", "k5", "k6",    "s1",   "s2",
                                               "s3", "s4", "tau_x", "tau_y"};
      Fail(source, m.line,
           what + " has " + kNames[k - 5] + " = " + import_internal::Scientific(m.values[k]) +
               "; hecal's plumb_bob model has only k1, k2, p1, p2, k3",
           "calibrate with k1, k2, p1, p2, k3 only (OpenCV: no CALIB_RATIONAL_MODEL, "
           "CALIB_THIN_PRISM_MODEL or CALIB_TILTED_MODEL)");
    }
  }
  return coefficients;
}

void RequirePlumbBob(const YAML::Node& node, const std::string& source, const std::string& what) {
  const std::string model = import_internal::ScalarText(node, source, what);
  if (model != "plumb_bob") {
    Fail(source, LineOf(node),
         what + " is " + import_internal::Quoted(model) + "; hecal supports plumb_bob only",
         "calibrate with the plumb_bob (Brown-Conrady k1, k2, p1, p2, k3) model");
  }
}

// width and height: both or neither, whole numbers ≥ 1.
void ReadImageSize(const internal::YamlMap& entries, const std::string& width_key,
                   const std::string& height_key, const std::string& source,
                   pose::CameraModel* camera) {
  const std::optional<YAML::Node> width = entries.Find(width_key);
  const std::optional<YAML::Node> height = entries.Find(height_key);
  if (!width && !height) return;
  if (!width || !height) {
    Fail(source, entries.Line(width ? width_key : height_key),
         "the camera file has " + (width ? width_key : height_key) + " but no " +
             (width ? height_key : width_key),
         "give both image sizes in pixels, or neither");
  }
  camera->width =
      static_cast<int>(import_internal::ScalarCount(*width, source, width_key, kLargestImageSide));
  camera->height = static_cast<int>(
      import_internal::ScalarCount(*height, source, height_key, kLargestImageSide));
  if (camera->width < 1 || camera->height < 1) {
    Fail(source, entries.Line(camera->width < 1 ? width_key : height_key),
         "the image size is " + std::to_string(camera->width) + " x " +
             std::to_string(camera->height) + " pixels",
         "give the image size in pixels");
  }
}

// Where fx, fy, cx, cy were read, for the value checks.
struct IntrinsicLines {
  int fx = 0, fy = 0, cx = 0, cy = 0;
};

void CheckIntrinsics(const pose::CameraModel& camera, const IntrinsicLines& lines,
                     const std::string& source) {
  const std::pair<const char*, double> focal[] = {{"fx", camera.fx}, {"fy", camera.fy}};
  for (const auto& [name, value] : focal) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      Fail(source, std::string(name) == "fx" ? lines.fx : lines.fy,
           std::string(name) + " is " + import_internal::Scientific(value) +
               ", not a positive focal length",
           "give the focal length in pixels");
    }
  }
  if (!std::isfinite(camera.cx) || !std::isfinite(camera.cy)) {
    Fail(source, std::isfinite(camera.cx) ? lines.cy : lines.cx,
         "the principal point is not finite", "give cx, cy in pixels");
  }
}

std::string NoDistortionNote(const std::string& source, const std::string& key) {
  return source + " has no " + key + ": read as no distortion";
}

pose::CameraModel ParseHecal(const internal::YamlMap& entries, const std::string& source,
                             std::vector<std::string>* notes) {
  static constexpr std::string_view kKeys[] = {"fx",    "fy",     "cx",        "cy",
                                               "width", "height", "distortion"};
  internal::RejectUnknownKeys(entries, kKeys, source, "");
  pose::CameraModel camera;
  IntrinsicLines lines;
  const std::pair<const char*, std::pair<double*, int*>> values[] = {
      {"fx", {&camera.fx, &lines.fx}},
      {"fy", {&camera.fy, &lines.fy}},
      {"cx", {&camera.cx, &lines.cx}},
      {"cy", {&camera.cy, &lines.cy}}};
  for (const auto& [key, target] : values) {
    const YAML::Node node =
        Require(entries, key, source, 0, std::string("add ") + key + ": ... (pixels); " + kLayouts);
    *target.first = CameraNumber(node, source, key);
    *target.second = entries.Line(key);
  }
  CheckIntrinsics(camera, lines, source);
  ReadImageSize(entries, "width", "height", source, &camera);

  const std::optional<YAML::Node> found = entries.Find("distortion");
  if (!found) {
    notes->push_back(NoDistortionNote(source, "distortion"));
    return camera;
  }
  const YAML::Node& distortion = *found;
  if (!distortion.IsMap()) {
    Fail(source, entries.Line("distortion"), "distortion is not a map",
         "write distortion: {model: plumb_bob, coefficients: [k1, k2, p1, p2, k3]}");
  }
  const internal::YamlMap inner = internal::ReadYamlMap(distortion, source);
  static constexpr std::string_view kDistortionKeys[] = {"model", "coefficients"};
  internal::RejectUnknownKeys(inner, kDistortionKeys, source, " in distortion");
  const int line = entries.Line("distortion");
  RequirePlumbBob(Require(inner, "model", source, line, "add model: plumb_bob under distortion"),
                  source, "distortion model");
  camera.distortion = PlumbBob(Require(inner, "coefficients", source, line,
                                       "add coefficients: [k1, k2, p1, p2, k3] under distortion"),
                               source, "distortion coefficients");
  return camera;
}

pose::CameraModel ParseMatrixLayout(const internal::YamlMap& entries, const std::string& source,
                                    std::vector<std::string>* notes) {
  const import_internal::Matrix k =
      import_internal::ReadMatrix(*entries.Find("camera_matrix"), source, "camera_matrix");
  if (k.values.size() != 9 || !((k.rows == 3 && k.cols == 3) || k.rows == 1)) {
    Fail(source, k.line,
         "camera_matrix is " + std::to_string(k.rows) + "x" + std::to_string(k.cols) + ", not 3x3",
         "give the 3x3 camera matrix [fx 0 cx; 0 fy cy; 0 0 1]");
  }
  const std::vector<double>& K = k.values;
  if (K[1] != 0.0 || K[3] != 0.0 || K[6] != 0.0 || K[7] != 0.0 || K[8] != 1.0) {
    Fail(source, k.line,
         "camera_matrix is not of the form [fx 0 cx; 0 fy cy; 0 0 1]" +
             std::string(K[1] != 0.0 ? " (it has skew " + import_internal::Scientific(K[1]) +
                                           ", which hecal's camera model lacks)"
                                     : ""),
         "calibrate without skew (OpenCV's calibrateCamera never estimates it)");
  }
  pose::CameraModel camera;
  camera.fx = K[0];
  camera.cx = K[2];
  camera.fy = K[4];
  camera.cy = K[5];
  CheckIntrinsics(camera, IntrinsicLines{k.line, k.line, k.line, k.line}, source);
  ReadImageSize(entries, "image_width", "image_height", source, &camera);
  if (const std::optional<YAML::Node> model = entries.Find("distortion_model")) {
    RequirePlumbBob(*model, source, "distortion_model");
  }
  if (const std::optional<YAML::Node> coefficients = entries.Find("distortion_coefficients")) {
    camera.distortion = PlumbBob(*coefficients, source, "distortion_coefficients");
  } else {
    notes->push_back(NoDistortionNote(source, "distortion_coefficients"));
  }
  return camera;
}

pose::CameraModel ParseYaml(const YAML::Node& root, const std::string& source,
                            std::vector<std::string>* notes) {
  if (!root.IsDefined() || root.IsNull()) Fail(source, 0, "the camera file is empty", kLayouts);
  if (!root.IsMap()) {
    Fail(source, LineOf(root), "the camera file is not a map of 'key: value' lines", kLayouts);
  }
  const internal::YamlMap entries = internal::ReadYamlMap(root, source);
  if (entries.Find("camera_matrix")) {
    for (const char* key : {"fx", "fy", "cx", "cy", "distortion"}) {
      if (entries.Find(key)) {
        Fail(source, entries.Line(key),
             std::string("the camera file has both camera_matrix and ") + key +
                 ", so it mixes two layouts",
             "keep either camera_matrix + distortion_coefficients or fx, fy, cx, cy + distortion");
      }
    }
    return ParseMatrixLayout(entries, source, notes);
  }
  if (!entries.Has("fx") && !entries.Has("fy")) {
    Fail(source, 0, "the camera file has neither fx, fy (hecal) nor camera_matrix (OpenCV, ROS)",
         kLayouts);
  }
  return ParseHecal(entries, source, notes);
}

// ViSP's XML starts with "<?xml" or "<root>"; YAML cannot start with '<' as a camera file.
bool LooksLikeXml(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  const size_t first = text.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && text[first] == '<';
}

}  // namespace

CameraFile ParseCameraFile(std::string_view text, const std::string& source) {
  if (LooksLikeXml(text)) {
    const internal::VispCameraXml xml = internal::ParseVispCameraXml(text, source);
    CheckIntrinsics(xml.file.camera,
                    IntrinsicLines{xml.lines[0], xml.lines[1], xml.lines[2], xml.lines[3]}, source);
    return xml.file;
  }
  CameraFile file;
  file.camera = import_internal::GuardYaml(source, [&] {
    return ParseYaml(import_internal::LoadYaml(text, source), source, &file.notes);
  });
  return file;
}

CameraFile ReadCameraFile(const std::string& path) {
  return ParseCameraFile(ReadFile(path), path);
}

std::string FormatCameraYaml(const pose::CameraModel& camera,
                             const std::vector<std::string>& comments) {
  ImportedIntrinsics intrinsics;
  intrinsics.fx = camera.fx;
  intrinsics.fy = camera.fy;
  intrinsics.cx = camera.cx;
  intrinsics.cy = camera.cy;
  intrinsics.distortion.assign(camera.distortion.begin(), camera.distortion.end());
  return FormatIntrinsicsYaml(intrinsics, comments, camera.width, camera.height);
}

void WriteCameraFile(const std::string& path, const pose::CameraModel& camera,
                     const std::vector<std::string>& comments) {
  WriteFileAtomically(path, FormatCameraYaml(camera, comments));
}

}  // namespace hecal::io
