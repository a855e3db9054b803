// The files a target detection writes beside its pose table of T_camera_target (docs/cli.md,
// `hecal detect`): `<stem>.points.csv`, the detected target points of every image used, and
// `<stem>.camera.yaml`, the intrinsics when they were estimated from the images (camera_file.h),
// where <stem> is the pose table's path without its extension (det.csv → det).
//
// points.csv: one '#' line saying what the file holds, the header `id,point_id,u,v`, then one
// row per point: the image's id (its file stem or sub-folder, RFC 4180-quoted when it holds a
// comma, a quote or a line break), the target point's id (target_file.h), the pixel (origin at
// the centre of the top-left pixel, as OpenCV) printed to round-trip exactly.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace hecal::io {

struct DetectedPoint {
  std::string image;  // the image's id
  int point_id = 0;   // the target point's id
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

std::string FormatDetectedPoints(const std::vector<DetectedPoint>& points);

struct DetectionOutputPaths {
  std::string points;  // <stem>.points.csv
  std::string camera;  // <stem>.camera.yaml
};

// The companion files of the pose table `output`.
DetectionOutputPaths DetectionCompanionPaths(const std::string& output);

}  // namespace hecal::io
