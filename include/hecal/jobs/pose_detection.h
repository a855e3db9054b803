// Camera poses from a folder of target images as one job (`hecal detect`, docs/cli.md#hecal-detect,
// docs/targets.md): everything between the caller's options and the texts of the files a
// detection writes, printing and writing nothing (progress, notes and warnings go to
// JobCallbacks, job_callbacks.h).
//
// Steps (DetectCameraPoses)
//   1. The options checked (IsValid) before any file is read.
//   2. The image front end (image_front_end.h: detection, intrinsics, PnP and refinement; its
//      texts in that order) for pose use (one image is enough with given intrinsics).
//   3. The results of every used image, in file-name order: the pose table (T_camera_target, id =
//      the image's file stem or sub-folder) with its '#' lines, the detected points
//      (io/detection_output.h) and, when estimated from the images, the intrinsics as camera.yaml
//      (io/camera_file.h) with '#' lines naming the images and the RMS reprojection error.
// Frames and units: T_camera_target maps target points (target_file.h, metres) into the camera
// frame (x right, y down, z forward); pixels with the origin at the centre of the top-left pixel.
//
// Errors (hecal::InputError): invalid options (source the field: ImageSetOptions.*,
// PoseDetectionOptions.output); those of the front end pass through. Nothing is written.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/io/detection_output.h"
#include "hecal/io/pose_table.h"
#include "hecal/jobs/job_callbacks.h"
#include "hecal/pose/camera_model.h"
#include "hecal/vision/image_set.h"

namespace hecal::jobs {

struct PoseDetectionOptions {
  // The folder, target file, camera file ("" = estimate the intrinsics) and detection threads;
  // `use` is the job's (poses).
  vision::ImageSetOptions images;
  // The pose table the caller will write: the table's source, and the stem of its companions
  // (io::DetectionCompanionPaths) that the '#' lines name.
  std::string output;
  std::string caller = "hecal detect";  // names the job in its first progress line and '#' lines

  // core/options_check.h: false naming the first bad field: images (ImageSetOptions::IsValid),
  // then PoseDetectionOptions.output (empty).
  bool IsValid(std::string* why) const;
};

struct PoseDetection {
  io::PoseTable table;                    // T_camera_target per used image (metres), ids
  io::PoseWriteOptions write;             // the table's '#' lines (quaternions, metres)
  std::vector<io::DetectedPoint> points;  // every detected point of every used image
  pose::CameraModel camera;               // the intrinsics used: given or estimated
  // camera.yaml of the estimated intrinsics (to io::DetectionCompanionPaths(output).camera);
  // nullopt when they were given.
  std::optional<std::string> camera_yaml;
  vision::ImageSet set;  // the image front end's result (the detect page, detection_report.h)
};

// Steps 1–3 above.
PoseDetection DetectCameraPoses(const PoseDetectionOptions& options, const JobCallbacks& callbacks);

}  // namespace hecal::jobs
