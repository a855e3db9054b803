// A target description that one image shows to be wrong: see target_mismatch.h.
#include "hecal/vision/target_mismatch.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <optional>
#include <vector>

#include "hecal/vision/chessboard_extent.h"
#include "hecal/vision/chessboard_size_probe.h"
#include "hecal/vision/image_set.h"
#include "hecal/vision/marker_probe.h"
#include "size_text.h"

namespace hecal::vision {
namespace {

constexpr double kLayoutMisfit = 0.10;  // of a marker's side: the described layout misfits
constexpr double kLayoutFit = 0.05;     // of a marker's side: the transposed layout fits
constexpr double kLayoutRatio = 0.25;   // and fits this much better

TargetMismatch ChessboardMismatch(const cv::Mat& gray, const pose::TargetSpec& target,
                                  const Detection& detection) {
  const std::string described = internal::SizeText(target.cols, target.rows);
  if (detection.status == DetectionStatus::kNotFound) {
    const std::optional<cv::Size> size = ProbeChessboardSize(gray, target.cols, target.rows);
    if (!size) return {};
    const std::string shown = internal::SizeText(size->width, size->height);
    return {"no " + described + " chessboard found, but a whole " + shown +
                " one: the images show a " + shown + " chessboard, the file says " + described,
            "set cols: " + std::to_string(size->width) +
                " and rows: " + std::to_string(size->height) +
                " (cols/rows count INNER corners: a board of 25x18 squares has 24x17)"};
  }
  if (detection.num_points() != detection.total_points) return {};
  const ChessboardExtent extent =
      MeasureChessboardExtent(gray, target.cols, target.rows, PixelsOf(detection));
  if (!extent.larger()) return {};
  const std::string fix =
      "set cols and rows to the INNER corners of the whole printed board (a board of 25x18 "
      "squares has 24x17): the detector finds the described " +
      described + " corners at a different place on the larger board in each image";
  if (extent.not_neighbours) {
    return {"the " + described +
                " corners found are not neighbouring corners of one chessboard (the squares "
                "between them do not alternate dark and bright): they are corners of a larger "
                "board, several squares apart",
            fix};
  }
  return {"the chessboard continues beyond the " + described + " inner corners described: it has " +
              (extent.out_of_view ? "at least " : "") +
              internal::SizeText(target.cols + extent.before_x + extent.after_x,
                                 target.rows + extent.before_y + extent.after_y),
          fix};
}

bool UsesAprilTags(pose::TargetType type) {
  return type == pose::TargetType::kAprilTagGrid || type == pose::TargetType::kAprilTag;
}

// The dictionary (ArUco types) or family (AprilTag types) the file names.
std::string DescribedCode(const pose::TargetSpec& target) {
  return UsesAprilTags(target.type) ? target.family : target.dictionary;
}

// Do the markers seen belong to the kind of the described dictionary or family?
bool SameKind(const pose::TargetSpec& target, const MarkersSeen& seen) {
  if (UsesAprilTags(target.type)) return seen.family == target.family;
  if (seen.dictionary == "DICT_ARUCO_ORIGINAL" || seen.dictionary.starts_with("DICT_APRILTAG_")) {
    return target.dictionary == seen.dictionary;
  }
  const std::string prefix = seen.dictionary.substr(0, seen.dictionary.rfind('_') + 1);
  return target.dictionary.starts_with(prefix);
}

// The first id on the board (grids: first_id; single tags: id; charuco: 0).
int FirstId(const pose::TargetSpec& target) {
  if (pose::IsSingleTag(target.type)) return target.id;
  return target.type == pose::TargetType::kCharuco ? 0 : target.first_id;
}

// The change of type / dictionary / family that reads the markers seen.
std::string CodeFix(const pose::TargetSpec& target, const MarkersSeen& seen) {
  const bool grid = !pose::IsSingleTag(target.type);
  if (!seen.family.empty()) {  // AprilTags
    if (UsesAprilTags(target.type)) return "set family: " + seen.family;
    if (target.type == pose::TargetType::kCharuco) return "set dictionary: " + seen.dictionary;
    return std::string("use type: ") + (grid ? "apriltag_grid" : "apriltag") +
           " with family: " + seen.family + " (in place of dictionary)";
  }
  if (!UsesAprilTags(target.type)) {
    return "set dictionary: " + seen.Smallest() + " (or the larger " +
           seen.dictionary.substr(0, seen.dictionary.rfind('_')) +
           " dictionary the board was made with)";
  }
  return std::string("use type: ") + (grid ? "aruco_grid" : "aruco") +
         " with dictionary: " + seen.Smallest() + " (in place of family)";
}

TargetMismatch MarkerCodeMismatch(const cv::Mat& gray, const pose::TargetSpec& target) {
  const int markers = pose::MarkerCount(target);
  const std::optional<MarkersSeen> seen = ProbeMarkers(gray, std::min(2, markers));
  if (!seen) return {};
  const std::string found = "no point of the " + Describe(target) + " found, but " +
                            std::to_string(seen->count) + " " + seen->Kind() + " (ids " +
                            std::to_string(seen->min_id) + " to " + std::to_string(seen->max_id) +
                            ")";
  if (!SameKind(target, *seen)) {
    return {
        found + ": the images show " + seen->Kind() + ", the file says " + DescribedCode(target),
        CodeFix(target, *seen)};
  }
  const int first = FirstId(target), last = first + markers - 1;
  if (seen->max_id >= first && seen->min_id <= last) return {};  // the board's ids are there
  const std::string ids = markers == 1
                              ? "id " + std::to_string(first)
                              : "ids " + std::to_string(first) + " to " + std::to_string(last);
  std::string fix;
  if (pose::IsSingleTag(target.type)) {
    fix = "set id: to the tag's id (" + std::to_string(seen->min_id) +
          (seen->count > 1 ? " to " + std::to_string(seen->max_id) : std::string()) + " seen)";
  } else if (target.type == pose::TargetType::kCharuco) {
    fix =
        "check the dictionary and cols/rows against the print (a ChArUco board's markers are "
        "numbered from 0)";
  } else {
    fix = "set first_id: " + std::to_string(seen->min_id) +
          " if that is the top-left marker, and check cols/rows";
  }
  return {found + ", none of them the board's " + ids, fix};
}

// The RMS of the least-squares homography from the layout's marker corners (target plane) to the
// pixels, or nullopt when it cannot be fitted.
std::optional<double> LayoutRms(const pose::TargetSpec& layout, const Detection& detection) {
  const std::vector<pose::ObjectPoint> object = pose::ObjectPoints(layout);
  std::vector<cv::Point2d> from, to;
  for (const ImagePoint& p : detection.points) {
    const Eigen::Vector3d& x = object[static_cast<std::size_t>(p.id)].position;
    from.emplace_back(x.x(), x.y());
    to.emplace_back(p.pixel.x(), p.pixel.y());
  }
  const cv::Mat H = cv::findHomography(from, to, 0);
  if (H.empty()) return std::nullopt;
  std::vector<cv::Point2d> mapped;
  cv::perspectiveTransform(from, mapped, H);
  double sum = 0.0;
  for (std::size_t k = 0; k < to.size(); ++k) sum += std::pow(cv::norm(mapped[k] - to[k]), 2);
  return std::sqrt(sum / static_cast<double>(to.size()));
}

TargetMismatch GridLayoutMismatch(const pose::TargetSpec& target, const Detection& detection) {
  if (target.cols == target.rows || detection.num_points() < 12) return {};
  double side = 0.0;  // mean marker side, px: corners 0-1 of each marker
  int sides = 0;
  for (std::size_t k = 0; k + 1 < detection.points.size(); ++k) {
    const ImagePoint& a = detection.points[k];
    const ImagePoint& b = detection.points[k + 1];
    if (a.id % 4 != 0 || b.id != a.id + 1) continue;
    side += (b.pixel - a.pixel).norm();
    ++sides;
  }
  if (sides == 0) return {};
  side /= sides;
  pose::TargetSpec transposed = target;
  std::swap(transposed.cols, transposed.rows);
  const std::optional<double> given = LayoutRms(target, detection);
  const std::optional<double> turned = LayoutRms(transposed, detection);
  if (!given || !turned || !(*given >= kLayoutMisfit * side) || !(*turned <= kLayoutFit * side) ||
      !(*turned <= kLayoutRatio * *given)) {
    return {};
  }
  const std::string described = internal::SizeText(target.cols, target.rows);
  const std::string shown = internal::SizeText(target.rows, target.cols);
  char figures[160];
  std::snprintf(figures, sizeof figures,
                "(homography RMS %.1f px) but where a %s grid does (%.1f px)", *given,
                shown.c_str(), *turned);
  return {"the markers found do not lie where a " + described + " grid puts them " + figures +
              ": the images show a " + shown + " grid, the file says " + described,
          "set cols: " + std::to_string(target.rows) + " and rows: " + std::to_string(target.cols) +
              " (cols counts the markers along x, the direction "
              "in which the ids go up first)"};
}

}  // namespace

TargetMismatch FindTargetMismatch(const cv::Mat& gray, const pose::TargetSpec& target,
                                  const Detection& detection) {
  switch (target.type) {
    case pose::TargetType::kChessboard:
      return ChessboardMismatch(gray, target, detection);
    case pose::TargetType::kArucoGrid:
    case pose::TargetType::kAprilTagGrid:
      if (detection.num_points() > 0) return GridLayoutMismatch(target, detection);
      return MarkerCodeMismatch(gray, target);
    case pose::TargetType::kCharuco:
    case pose::TargetType::kAruco:
    case pose::TargetType::kAprilTag:
      if (detection.num_points() > 0) return {};
      return MarkerCodeMismatch(gray, target);
    case pose::TargetType::kCircles:
    case pose::TargetType::kAsymmetricCircles:
      break;
  }
  return {};
}

}  // namespace hecal::vision
