// Point order of grid targets: the canonical order, per image and across a set of images.
//
// Why: OpenCV's grid detectors (findChessboardCorners[SB], findCirclesGrid) return a cols × rows
// grid of points row by row, but which end of the board they start from is not defined — on the
// same image findChessboardCornersSB starts at one corner and findChessboardCorners at the
// opposite one. Labelling the points from the wrong end turns the pose by a half turn about the
// board normal (T_camera_target → T_camera_target · F, F = a 180° rotation about z through the
// pattern's centre), which moves Z of a hand–eye calibration by the board's diagonal. Marker
// targets (charuco, aruco_grid, apriltag_grid) have decoded ids and never need this.
//
// Canonical order (the target frame of hecal/pose/target.h): point (c, r) has id r·cols + c, the
// x axis runs along the columns, y along the rows, z = x × y into the board. Seen from the
// printed side (the only side a camera can see), the image of this frame is right-handed in
// pixel coordinates (u right, v down): the quadrilateral of the four extreme points
// (0,0) → (cols−1,0) → (cols−1,rows−1) → (0,rows−1) has positive signed area
// Σ (u_k v_{k+1} − u_{k+1} v_k) > 0.
//
// Per image (CanonicalGridOrder), on the detector's row-major grid:
//   1. Handedness. Negative area means the detector mirrored the grid; the rows are reversed
//      ((c, r) → (c, rows−1−r)), a symmetry of chessboards, circle grids and asymmetric grids
//      with an odd number of rows (pose::CheckTarget rejects the even ones). An area under 1 px²
//      (the extreme points on a line): kInvalid.
//   2. Half turn. The half turn (c, r) → (cols−1−c, rows−1−r), i.e. id → N−1−id, keeps the
//      handedness. It maps the point set onto itself for chessboards and symmetric circle grids,
//      not for asymmetric grids with an odd number of rows (their order is then unique).
//      Chessboard squares: square (i, j), i = 0..cols, j = 0..rows, is the square whose
//      top-left inner-corner neighbour is corner (i−1, j−1); the canonical colouring has square
//      (0, 0) — the outer square diagonally before id 0 — BLACK, so square (i, j) is black iff
//      i + j is even (OpenCV's pattern generator and CharucoBoard draw boards this way). A half
//      turn maps square (i, j) to (cols−i, rows−j), so it preserves the colouring iff
//      cols + rows is even. When cols + rows is odd (e.g. 24 × 17) the colours decide: each
//      interior square (between four detected corners, i, j ≥ 1) is sampled at its centre and
//      counted as dark when below the median of all interior samples; if at least 80% of the
//      squares agree with the canonical colouring the order is kept, if at most 20% do it is
//      turned, otherwise (unreadable colours: glare, low contrast) the result is kSymmetric.
//   3. Otherwise (symmetric circle grid, chessboard with cols + rows even) the image alone cannot
//      tell: kSymmetric, with the image rule applied: of the two orders the one whose x axis
//      (Σ_r p(cols−1, r) − p(0, r)) points right in the image (u component > 0; on a tie, down) is
//      returned. DetectTarget reports such detections as ambiguous.
//
// Across images (ResolveOrder), for the ambiguous detections of one target, in the order given
// (acquisition order):
//   The first ambiguous detection is the reference; its image-rule order is kept. The others are
//   ordered by one of two rules, each comparison giving "keep", "turn" or "undecided":
//   - robot rule (options.camera and options.R_base_gripper given): the rotation angle of a
//     relative motion is the same seen by the robot and by the camera, for eye-in-hand and
//     eye-to-hand alike: ∠(R_Bi^T R_Bj) = ∠(R_Cj R_Ci^T), R_C the rotation of T_camera_target
//     (IPPE pose from the detection). The two orders of j give R_Cj and R_Cj·Rz(π); a comparison
//     decides when exactly one of them agrees with the robot angle within
//     options.angle_tolerance_deg. Every ordered view is compared with every open one; a view is
//     ordered when at least one comparison decides and none disagrees; repeated until nothing
//     changes. No assumption on how the views differ.
//   - image rule (no robot rotations): a chain. View j is compared with view j − 1 only: the
//     angle between their x-axis directions d_{j−1}, d_j (as in step 3) below 90° −
//     options.direction_margin_deg → keep, above 90° + margin → turn, else undecided. This
//     assumes the board turns in the image by less than 90° − margin between consecutive views
//     (a camera that does not roll by more than that from one view to the next); comparing with
//     views further apart would not be safe, since their roll may exceed a quarter turn. The
//     chain stops at the first undecided view: it and every later view stay ambiguous. With
//     larger rolls give the robot rotations.
//   Views left undecided, or with disagreeing decisions, stay ambiguous and are listed in
//   OrderReport::ambiguous: skip them (never guess). Ordered detections become found, with order
//   kReference (the reference) or kConsistency.
//
// Errors: the InputError of OrderOptions::IsValid (a tolerance out of range, R_base_gripper
// without a camera); hecal::InputError (source "options") when R_base_gripper's count differs from
// the number of detections.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/detection.h"

namespace hecal::vision {

enum class GridOrder {
  kUnique,     // canonical order fixed by this image
  kSymmetric,  // fixed up to a half turn (image rule applied)
  kInvalid,    // not a usable grid: wrong point count, or extreme points (nearly) on one line
};

// Rewrites `grid` — cols × rows points in the row-major order of an OpenCV grid detector, for a
// chessboard, circles or acircles target — into the canonical order. `gray` is the 8-bit
// single-channel image the points were found in (chessboard square colours).
GridOrder CanonicalGridOrder(const cv::Mat& gray, const pose::TargetSpec& target,
                             std::vector<cv::Point2f>* grid);

struct OrderOptions {
  // Robot rule: the intrinsics (for the IPPE pose of each view) and R_base_gripper of each
  // detection (same indexing as the detections). Leave both empty for the image rule.
  std::optional<pose::CameraModel> camera;
  std::vector<Eigen::Matrix3d> R_base_gripper;
  double angle_tolerance_deg = 3.0;    // robot rule
  double direction_margin_deg = 20.0;  // image rule, in (0, 90)

  // core/options_check.h: false naming OrderOptions.angle_tolerance_deg or
  // .direction_margin_deg (not in (0, 90)), or .camera (R_base_gripper given without it).
  bool IsValid(std::string* why) const;
};

struct OrderReport {
  int reference = -1;          // index of the reference detection; -1 when none was ambiguous
  std::vector<int> turned;     // detections whose order was turned by a half turn
  std::vector<int> ambiguous;  // detections left ambiguous: skip them
};

// Makes the ambiguous detections of `target` (all views of one physical board) consistent with
// each other, in place; other detections are not touched. See the rules above.
OrderReport ResolveOrder(const pose::TargetSpec& target, const OrderOptions& options,
                         std::vector<Detection>* detections);

}  // namespace hecal::vision
