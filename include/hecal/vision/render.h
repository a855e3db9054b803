// Synthetic images of a calibration target, for testing the image chain against ground truth.
//
// RenderTarget draws `target` as seen by `camera` (pinhole + plumb_bob, pose/camera_model.h) at
// T_camera_target (x_camera = T_camera_target · x_target, metres), by inverse mapping: for every
// sample position (u, v) in a pixel, the ray through pose::Undistort(u, v) is cut with the board
// plane z = 0 of the target frame and the board's printed pattern is read at that point. The
// pattern is first read at every pixel corner; a pixel whose four corners agree, and whose eight
// neighbours' corners agree too, is uniform (any edge entering it would cross a neighbour
// completely and separate that neighbour's corners — true for pattern features of 1 px and
// more). Every other pixel averages supersampling² samples on a stratified grid, jittered per
// pixel by a hash of the pixel position (so the area integral has no systematic bias along
// straight edges: the imaged black area equals the projected area to 0.001 px × perimeter,
// render_test). The normalised coordinates are undistorted exactly at the pixel corners and
// interpolated bilinearly inside the pixel (the error of that is below 1e-4 px for lens
// distortions of real cameras). Pixels follow
// OpenCV: pixel (i, j) covers u ∈ [i − ½, i + ½], v ∈ [j − ½, j + ½]. The image of a board point P
// is therefore pose::Project(camera, T_camera_target · P), with no bias from the renderer beyond
// the 8-bit quantisation, the blur (symmetric) and the noise.
//
// The printed board (target frame, hecal/pose/target.h; black = 0, white = 1 before scaling to
// options.black .. options.white grey levels):
//   chessboard  (cols + 1) × (rows + 1) squares of side `square` around the inner corners, square
//               (i, j) (top-left corner at ((i − 1)·square, (j − 1)·square)) black iff i + j is
//               even — the canonical colouring of order_consistency.h.
//   charuco     cv::aruco::CharucoBoard::create(...) of OpenCV 4.6: squares with a marker are
//               white with the marker centred, the others black.
//   aruco_grid  cv::aruco::GridBoard::create(...): each marker's cells from the dictionary bits
//               (Dictionary::getBitsFromByteList), one black border cell, (markerSize + 2)² cells
//               over the marker side.
//   apriltag_grid  apriltag_to_image(family, first_id + m): the width_at_border² central cells
//               span the marker square; outer rings that are white on every tag are left to the
//               paper, the others (reversed-border families) must fit in the spacing.
//   aruco, apriltag  the one marker `id` drawn as above, its black square (side `size`) centred
//               on the target origin (pose/target.h).
//   circles, acircles  black discs of radius options.circle_radius × the smallest distance
//               between two centres, centred on pose::ObjectPoints.
//   Around the pattern a white border of options.margin × the pattern pitch (square; marker for
//   the grids; size for a single tag) on every side; outside it and where rays miss the board (or
//   the plane is behind the camera), options.background.
// Then, in this order: Gaussian blur of options.blur_sigma px (none when 0), additive Gaussian
// noise of options.noise_sigma grey levels (std::mt19937_64 seeded with options.seed), rounding
// and saturation to 8 bits.
//
// Errors: hecal::InputError (source "target") when pose::CheckTarget rejects the spec or an
// AprilTag family's data bits would overlap between neighbouring markers (spacing too small);
// the InputError of RenderOptions::IsValid; (source "options") for no image size (options and
// camera both 0); (source "T_camera_target") when the camera sees the back of the board (camera
// centre at z ≥ 0 in the target frame).
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"

namespace hecal::vision {

struct RenderOptions {
  int width = 0;               // pixels; 0: camera.width
  int height = 0;              // pixels; 0: camera.height
  double blur_sigma = 0.0;     // pixels
  double noise_sigma = 0.0;    // grey levels
  double background = 128.0;   // grey level off the board
  double black = 20.0;         // grey level of the printed black
  double white = 235.0;        // grey level of the paper
  double margin = 1.0;         // white border, in pattern pitches
  double circle_radius = 0.3;  // circles: radius / smallest centre distance, in (0, 0.5)
  int supersampling = 8;       // samples per pixel along each axis
  std::uint64_t seed = 1;      // noise

  // core/options_check.h: false naming RenderOptions.size (a negative side), .blur_sigma,
  // .noise_sigma or .margin (negative or not finite), .background, .black or .white (not a grey
  // level 0 … 255), .circle_radius (not in (0, 0.5)) or .supersampling (not 1 … 64).
  bool IsValid(std::string* why) const;
};

// An 8-bit single-channel image of the target (see above).
cv::Mat RenderTarget(const pose::TargetSpec& target, const pose::CameraModel& camera,
                     const Pose& T_camera_target, const RenderOptions& options = {});

}  // namespace hecal::vision
