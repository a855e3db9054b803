// Are intrinsics ESTIMATED from the images (intrinsics_calibration.h) those of a real camera? A
// target description that does not match the print (cols/rows swapped or one off, a 9 × 6 board
// declared for a patch of a larger board, points in a mirrored order) still gives
// cv::calibrateCamera a result: the optimiser bends K and the distortion until the wrong points
// fit as well as they can. That result is no camera, and every pose from it is wrong. Given
// intrinsics have their own check (intrinsics_fit.h); this one judges the estimate alone, from
// physics rather than from the data set, so that the bundled real sets pass by a wide margin.
//
// A real camera's estimate is implausible when any of (IntrinsicsPlausibilityOptions):
//   - the RMS reprojection error over all points is at least max_rms_px (2 px). A correct
//     chessboard fits to the detection noise: 0.074 px on all 28 images of data/rwhe-kuka2
//     (SOURCE.md), 0.03 px on rendered boards (intrinsics_fit.h); no detector is off by 2 px on
//     a sharp target, so the points are not those of the described target. The same bound
//     refuses given intrinsics (intrinsics_fit.h's refuse_rms_px).
//   - max(fx, fy) / min(fx, fy) exceeds max_focal_ratio (1.5). Machine-vision sensors have square
//     pixels (fx/fy within a few per cent of 1: 1.0001 on kuka2); the most anamorphic standard
//     pixel aspect, ITU-R BT.601 16:9 PAL, is 64/45 ≈ 1.42.
//   - the radial distortion folds the image: the slope of the distorted radius
//     r_d(r) = r (1 + k1 r² + k2 r⁴ + k3 r⁶) (Brown–Conrady, OpenCV's plumb_bob), i.e.
//     1 + 3 k1 r² + 5 k2 r⁴ + 7 k3 r⁶, is ≤ 0 at some normalised radius r up to the image corner
//     farthest from the principal point (x/fx, y/fy). A lens maps radii one-to-one; a fold means
//     two scene directions land on one pixel inside the image, which no lens does (kuka2's
//     estimate: slope ≥ 0.68 up to its corner radius 1.07).
//   - the principal point lies more than max_principal_offset (0.25) of the image width or height
//     from the image centre. Lenses are centred on the sensor to a few per cent (kuka2: 0.1 % and
//     1.1 %); a quarter of the image is beyond any mounting tolerance (only a shift lens or a
//     sensor crop far off-centre would do it).
// The first two are the symptoms a wrong description produces; the last two are what the
// optimiser does to absorb the misfit, so they are named as well (measured: a 9 × 6 board
// declared for data/rwhe-kuka2's 24 × 17 board gives RMS 10.8 px, fx 5045, fy 40971, k2 −1622).
//
// Errors: the InputError of IntrinsicsPlausibilityOptions::IsValid.
#pragma once

#include <string>
#include <vector>

#include "hecal/vision/intrinsics_calibration.h"

namespace hecal::vision {

struct IntrinsicsPlausibilityOptions {
  double max_rms_px = 2.0;
  double max_focal_ratio = 1.5;        // max(fx, fy) / min(fx, fy)
  double max_principal_offset = 0.25;  // |c − centre| as a fraction of the width / height

  // core/options_check.h: false naming IntrinsicsPlausibilityOptions.max_rms_px or
  // .max_principal_offset (not above 0 and finite) or .max_focal_ratio (not above 1 and finite).
  bool IsValid(std::string* why) const;
};

struct IntrinsicsPlausibility {
  // One phrase per failed test, with the figures (e.g. "reprojection RMS 10.8 px (a correct
  // target fits to about 0.1 px)"); empty when the estimate is plausible.
  std::vector<std::string> problems;
  bool plausible() const { return problems.empty(); }
};

IntrinsicsPlausibility CheckIntrinsicsPlausible(const IntrinsicsResult& estimate,
                                                const IntrinsicsPlausibilityOptions& options = {});

// The smallest normalised radius in [0, r_max] at which the slope of r_d(r) (above) is ≤ 0, or a
// negative value when it stays positive; r_max is sampled in 1000 steps.
double RadialFoldRadius(const pose::CameraModel& camera, double r_max);

}  // namespace hecal::vision
