// Calibration targets: their description (target.yaml, docs/targets.md) and the
// 3-D positions of their points in the target frame. Lengths in metres; every point has z = 0.
//
// The target frame of a board is OpenCV 4.6's frame for that board, so poses compare with
// OpenCV's; a single tag's is libapriltag's. In every one x runs to the right (along the
// columns), y down (along the rows), z = x × y into the board (away from a viewer facing the
// printed side). Origin and point ids (what a detection reports for each pixel):
//
//   chessboard  cols × rows inner corners. Corner (c, r) has id r·cols + c and sits at
//               (c·square, r·square, 0): the origin is the first inner corner, the order is
//               findChessboardCorners' (row by row), the object points are those of OpenCV's
//               calibration sample (samples/cpp/calibration.cpp, calcChessboardCorners).
//   circles     cols × rows circle centres, spacing `square`; id r·cols + c at
//               (c·square, r·square, 0), findCirclesGrid(CALIB_CB_SYMMETRIC_GRID) order.
//   acircles    OpenCV's asymmetric grid: `rows` rows of `cols` circles, odd rows shifted by half
//               a pitch (cols = patternSize.width, rows = patternSize.height, e.g. 4 × 11 for
//               OpenCV's acircles_pattern.png). Centre (c, r) has id r·cols + c at
//               ((2c + r mod 2)·square, r·square, 0), as calcChessboardCorners builds
//               ASYMMETRIC_CIRCLES_GRID and findCirclesGrid(CALIB_CB_ASYMMETRIC_GRID) orders the
//               centres. So `square` is the distance between rows and half the distance between
//               neighbours within a row; diagonal neighbours are √2·square apart.
//   charuco     cols × rows SQUARES (cv::aruco::CharucoBoard::create(cols, rows, square, marker,
//               dictionary) in OpenCV 4.6): origin at the board's top-left outer corner, the
//               top-left square black, markers in the white squares (row-major, ids 0, 1, ...).
//               Points are the (cols−1) × (rows−1) inner chessboard corners: corner (c, r) has id
//               r·(cols−1) + c at ((c+1)·square, (r+1)·square, 0) — CharucoBoard's
//               chessboardCorners and the ids interpolateCornersCharuco reports.
//   aruco_grid, apriltag_grid  cols × rows markers of side `marker`, `spacing` apart
//               (cv::aruco::GridBoard::create(cols, rows, marker, spacing, dictionary, first_id) in
//               OpenCV 4.6): origin at the top-left corner of the top-left marker. Marker
//               m = r·cols + c (tag id first_id + m) has its top-left corner at
//               (c·(marker + spacing), r·(marker + spacing), 0); its corners get ids 4m + 0..3 in
//               OpenCV's aruco order: top-left, top-right, bottom-right, bottom-left (clockwise as
//               seen on the printed side). For AprilTags, `marker` is the side of the square
//               libapriltag's detection corners span (its tagsize).
//   aruco, apriltag  ONE marker: tag `id` of the dictionary / family, side `size` (like
//               `marker` above, the black square the detector's corners span). Origin at the
//               tag's CENTRE, x to the right, y down, z into the tag: libapriltag 3's tag frame
//               (apriltag_pose.c, estimate_tag_pose_orthogonal_iteration, puts its detection
//               corners p[0..3] — bottom-left, bottom-right, top-right, top-left of the printed
//               tag — at (−s/2, s/2), (s/2, s/2), (s/2, −s/2), (−s/2, −s/2)), also ViSP's
//               vpDetectorAprilTag with setZAlignedWithCameraAxis(true). Corner ids 0..3 are
//               top-left, top-right, bottom-right, bottom-left (aruco order, as for the grids) at
//               (−s/2, −s/2, 0), (s/2, −s/2, 0), (s/2, s/2, 0), (−s/2, s/2, 0), s = size.
//               OpenCV 4.6's aruco::estimatePoseSingleMarkers (default PatternPos CCW_center) and
//               ViSP by default put the origin at the centre too, but with y UP and z OUT of the
//               tag: their pose is T_camera_tag · diag(1, −1, −1), a half turn about x. OpenCV's
//               CW_top_left_corner pattern is this frame moved to the top-left corner:
//               T_camera_tag · Translation(−s/2, −s/2, 0). (target_opencv_test checks OpenCV's
//               object points, detection_tag_test the poses of libapriltag and OpenCV.)
//
// OpenCV before 4.6 (and moveit_calibration's numbers) put ArUco/ChArUco boards' origin at the
// bottom-left with y up and z out of the board; data/moveit-calibration/SOURCE.md converts.
// Patterns that look the same after a half turn (chessboards, symmetric circle grids) can be
// reported from either end, so their frame is fixed only up to a half turn about z. Asymmetric
// grids with an even number of rows have that symmetry too, and OpenCV 4.6 numbers them in an
// order that matches no placement of the object points (target_opencv_test shows it), so
// CheckTarget rejects them.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hecal::pose {

