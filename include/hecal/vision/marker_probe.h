// Which square markers does an image show? When a marker target (charuco, aruco_grid,
// apriltag_grid, aruco, apriltag) is found in no image, the likeliest mistakes in its description
// are the dictionary or family (a DICT_4X4_50 board described as DICT_5X5_250, an AprilTag board
// described as ArUco) and the ids (first_id, or a single tag's id).
//
// Method: cv::aruco::detectMarkers (OpenCV 4.6) with the largest predefined dictionary of each
// kind: DICT_4X4_1000, DICT_5X5_1000, DICT_6X6_1000, DICT_7X7_1000, DICT_ARUCO_ORIGINAL and the
// four AprilTag families OpenCV decodes (DICT_APRILTAG_16h5, 25h9, 36h10, 36h11; their codes are
// those of libapriltag's tag16h5 … tag36h11). The smaller dictionaries of a kind are the first
// codes of the largest (DICT_4X4_50 is the first 50 of DICT_4X4_1000), so a marker of any of them
// is found with its id. The kind with the most markers, at least `min_markers` (the caller asks
// for 2 on a board, so that one chance decoding in a textured image does not count), is the
// answer, with the range of ids seen; a tie goes to the kind listed first.
//
// Input: an 8-bit grey image. Output: the kind found, or nullopt.
#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>

namespace hecal::vision {

struct MarkersSeen {
  std::string dictionary;  // the largest OpenCV dictionary of the kind, e.g. "DICT_5X5_1000"
  std::string family;      // the AprilTag family name when the kind is AprilTag ("tag36h11")
  int count = 0;           // markers found (distinct ids)
  int min_id = 0, max_id = 0;

  // The kind, for messages: "DICT_5X5" markers, or "tag36h11" AprilTags.
  std::string Kind() const;
  // The smallest predefined dictionary of the kind that holds every id seen ("DICT_5X5_50"), or
  // the family ("tag36h11").
  std::string Smallest() const;
};

std::optional<MarkersSeen> ProbeMarkers(const cv::Mat& gray, int min_markers);

}  // namespace hecal::vision
