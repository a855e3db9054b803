// Do given intrinsics fit the images? A check for intrinsics read from a file (`hecal detect
// --intrinsics`, `hecal calibrate --images --intrinsics`), so that a unit or bookkeeping mistake
// in camera.yaml does not end in a silent, wrong answer.
//
// Per view (a planar target's object points, z = 0, and their pixels):
//   e  the RMS reprojection error (px) of the maximum-likelihood pose with the given intrinsics
//      (SolvePnPOpenCvRefined, opencv_pnp.h);
//   h  for views with at least 6 points, the RMS (px) of the best homography from the target
//      plane to the pixels undistorted with the given distortion and mapped back through the
//      given fx, fy, cx, cy (cv::findHomography, least squares): what any pinhole K could
//      achieve. With the right K the pose model (6 dof) fits as well as the homography (8 dof):
//      e ≈ h, the detection noise (measured 0.03 px on rendered chessboards, 0.08 px on 12 of the
//      real images of data/rwhe-kuka2 with the reference intrinsics, 0.25 / 0.20 px on
//      moveit_calibration's ChArUco photo).
// E and H are the medians over the views (H over the views that have h).
//
// Verdict (IntrinsicsFitOptions). The thresholds come from measurements: 8 rendered 640 × 480
// chessboard views, 12 of the real kuka2 images and moveit's ChArUco photo, each with its true
// intrinsics and with them changed as users get them wrong (E / H in px; rendered, kuka2, moveit):
//   does not fit  E ≥ refuse_rms_px (2 px): no detector is that poor on a sharp target, so the
//                 model does not describe the images. fx, fy 10× too large: 6.0 / 0.36,
//                 23.5 / 1.65, 3.0 / 0.18; the intrinsics of twice the resolution: 3.8 / 0.37,
//                 8.3 / 1.7, 3.1 / 0.21; of half the resolution: 6.1 / 2.9, 156 / ∞, 56 / ∞
//                 (∞: pixels the wrong distortion cannot undistort); cx and cy swapped on kuka2:
//                 14.5 / 2.4; fx 10% short on kuka2: 2.2 / 0.33.
//   suspect       below 2 px, E ≥ warn_ratio (3) × max(H, free_floor_px = 0.05 px) and
//                 E ≥ min_warn_rms_px (0.2 px): the pose model fits clearly worse than a free
//                 homography. cx and cy swapped: 1.8 / 0.27 (rendered), 1.5 / 0.31 (moveit);
//                 fx 10% long: 0.51 / 0.07, 2.0 / 0.27; cx 20 px off: 0.34 / 0.05, 0.57 / 0.10;
//                 fx 2% long on kuka2: 0.41 / 0.10. Without any h (every view under 6 points:
//                 single tags), E ≥ warn_rms_px_without_free (1 px).
//   fits          otherwise: the true intrinsics (0.028 / 0.028, 0.076 / 0.077, 0.25 / 0.20),
//                 and mistakes too small to see against the detection noise: on moveit's one
//                 photo fx 10% long (0.28 / 0.19) or cx 20 px off (0.30 / 0.19); fx 2% off on
//                 the rendered views (0.11 / 0.03).
// Limits: a small target hardly shows the focal length in its perspective (a single tag of a few
// dozen pixels: fx 10× too large moved E from 0.30 to 0.43 px on moveit's 26 px markers, unseen);
// and wrong distortion coefficients hurt the homography too (E / H of 1–2), so only E ≥ 2 px
// catches them (the lens's k1 left out: 0.71 / 0.37 and 1.8 / 1.7, unseen).
//
// When the verdict is not `fits`, IntrinsicsFit says more:
//   points_do_not_fit  E < 2·H and H ≥ 1 px: the free homography does not fit either, so the
//                      trouble is the points, not K: a target description that does not match
//                      the print (moveit_calibration's ArUco photo with the 4 × 3 grid its test
//                      declares: E 41.9, H 41.8 px; the print is 3 × 4: 0.55 px), a board that
//                      is not flat, or wrong distortion coefficients.
//   correction         the best of four simple corrections, when it fits at least 4× better
//                      than the given intrinsics (each scored by E on up to
//                      max_diagnosis_views views): cx and cy swapped; fx, fy scaled by k (k
//                      searched over 1/20 … 20: a focal length in other units, or of another
//                      lens); fx, fy, cx, cy scaled by k (the intrinsics of another resolution,
//                      c' = (c + ½)·k − ½); the distortion left out (images that are already
//                      undistorted).
//
// Errors: hecal::InputError (source "views") for no views, a view with fewer than 4 points or
// mismatched sizes; the InputError of IntrinsicsFitOptions::IsValid.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/pose/camera_model.h"
#include "hecal/vision/intrinsics_calibration.h"

namespace hecal::vision {

struct IntrinsicsFitOptions {
  double refuse_rms_px = 2.0;
  double warn_ratio = 3.0;
  double min_warn_rms_px = 0.2;
  double warn_rms_px_without_free = 1.0;
  double free_floor_px = 0.05;
  int max_diagnosis_views = 10;

  // core/options_check.h: false naming the threshold that is not above 0 and finite, or
  // IntrinsicsFitOptions.max_diagnosis_views (below 1).
  bool IsValid(std::string* why) const;
};

enum class IntrinsicsVerdict { kFits, kSuspect, kDoesNotFit };

// One of the simple corrections (see above), and how well the images fit with it.
struct IntrinsicsCorrection {
  enum class Kind { kSwapPrincipalPoint, kScaleFocal, kScaleResolution, kNoDistortion };
  Kind kind = Kind::kSwapPrincipalPoint;
  double scale = 1.0;        // k, for the scaling kinds
  pose::CameraModel camera;  // the corrected intrinsics
  double median_rms_px = 0.0;
};

struct IntrinsicsFit {
  IntrinsicsVerdict verdict = IntrinsicsVerdict::kFits;
  double median_rms_px = 0.0;                // E
  std::optional<double> median_free_rms_px;  // H; nullopt when no view has 6 points
  bool points_do_not_fit = false;
  std::optional<IntrinsicsCorrection> correction;
};

IntrinsicsFit CheckIntrinsicsFit(const std::vector<CalibrationView>& views,
                                 const pose::CameraModel& camera,
                                 const IntrinsicsFitOptions& options = {});

}  // namespace hecal::vision
