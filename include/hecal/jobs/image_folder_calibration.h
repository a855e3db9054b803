// Calibration from a folder of target images as one job (`hecal calibrate --images DIR`;
// docs/architecture.md, "The data flow of hecal calibrate", from images): everything between the
// caller's options and the result document, printing nothing (progress, notes and warnings go to
// JobCallbacks, job_callbacks.h).
//
// Steps (CalibrateFromImageFolder)
//   1. The options checked (IsValid) before any file is read.
//   2. The robot pose table read (io/pose_table.h, options.robot_read).
//   3. The image front end (image_front_end.h: detection, intrinsics, PnP; its texts in that
//      order, the fit warning last) for hand–eye use.
//   4. The robot rows paired with the images by id or by order (io/image_pairing.h; notes).
//   5. The convention check (handeye/convention_check.h) on the used images' poses, in the
//      caller's words (options.words): it stops with the fix for a mistake that fits clearly
//      better, or picks the setup when options.setup is empty; its notes and then the robot
//      table's warnings become the document's first warnings.
//   6. jobs::CalibrateFromImages (jobs/image_calibration.h): the pose level, then the joint
//      reprojection refinement over X, Z and the robot poses, with every image and the skipped
//      and rejected ones with their reasons.
// Frames and units: T_base_gripper from the robot table (its unit labels the document),
// T_camera_target from the images (metres); X and Z as handeye/problem.h defines them for the
// setup.
//
// Errors (hecal::InputError): invalid options (source the field: ImageSetOptions.*,
// ImageCalibrationOptions.*, CalibrateOptions.*, PoseReadOptions.*,
// ImageFolderCalibrationOptions.robot); those of the robot table, the front end, the pairing,
// the convention check and the calibration (also DegenerateError) pass through. Nothing is
// written.
#pragma once

#include <optional>
#include <string>

#include "hecal/estimation/image_calibration.h"
#include "hecal/handeye/convention_check.h"
#include "hecal/io/pose_table.h"
#include "hecal/jobs/job_callbacks.h"
#include "hecal/pose/camera_model.h"
#include "hecal/report/result_file.h"
#include "hecal/vision/image_set.h"

namespace hecal::jobs {

struct ImageFolderCalibrationOptions {
  // The folder, target file, camera file ("" = estimate the intrinsics) and detection threads;
  // `use` is the job's (hand–eye).
  vision::ImageSetOptions images;
  std::string robot;                    // the robot pose table: T_base_gripper, one row per image
  io::PoseReadOptions robot_read;       // its units, angles, Euler sequence; invert on reading
  std::optional<handeye::Setup> setup;  // nullopt: the convention check picks it
  // Method, noise, robust loss, covariance, pixel σ, intrinsics refinement; `setup` and `camera`
  // are the job's (from `setup` above and the images).
  estimation::ImageCalibrationOptions calibration;
  handeye::ConventionWords words;  // the convention check's texts in the caller's words
  std::string caller = "calibration from images";  // names the job in its first progress line

  // core/options_check.h: false naming the first bad field, in the order calibration
  // (ImageCalibrationOptions::IsValid), ImageFolderCalibrationOptions.robot (empty),
  // robot_read (PoseReadOptions::IsValid), images (ImageSetOptions::IsValid).
  bool IsValid(std::string* why) const;
};

struct ImageFolderCalibration {
  report::ResultDocument document;  // what report::WriteResult writes
  pose::CameraModel camera;         // the intrinsics the refinement started from (given/estimated)
};

// Steps 1–6 above.
ImageFolderCalibration CalibrateFromImageFolder(const ImageFolderCalibrationOptions& options,
                                                const JobCallbacks& callbacks);

}  // namespace hecal::jobs
