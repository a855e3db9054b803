// camera.yaml (or ViSP camera XML) ↔ pose::CameraModel (docs/targets.md; examples in
// docs/targets.md).
//
// Four layouts are read. A file whose first non-blank character is '<' (<?xml ...?> or <root>)
// is ViSP's camera XML, whatever its extension; otherwise it is YAML, and the YAML layouts are
// told apart by their keys:
//   hecal   fx, fy, cx, cy, optional width, height, and
//           distortion: {model: plumb_bob, coefficients: [k1, k2, p1, p2, k3]}.
//           Other keys are rejected (with a "did you mean" suggestion).
//   OpenCV  cv::FileStorage YAML ("%YAML:1.0" first line, as samples/cpp/calibration.cpp writes):
//           camera_matrix: !!opencv-matrix {rows: 3, cols: 3, dt: d, data: [...]},
//           distortion_coefficients: !!opencv-matrix (N × 1 or 1 × N), optional image_width,
//           image_height. Other keys (calibration_time, avg_reprojection_error, ...) are ignored.
//   ROS     sensor_msgs/CameraInfo YAML (camera_calibration_parsers): camera_matrix and
//           distortion_coefficients as {rows, cols, data} maps, distortion_model: plumb_bob,
//           image_width, image_height; rectification_matrix, projection_matrix, camera_name
//           and other keys are ignored.
//   ViSP    vpXmlParserCamera XML (src/io/visp_camera_xml.h: the layout, the choice of model and
//           kud → k1).
// A YAML file with camera_matrix is read as OpenCV / ROS (the same reader: distortion_model,
// when present, must be plumb_bob); otherwise as hecal's layout.
//
// Missing distortion: a hecal file without `distortion`, or an OpenCV / ROS file without
// distortion_coefficients, is read as no distortion (all coefficients 0), and CameraFile::notes
// says so ("camera.yaml has no distortion: read as no distortion"); the commands print the notes.
//
// Checks: fx, fy > 0 and finite; cx, cy and the coefficients finite; the camera matrix exactly
// [fx 0 cx; 0 fy cy; 0 0 1] (hecal's model has no skew); width and height whole numbers ≥ 1,
// both or neither (absent: 0, unknown). Coefficients are in OpenCV's order (k1, k2, p1, p2, k3,
// k4, k5, k6, s1, s2, s3, s4, τx, τy); 4, 5, 8, 12 or 14 of them, and every one after k3 must be
// zero, since plumb_bob has only k1, k2, p1, p2, k3 (4 values: k3 = 0).
// Errors: hecal::InputError(file, line, problem, fix), the line of the offending key or value.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "hecal/pose/camera_model.h"

namespace hecal::io {

// A camera file as read: the model, and notes on how it was read (missing distortion, the ViSP
// model chosen), one line each, for the command's printout.
struct CameraFile {
  pose::CameraModel camera;
  std::vector<std::string> notes;
};

CameraFile ReadCameraFile(const std::string& path);

// The same from text (any of the four layouts); `source` names it in errors and notes.
CameraFile ParseCameraFile(std::string_view text, const std::string& source);

// hecal's layout, preceded by `comments` as '#' lines; numbers are printed to round-trip exactly.
// width and height are written when both are known (> 0). The one camera.yaml writer: it is
// FormatIntrinsicsYaml (io/import_types.h), which the importers use.
std::string FormatCameraYaml(const pose::CameraModel& camera,
                             const std::vector<std::string>& comments);

// FormatCameraYaml written with io::WriteFileAtomically (never a partial file).
void WriteCameraFile(const std::string& path, const pose::CameraModel& camera,
                     const std::vector<std::string>& comments);

}  // namespace hecal::io
