// Pieces shared by the detectors (detection*.cc), the order rules and the renderer (render.cc):
// target checks, image conversion, marker dictionaries and AprilTag families, the per-type
// detectors, the edge-based corner refinement and the sharpness measure. Internal to the vision
// module.
#pragma once

#include <opencv2/aruco.hpp>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/detection.h"

struct apriltag_family;

namespace hecal::vision::internal {

// Throws hecal::InputError (source "target") when pose::CheckTarget rejects the spec.
void RequireUsableTarget(const pose::TargetSpec& target);

// The image as 8-bit grey (a view when it already is); InputError (source "image") for an empty
// image or one that is not 8-bit with 1, 3 (BGR) or 4 (BGRA) channels.
cv::Mat ToGray(const cv::Mat& image);

// OpenCV's predefined dictionary of that name (pose::ArucoDictionaries() order = enum order).
// Throws InputError (source "target") for an unknown name.
cv::Ptr<cv::aruco::Dictionary> ArucoDictionary(const std::string& name);

// A libapriltag family created by name (pose::AprilTagFamilies()) and destroyed with it.
// Throws InputError (source "target") for an unknown name.
class AprilTagFamily {
 public:
  explicit AprilTagFamily(const std::string& name);
  ~AprilTagFamily();
  AprilTagFamily(const AprilTagFamily&) = delete;
  AprilTagFamily& operator=(const AprilTagFamily&) = delete;

  apriltag_family* get() const { return family_; }
  int total_width() const;      // cells across a printed tag
  int width_at_border() const;  // cells across the square the detection corners span

 private:
  apriltag_family* family_ = nullptr;
  void (*destroy_)(apriltag_family*) = nullptr;
};

// The printed cells of tag `id` of an AprilTag family, row 0 at the top: total_width² values,
// 1 = white, 0 = black (apriltag_to_image).
cv::Mat AprilTagCells(const AprilTagFamily& family, int id);

// The markers of a target made of markers only, as a grid: aruco_grid and apriltag_grid as
// they are, a single tag (aruco, apriltag) as a 1 × 1 grid of its id with no neighbours
// (spacing 0). `origin` is the top-left corner of marker 0 in the target frame: (0, 0) for the
// grids, (−size/2, −size/2) for a single tag (pose/target.h). Marker m's corners are point ids
// 4m + 0..3 either way.
struct MarkerGrid {
  int cols = 1;
  int rows = 1;
  double marker = 0.0;   // side, metres
  double spacing = 0.0;  // gap between neighbours, metres
  int first_id = 0;      // tag id of marker 0
  cv::Point2d origin;
};
// For aruco_grid, apriltag_grid, aruco and apriltag targets.
MarkerGrid MarkerGridOf(const pose::TargetSpec& target);

// The per-type detectors (detection_markers.cc, detection_apriltag.cc); `gray` is 8-bit grey.
// The marker detectors take aruco_grid and aruco, apriltag_grid and apriltag targets, and refine
// the corners with `camera` when it is given (RefineMarkerCorners).
Detection DetectCharuco(const cv::Mat& gray, const pose::TargetSpec& target,
                        const DetectOptions& options);
Detection DetectArucoMarkers(const cv::Mat& gray, const pose::TargetSpec& target,
                             const DetectOptions& options,
                             const std::optional<pose::CameraModel>& camera);
Detection DetectAprilTags(const cv::Mat& gray, const pose::TargetSpec& target,
                          const DetectOptions& options,
                          const std::optional<pose::CameraModel>& camera);

// Edge-based corner refinement (detection_edges.cc).
// Moves the corners of square markers (4 each, in order around the marker) to the intersections
// of their fitted sides; `cells_across` is the number of marker cells the corners span (ArUco
// markerSize + 2, AprilTag width_at_border). With `camera` (the image's intrinsics) the sides are
// fitted and intersected in undistorted (ideal) pixels, where they are straight.
void RefineMarkerCorners(const cv::Mat& gray, int cells_across,
                         const std::optional<pose::CameraModel>& camera,
                         std::vector<std::vector<cv::Point2f>>* markers);
// Moves the saddle corners of a cols × rows grid of inner corners (row-major, nullopt where not
// detected) to the intersections of their fitted grid lines; the edge band's half-width is
// band_fraction × the distance to the nearer neighbour.
void RefineSaddleCorners(const cv::Mat& gray, int cols, int rows, double band_fraction,
                         std::vector<std::optional<cv::Point2f>>* grid);

// Removes every marker whose id occurs more than once (which of them belongs to the board cannot
// be told); returns "<count> <noun>", naming the dropped ids and, when `others` (decoded ids
// that are not the target's, ignored) is not empty, those.
std::string KeepUniqueMarkers(std::vector<int>* ids, std::vector<std::vector<cv::Point2f>>* corners,
                              const std::string& noun, const std::vector<int>& others);

// The corner points of grid markers (aruco_grid, apriltag_grid): marker id first_id + m gives
// point ids 4m + 0..3 from its corners in aruco order.
std::vector<ImagePoint> GridMarkerPoints(const std::vector<int>& ids,
                                         const std::vector<std::vector<cv::Point2f>>& corners,
                                         int first_id);

// Finishes the detection of a marker target from labelled points (unique ids, any order): sorts
// them, sets the status (found / partial / not_found by detection.h's rules), the sharpness and
// the message, which starts with `summary` (e.g. "12 markers").
Detection MarkerDetection(const cv::Mat& gray, const pose::TargetSpec& target,
                          const DetectOptions& options, std::vector<ImagePoint> points,
                          const std::string& summary);

// Mean edge width in pixels around `points` (detection.h: the gradient-based sharpness);
// NaN when fewer than 2 points.
double MeanEdgeWidth(const cv::Mat& gray, const std::vector<cv::Point2f>& points);

// The smallest distance between two of `points` (infinity for fewer than 2).
double SmallestSpacing(const std::vector<cv::Point2f>& points);

}  // namespace hecal::vision::internal