enum class TargetType {
  kChessboard,
  kCharuco,
  kArucoGrid,
  kAprilTagGrid,
  kCircles,
  kAsymmetricCircles,
  kAruco,    // one ArUco marker
  kAprilTag  // one AprilTag
};

// Every field has a default (the unused ones stay zero or empty), so that a spec can be written
// with designated initializers: {.type = TargetType::kChessboard, .cols = 9, .rows = 6}.
struct TargetSpec {
  TargetType type = TargetType::kChessboard;
  int cols = 0;  // chessboard/circles/acircles: points along x; charuco: squares; grids: markers
  int rows = 0;  // likewise along y
  double square = 0.0;       // chessboard/charuco square side; circles/acircles pitch (see above)
  double marker = 0.0;       // charuco / aruco_grid / apriltag_grid marker side
  double spacing = 0.0;      // aruco_grid / apriltag_grid gap between neighbouring markers
  std::string dictionary{};  // charuco / aruco_grid: an ArucoDictionaries() name, "DICT_5X5_250"
  std::string family{};      // apriltag_grid / apriltag: an AprilTagFamilies() name, "tag36h11"
  int first_id = 0;          // grids: tag id of the top-left marker
  int id = 0;                // aruco / apriltag: the tag's id
  double size = 0.0;         // aruco / apriltag: the tag's side (see above)
};

// "chessboard" | "charuco" | "aruco_grid" | "apriltag_grid" | "circles" | "acircles" | "aruco" |
// "apriltag".
std::string_view TargetTypeName(TargetType type);
// The inverse of TargetTypeName; nullopt for any other text.
std::optional<TargetType> ParseTargetType(std::string_view name);
// Every type, in the order listed above.
std::span<const TargetType> TargetTypes();

// The fields of TargetSpec (target.yaml keys), and which of them a type uses.
enum class TargetField {
  kCols,
  kRows,
  kSquare,
  kMarker,
  kSpacing,
  kDictionary,
  kFamily,
  kFirstId,
  kId,
  kSize
};
enum class FieldUse { kUnused, kRequired, kOptional };
std::string_view TargetFieldName(TargetField field);  // "cols", "rows", ..., "id", "size"
std::span<const TargetField> TargetFields();
FieldUse TargetFieldUse(TargetType type, TargetField field);

// A named marker set and how many distinct ids it has.
struct MarkerDictionary {
  std::string_view name;
  int size = 0;
};
// OpenCV 4.6's predefined ArUco dictionaries (cv::aruco::PREDEFINED_DICTIONARY_NAME), in enum
// order: entry k is the dictionary with enum value k (DICT_4X4_50 = 0 ... DICT_APRILTAG_36h11).
std::span<const MarkerDictionary> ArucoDictionaries();
// The AprilTag families libapriltag 3.3 (Debian 12's libapriltag-dev) ships.
std::span<const MarkerDictionary> AprilTagFamilies();

// True for aruco and apriltag (one marker).
bool IsSingleTag(TargetType type);

// Markers on the target: charuco ⌊cols·rows/2⌋, grids cols·rows, single tags 1, 0 for the others.
int MarkerCount(const TargetSpec& target);
// Points ObjectPoints returns: chessboard/circles/acircles cols·rows, charuco (cols−1)·(rows−1),
// grids 4·cols·rows, single tags 4.
int PointCount(const TargetSpec& target);

// Why a spec does not describe a usable target: the field at fault, what is wrong, how to fix.
struct TargetProblem {
  TargetField field = TargetField::kCols;
  std::string problem;
  std::string fix;
};
// nullopt when the spec is usable. Checks, for the spec's type: every required field set (counts
// and lengths positive and finite, names non-empty) and every unused field left at its default;
// cols, rows ≥ 2 (charuco ≥ 3 squares, so the inner corners are not on one line) and ≤ 1000;
// marker < square (charuco); a known dictionary / family with enough ids for
// first_id + MarkerCount markers (single tags: id + 1); first_id, id ≥ 0; acircles with an odd
// number of rows (see above). Whether the lengths are plausible for a printed target is the
// file reader's question (io/target_file.h), which knows the unit they were written in.
std::optional<TargetProblem> CheckTarget(const TargetSpec& target);

struct ObjectPoint {
  int id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // target frame, metres
};

// Every point of the target, ordered by id (ids 0 .. PointCount − 1, see the header comment).
// Throws hecal::InputError (source "TargetSpec.<field>") with CheckTarget's problem and fix when
// the spec is not usable.
std::vector<ObjectPoint> ObjectPoints(const TargetSpec& target);

}  // namespace hecal::pose
