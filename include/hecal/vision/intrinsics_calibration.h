// Camera intrinsics from views of a planar target, with OpenCV 4.6's cv::calibrateCamera (Zhang,
// "A Flexible New Technique for Camera Calibration", IEEE TPAMI 22(11), 2000: closed-form
// initialisation from the views' homographies, then Levenberg–Marquardt on the reprojection
// error over K, the plumb_bob distortion (k1, k2, p1, p2, k3) and every view's pose).
//
// Input: per view, object points in the target frame (z = 0, metres) and their pixels; the image
// size in pixels. Output: a pose::CameraModel (pose/camera_model.h), the RMS reprojection error
// over all points (px, calibrateCamera's return value), the RMS of each view, each view's
// T_camera_target (= [Rodrigues(rvec) | tvec], metres) and the 1σ of fx, fy, cx, cy (px) and of
// k1, k2, p1, p2, k3 from calibrateCamera's stdDeviationsIntrinsics (the diagonal of the inverse
// Gauss–Newton Hessian scaled by the residual variance, so it assumes the model is right and the
// pixel noise white).
//
// Warnings (IntrinsicsResult::warnings, one sentence each, with what to do) when the views do not
// constrain the model well:
//   - fewer than options.recommended_views views (default 5; 3 is the hard minimum, below);
//   - every pair of views has board normals within options.min_normal_spread_deg (default 10°)
//     of each other: with (nearly) parallel boards — e.g. all fronto-parallel — the focal length
//     trades against the distance (Zhang §3.3: parallel planes add no constraint on K). The σ
//     below do NOT reveal this: the distortion terms break the exact f/Z symmetry, so the
//     Hessian looks well conditioned while f is far off (measured: 3 fronto-parallel views of a
//     9×6 board, 0.05 px noise, true f = 620 px → 896 ± 0.8 px; tilted by 0, 1.1 and 2.3° → 1615 ±
//     0.3 px). Callers that need usable intrinsics should refuse such a set (`hecal detect` does);
//   - the points of all views together cover less than options.min_coverage (default 0.5) of the
//     image, measured on a 10 × 10 grid of cells: distortion outside the covered part is
//     extrapolated;
//   - σ(fx)/fx or σ(fy)/fy above options.max_focal_sigma_relative (default 0.005: a depth error
//     of that fraction), or σ(cx), σ(cy) above options.max_principal_sigma_px (default 5 px).
//
// Errors: hecal::InputError (source "views") for an empty or mismatched view, fewer than 4 points
// in a view, non-finite values, object points off the plane z = 0 (calibrateCamera's planar
// initialisation needs z = 0), a non-positive image size; the InputError of
// IntrinsicsOptions::IsValid; hecal::DegenerateError for fewer than 3 views (a planar target gives
// 2 constraints on K per view; K has 4–5 unknowns) and when OpenCV fails or returns non-finite
// values.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"

namespace hecal::vision {

struct CalibrationView {
  std::vector<Eigen::Vector3d> object_points;  // target frame, metres, z = 0
  std::vector<Eigen::Vector2d> image_points;   // pixels, one per object point
};

struct IntrinsicsOptions {
  bool fix_k3 = false;            // estimate k1, k2, p1, p2 only (CALIB_FIX_K3)
  bool fix_aspect_ratio = false;  // fx = fy (CALIB_FIX_ASPECT_RATIO with a ratio of 1)
  int recommended_views = 5;
  double min_normal_spread_deg = 10.0;
  double min_coverage = 0.5;                // fraction of the 10 × 10 image cells with points
  double max_focal_sigma_relative = 0.005;  // σ(f)/f
  double max_principal_sigma_px = 5.0;

  // core/options_check.h: false naming IntrinsicsOptions.recommended_views (negative),
  // .min_normal_spread_deg (not 0 … 180), .min_coverage (not 0 … 1), .max_focal_sigma_relative or
  // .max_principal_sigma_px (not above 0 and finite).
  bool IsValid(std::string* why) const;
};

// 1σ of the intrinsics (fx, fy, cx, cy in px; distortion dimensionless); 0 for fixed parameters
// (with fix_aspect_ratio, σ(fx) = σ(fy)·fx/fy, since fx follows fy).
struct IntrinsicsSigma {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  std::array<double, 5> distortion = {0.0, 0.0, 0.0, 0.0, 0.0};  // k1, k2, p1, p2, k3
};

struct IntrinsicsResult {
  pose::CameraModel camera;           // width, height = the image size
  double rms_px = 0.0;                // RMS reprojection error over all points
  std::vector<double> view_rms_px;    // per view, in input order
  std::vector<Pose> T_camera_target;  // per view, in input order
  IntrinsicsSigma sigma;
  double coverage = 0.0;           // fraction of the 10 × 10 image cells holding a point
  double normal_spread_deg = 0.0;  // largest angle between two views' board normals
  std::vector<std::string> warnings;
};

IntrinsicsResult CalibrateIntrinsics(const std::vector<CalibrationView>& views, int width,
                                     int height, const IntrinsicsOptions& options = {});

}  // namespace hecal::vision
