// Hand–eye calibration from images (the thesis pipeline,
// docs/handeye-methods.md#the-thesis-pipeline): the camera poses measured by PnP in every image,
// the robot poses, and the detected pixels.
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
//   4. Robot-noise agreement (when step 2 estimated the robot noise): the joint estimate must
//      agree with what the pose-level residuals imply — step 1's estimate, whose camera noise is
//      the PnP one — within their sampling error, or the result says why not. Compared is the
//      robot noise's effect at the scene, s = √(σ_t² + (σ_r L)²) (L = handeye::LengthScale):
//      the split between rotation and translation is weakly identifiable in both estimates (both
//      move the camera), their effect is not. It rests on at least ν = 3n − 6 degrees of freedom
//      (three residuals per station and kind, six unknowns of X and Z), so log s has a standard
//      error ≲ 1/√(2ν) in each and their difference ≲ 1/√ν (treated as independent:
//      conservative, the two share the data). When |log(s_joint / s_pose)| > 2/√ν (a factor
//      1.60 at 8 stations, 1.25 at 28) a warning gives both, the factor, the station with the
//      largest pose-level residual, and the likely causes:
//      one station dominating the pose-level residuals (a robot pose off by more than the noise,
//      which the joint refinement absorbs into that station's free robot pose, so its estimate
//      can collapse toward zero — and the covariance of X with it), or the pose-level camera
//      model (isotropic PnP summary) being wrong; and the fix: check that station, or give
//      --robot-sigma. Measured on real data: 8 chessboard images whose pose-level residuals are
//      0.7° RMS (one station at 1.9°) gave a joint estimate of 0.026°.
//   5. The robot noise the covariance rests on. The joint estimate is the better one when it can
//      be trusted (it sees each image's pose uncertainty), but a collapsed joint estimate makes
//      the covariance of X far too small. So the covariance takes the larger of the two — each
//      component the larger of the pose-level sigma and the joint posterior-mean sigma — when the
//      pose-level effect is the larger and either (a) the two disagree (step 4), or (b) fewer than
//      kModelCheckMinStations stations are used, where no check of the noise model is possible
//      (model_check.h) and a low joint estimate cannot be told from a collapsed one — and a
//      pose-level component exceeds the joint posterior mean's (else nothing changes). The
//      covariance is then the Gauss–Newton one of a re-solve with that robot sigma given (and
//      the pixel sigma fixed at step 2's; its Monte Carlo likewise), X and Z stay step 2's, the
//      result's robot_sigma is the one the covariance used, and a warning says so. When the joint
//      estimate is the larger, it is kept.
#pragma once

#include <string>
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

  // core/options_check.h: false naming ImageCalibrationOptions.pixel_sigma (PixelSigmaIsValid)
  // or a CalibrateOptions field.
  bool IsValid(std::string* why) const;
};

struct ImageCalibrationResult {
  CalibrationResult pose_level;     // step 1 (its `rejected`: the pose-level outliers)
  ReprojectionResult reprojection;  // step 2, on the stations used (per-image vectors follow them)
  CalibrationResult result;         // step 3: the answer; `rejected` = pose level ∪ image level
  std::vector<int> image_rejected;  // stations rejected in step 2, in order
  std::vector<double> image_rejected_rms_px;  // their reprojection RMS when rejected
};

// Step 4 above: empty when the joint robot sigma agrees with the pose-level one on `stations`
// stations at length scale L (metres), else the warning. `largest` names the station with the
// largest pose-level residual and `largest_deg` that residual's rotation (degrees).
std::string RobotNoiseAgreementWarning(const PoseSigma& joint, const PoseSigma& pose_level,
                                       size_t stations, double length_scale,
                                       const std::string& largest, double largest_deg);

// Step 5 above: whether the covariance takes the pose-level robot noise (the larger) instead of
// the joint estimate `joint`, on `stations` used stations at length scale L (metres).
bool CovarianceTakesPoseLevelRobotNoise(const PoseSigma& joint, const PoseSigma& pose_level,
                                        size_t stations, double length_scale);

// Throws InputError when !options.IsValid, and what Calibrate and RefineReprojection throw
// (DegenerateError, InputError).
ImageCalibrationResult CalibrateFromImages(const std::vector<ImageStation>& stations,
                                           const ImageCalibrationOptions& options);

}  // namespace hecal::estimation
