// Hand–eye calibration from images (issue 4, "End to end"; the thesis pipeline of SPEC.md A.3):
// the camera poses measured by PnP in every image, the robot poses, and the detected pixels.
//
//   1. Pose level: estimation::Calibrate (calibrate.h) on the problem of the PnP poses
//      T_camera_target_i and the robot poses, with the method of options.calibrate (ml by
//      default). The camera noise is known here: unless --camera-sigma is given, the camera
//      sigma is the RMS over the images of each PnP pose's per-axis standard deviation
//      (sqrt(trace/3) of the rotation and translation blocks of its covariance,
//      pose/pose_refinement.h), so that only the robot noise is estimated from the residuals
//      (noise_estimation.h: one side given, the other estimated) — instead of the equal split
//      that poses alone force.
//   2. Image level: the joint refinement of the reprojection error over X, Z and the robot poses
//      (reprojection_refinement.h), started from step 1, with the pixel sigma given or estimated
//      and the robot sigma given or — started from step 1's — estimated jointly with it as
//      variance components; with refine_intrinsics, the intrinsics too. The pose-level camera model
//      above is isotropic and uncorrelated, which a PnP pose is not (its rotation and translation
//      errors are strongly correlated through the target distance), so step 1's robot sigma can be
//      several times off; the joint estimate sees each image's true pose uncertainty through its
//      pixels.
//      Outliers: step 1 rejects pose-level outliers (calibrate.h, station_selection.h: a wrong
//      robot pose, a board detected in the wrong order); step 2 runs on the stations that remain,
//      and an image whose reprojection RMS exceeds 3 σ̂_px (a blurred view, a partly wrong
//      detection) is rejected and step 2 repeated without it, at most ⌊(n − 3)/2⌋ stations
//      rejected in all (beyond that they are flagged and kept, with a warning).
//   3. The result: step 1's result with X, Z, their covariance and the robot sigma replaced by
//      step 2's, and the pose-level residuals, whitened residuals and outlier flags of every
//      used station recomputed at step 2's X, Z with step 1's sigmas; the rejected stations
//      (both steps) with their residuals at that X, Z. The covariance is step 2's
//      linear one (its Gauss–Newton information), or with options.calibrate.covariance.method
//      = kMonteCarlo a Monte Carlo over the pixels and robot poses (image_monte_carlo.h); other
//      covariance methods are treated as linear. Warnings list the rejected and flagged images.
#pragma once

#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/reprojection_refinement.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/pose/camera_model.h"

namespace hecal::estimation {

// One image of the target, taken at one robot pose.
struct ImageStation {
  Pose T_base_gripper = Pose::Identity();
  Pose T_camera_target = Pose::Identity();        // from PnP
  Matrix6d camera_covariance = Matrix6d::Zero();  // of T_camera_target, right, (ω, v)
  ImagePoints points;                             // the detected points of the image
};

struct ImageCalibrationOptions {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  CalibrateOptions calibrate;         // step 1 (camera_sigma: from the PnP covariances if absent)
  pose::CameraModel camera;           // the intrinsics of every image
  std::optional<double> pixel_sigma;  // px; estimated when absent
  bool refine_intrinsics = false;     // step 2 refines the intrinsics too
};

struct ImageCalibrationResult {
  CalibrationResult pose_level;     // step 1 (its `rejected`: the pose-level outliers)
  ReprojectionResult reprojection;  // step 2, on the stations used (per-image vectors follow them)
  CalibrationResult result;         // step 3: the answer; `rejected` = pose level ∪ image level
  std::vector<int> image_rejected;            // stations rejected in step 2, in order
  std::vector<double> image_rejected_rms_px;  // their reprojection RMS when rejected
};

// Throws what Calibrate and RefineReprojection throw (DegenerateError, InputError).
ImageCalibrationResult CalibrateFromImages(const std::vector<ImageStation>& stations,
                                           const ImageCalibrationOptions& options);

}  // namespace hecal::estimation
