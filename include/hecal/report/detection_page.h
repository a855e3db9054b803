// The detect page of the HTML report (`hecal detect --report`; docs/report.md, "The detect
// page"): page kind "detect", drawn by web/detect.js with web/images.js's figures in the shell of
// html_report.h (FormatHtmlPage). Per image its detected points and their residuals at its
// refined PnP pose (pixels), its reprojection RMS and pose T_camera_target, or why it was
// skipped; the intrinsics used and the image size; thumbnails when given (page_thumbnails.h).
// The jobs layer fills it from the image front end (jobs/detection_report.h): this library reads
// no image.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "hecal/pose/camera_model.h"
#include "hecal/report/page_thumbnails.h"

namespace hecal::report {

struct DetectionPageImage {
  std::string id;       // the station id (file stem or sub-folder)
  std::string file;     // in the image folder, e.g. "im_00.png"
  std::string skipped;  // why it is not used; empty when used (the fields below are then set)
  std::vector<Eigen::Vector2d> points_px;     // detected, pixels
  std::vector<Eigen::Vector2d> residuals_px;  // π(T P_k) − u_k at the refined pose
  double rms_px = 0.0;
  Eigen::Matrix4d T_camera_target = Eigen::Matrix4d::Identity();  // metres
};

struct DetectionPageInput {
  std::string title;   // e.g. the image folder
  std::string target;  // the target's description (vision::Describe)
  // The target's points' extent in its own frame (metres): x min, y min, x max, y max.
  Eigen::Vector4d target_extent = Eigen::Vector4d::Zero();
  pose::CameraModel camera;                // the intrinsics used, with the image size
  std::string intrinsics_source;           // the camera file, or "estimated from the images"
  std::vector<DetectionPageImage> images;  // every image of the folder, in order
  std::vector<Thumbnail> thumbnails;       // of the used images, by id
};

// The page (html_report.h's FormatHtmlPage of kind "detect").
std::string FormatDetectionPage(const DetectionPageInput& input);

}  // namespace hecal::report
