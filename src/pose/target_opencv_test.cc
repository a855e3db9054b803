// hecal's target geometry against OpenCV 4.6 on identical specs: ChArUco and ArUco-grid object
// points from cv::aruco's own boards, a single tag's frame against estimatePoseSingleMarkers'
// object points, chessboard and circle-grid point order from OpenCV's detectors on rendered
// images, and the dictionary / AprilTag family tables from the libraries.
#include <apriltag/apriltag.h>
#include <apriltag/tag16h5.h>
#include <apriltag/tag25h9.h>
#include <apriltag/tag36h10.h>
#include <apriltag/tag36h11.h>
#include <apriltag/tagCircle21h7.h>
#include <apriltag/tagCircle49h12.h>
#include <apriltag/tagCustom48h12.h>
#include <apriltag/tagStandard41h12.h>
#include <apriltag/tagStandard52h13.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/aruco.hpp>
#include <opencv2/aruco/charuco.hpp>
#include <opencv2/calib3d.hpp>

#include "hecal/pose/target.h"

namespace hecal::pose {
namespace {

// OpenCV's boards store float coordinates: agreement to float precision of the board size
// (measured: at most 4.2e-8 m).
constexpr double kFloatTolerance = 1e-6;

double Distance(const Eigen::Vector3d& a, const cv::Point3f& b) {
  return (a - Eigen::Vector3d(b.x, b.y, b.z)).norm();
}

cv::Ptr<cv::aruco::Dictionary> Dictionary(const std::string& name) {
  const auto list = ArucoDictionaries();
  const auto it = std::find_if(list.begin(), list.end(),
                               [&](const MarkerDictionary& d) { return d.name == name; });
  return cv::aruco::getPredefinedDictionary(static_cast<int>(it - list.begin()));
}

TEST(TargetOpenCv, DictionaryTableMatchesOpenCvEnum) {
  const auto list = ArucoDictionaries();
  for (size_t k = 0; k < list.size(); ++k) {
    const cv::Ptr<cv::aruco::Dictionary> dictionary =
        cv::aruco::getPredefinedDictionary(static_cast<int>(k));
    EXPECT_EQ(dictionary->bytesList.rows, list[k].size) << list[k].name;
    // The name says the bit grid: DICT_5X5_* → 5, DICT_APRILTAG_36h* → 6, ARUCO_ORIGINAL → 5.
    const std::string name(list[k].name);
    int bits = 0;
    if (name.rfind("DICT_APRILTAG_", 0) == 0) {
      bits = static_cast<int>(std::lround(std::sqrt(std::stoi(name.substr(14, 2)))));
    } else if (name == "DICT_ARUCO_ORIGINAL") {
      bits = 5;
    } else {
      bits = name[5] - '0';
    }
    EXPECT_EQ(dictionary->markerSize, bits) << name;
  }
  // The table ends where the enum does.
  EXPECT_EQ(list.size(), static_cast<size_t>(cv::aruco::DICT_APRILTAG_36h11) + 1);
}

TEST(TargetOpenCv, AprilTagFamiliesMatchLibapriltag) {
  struct Family {
    apriltag_family_t* (*create)();
    void (*destroy)(apriltag_family_t*);
  };
  const Family families[] = {{tag16h5_create, tag16h5_destroy},
                             {tag25h9_create, tag25h9_destroy},
                             {tag36h10_create, tag36h10_destroy},
                             {tag36h11_create, tag36h11_destroy},
                             {tagCircle21h7_create, tagCircle21h7_destroy},
                             {tagCircle49h12_create, tagCircle49h12_destroy},
                             {tagCustom48h12_create, tagCustom48h12_destroy},
                             {tagStandard41h12_create, tagStandard41h12_destroy},
                             {tagStandard52h13_create, tagStandard52h13_destroy}};
  ASSERT_EQ(AprilTagFamilies().size(), std::size(families));
  for (size_t k = 0; k < std::size(families); ++k) {
    apriltag_family_t* family = families[k].create();
    EXPECT_EQ(AprilTagFamilies()[k].name, std::string_view(family->name));
    EXPECT_EQ(AprilTagFamilies()[k].size, static_cast<int>(family->ncodes)) << family->name;
    families[k].destroy(family);
  }
}

TEST(TargetOpenCv, CharucoCornersMatchCharucoBoard) {
  // The moveit board (5 × 7, square 0.1971/7, marker 0.0176) and a few other shapes.
  const struct {
    int cols, rows;
    double square, marker;
  } boards[] = {
      {5, 7, 0.1971 / 7, 0.0176}, {3, 3, 0.04, 0.03}, {8, 5, 0.025, 0.019}, {12, 9, 0.06, 0.045}};
  for (const auto& b : boards) {
    TargetSpec spec;
    spec.type = TargetType::kCharuco;
    spec.cols = b.cols;
    spec.rows = b.rows;
    spec.square = b.square;
    spec.marker = b.marker;
    spec.dictionary = "DICT_5X5_250";
    const cv::Ptr<cv::aruco::CharucoBoard> board =
        cv::aruco::CharucoBoard::create(b.cols, b.rows, static_cast<float>(b.square),
                                        static_cast<float>(b.marker), Dictionary(spec.dictionary));
    const std::vector<ObjectPoint> points = ObjectPoints(spec);
    ASSERT_EQ(points.size(), board->chessboardCorners.size());
    EXPECT_EQ(MarkerCount(spec), static_cast<int>(board->ids.size()));
    for (size_t k = 0; k < points.size(); ++k) {
      EXPECT_LT(Distance(points[k].position, board->chessboardCorners[k]), kFloatTolerance)
          << b.cols << "x" << b.rows << " corner " << k;
    }
    // The frame: the top-left square is black, so the first marker sits in square (1, 0) with
    // its top-left corner inset by (square − marker)/2 — OpenCV 4.6's top-left origin, y down.
    const double inset = (b.square - b.marker) / 2;
    EXPECT_LT(Distance(Eigen::Vector3d(b.square + inset, inset, 0), board->objPoints[0][0]),
              kFloatTolerance);
  }
}

TEST(TargetOpenCv, GridCornersMatchGridBoard) {
  const struct {
    int cols, rows;
    double marker, spacing;
    int first_id;
  } boards[] = {{4, 3, 0.0256, 0.0066, 0}, {2, 2, 0.05, 0.01, 7}, {6, 8, 0.03, 0.006, 100}};
  for (const auto& b : boards) {
    for (const TargetType type : {TargetType::kArucoGrid, TargetType::kAprilTagGrid}) {
      TargetSpec spec;
      spec.type = type;
      spec.cols = b.cols;
      spec.rows = b.rows;
      spec.marker = b.marker;
      spec.spacing = b.spacing;
      spec.first_id = b.first_id;
      (type == TargetType::kArucoGrid ? spec.dictionary : spec.family) =
          type == TargetType::kArucoGrid ? "DICT_6X6_250" : "tag36h11";
      const cv::Ptr<cv::aruco::GridBoard> board = cv::aruco::GridBoard::create(
          b.cols, b.rows, static_cast<float>(b.marker), static_cast<float>(b.spacing),
          Dictionary("DICT_6X6_250"), b.first_id);
      const std::vector<ObjectPoint> points = ObjectPoints(spec);
      ASSERT_EQ(points.size(), 4 * board->objPoints.size());
      for (size_t m = 0; m < board->objPoints.size(); ++m) {
        EXPECT_EQ(board->ids[m], b.first_id + static_cast<int>(m));  // tag id first_id + m
        for (size_t k = 0; k < 4; ++k) {
          EXPECT_LT(Distance(points[4 * m + k].position, board->objPoints[m][k]), kFloatTolerance)
              << TargetTypeName(type) << " marker " << m << " corner " << k;
        }
      }
    }
  }
}

// A single tag against OpenCV 4.6's estimatePoseSingleMarkers, which reports the object points it
// used for the corners it is given (aruco order, as hecal's ids 0..3): with the default
// PatternPos CCW_center they are hecal's turned half a turn about x, diag(1, −1, −1) (y up, z out
// of the tag); with CW_top_left_corner, hecal's moved by (size/2, size/2) (target.h).
TEST(TargetOpenCv, SingleTagFrameAgainstEstimatePoseSingleMarkers) {
  TargetSpec spec;
  spec.type = TargetType::kAruco;
  spec.dictionary = "DICT_4X4_50";
  spec.id = 3;
  spec.size = 0.07;
  const std::vector<ObjectPoint> points = ObjectPoints(spec);
  // Any corners in front of a camera: the object points do not depend on them.
  const std::vector<std::vector<cv::Point2f>> corners = {
      {{300.f, 200.f}, {380.f, 205.f}, {378.f, 290.f}, {298.f, 284.f}}};
  const cv::Matx33d K(600.0, 0.0, 320.0, 0.0, 600.0, 240.0, 0.0, 0.0, 1.0);
  const Eigen::Vector3d turn(1.0, -1.0, -1.0);
  for (const cv::aruco::PatternPos pattern :
       {cv::aruco::CCW_center, cv::aruco::CW_top_left_corner}) {
    const cv::Ptr<cv::aruco::EstimateParameters> parameters =
        cv::aruco::EstimateParameters::create();
    parameters->pattern = pattern;
    std::vector<cv::Vec3d> rvecs, tvecs;
    cv::Mat object;
    cv::aruco::estimatePoseSingleMarkers(corners, static_cast<float>(spec.size), K, cv::noArray(),
                                         rvecs, tvecs, object, parameters);
    ASSERT_EQ(object.total(), 4u);
    for (int k = 0; k < 4; ++k) {
      const cv::Point3f theirs = object.at<cv::Point3f>(k);
      const Eigen::Vector3d& ours = points[static_cast<size_t>(k)].position;
      const Eigen::Vector3d expected =
          pattern == cv::aruco::CCW_center
              ? Eigen::Vector3d(turn.cwiseProduct(ours))
              : Eigen::Vector3d(ours + Eigen::Vector3d(spec.size / 2.0, spec.size / 2.0, 0.0));
      EXPECT_LT(Distance(expected, theirs), kFloatTolerance)
          << "pattern " << pattern << " corner " << k;
    }
  }
}

// A white image with hecal's points drawn at pixel = offset + scale·(x, y): y down in the image
// is y in the target frame, as for a camera facing the printed side upright.
struct Render {
  double scale;  // pixels per metre
  double offset;
  cv::Point2d Pixel(const Eigen::Vector3d& p) const {
    return {offset + scale * p.x(), offset + scale * p.y()};
  }
};

// Filled discs of radius `radius` px, anti-aliased by 4 × 4 supersampling.
cv::Mat DrawDiscs(const std::vector<ObjectPoint>& points, const Render& render, double radius,
                  cv::Size size) {
  cv::Mat image(size, CV_8UC1, cv::Scalar(255));
  for (const ObjectPoint& point : points) {
    const cv::Point2d centre = render.Pixel(point.position);
    for (int v = static_cast<int>(centre.y - radius) - 1; v <= centre.y + radius + 1; ++v) {
      for (int u = static_cast<int>(centre.x - radius) - 1; u <= centre.x + radius + 1; ++u) {
        int inside = 0;
        for (int i = 0; i < 16; ++i) {
          const double du = u - 0.375 + 0.25 * (i % 4) - centre.x;
          const double dv = v - 0.375 + 0.25 * (i / 4) - centre.y;
          inside += du * du + dv * dv <= radius * radius;
        }
        image.at<uchar>(v, u) = static_cast<uchar>(255 - 255 * inside / 16);
      }
    }
  }
  return image;
}

// Largest distance between OpenCV's k-th detected point and hecal's point k drawn in the image.
double LargestOrderError(const std::vector<cv::Point2f>& detected,
                         const std::vector<ObjectPoint>& points, const Render& render) {
  double largest = 0.0;
  for (size_t k = 0; k < detected.size(); ++k) {
    largest =
        std::max(largest, cv::norm(cv::Point2d(detected[k]) - render.Pixel(points[k].position)));
  }
  return largest;
}

TEST(TargetOpenCv, CircleGridOrderMatchesFindCirclesGrid) {
  const Render render{1000.0, 40.0};  // 1 mm = 1 px
  const struct {
    TargetType type;
    int cols, rows;
    int flag;
  } grids[] = {{TargetType::kAsymmetricCircles, 4, 11, cv::CALIB_CB_ASYMMETRIC_GRID},
               {TargetType::kAsymmetricCircles, 5, 7, cv::CALIB_CB_ASYMMETRIC_GRID},
               {TargetType::kAsymmetricCircles, 3, 5, cv::CALIB_CB_ASYMMETRIC_GRID},
               {TargetType::kCircles, 4, 5, cv::CALIB_CB_SYMMETRIC_GRID},
               {TargetType::kCircles, 7, 6, cv::CALIB_CB_SYMMETRIC_GRID}};
  for (const auto& g : grids) {
    TargetSpec spec;
    spec.type = g.type;
    spec.cols = g.cols;
    spec.rows = g.rows;
    spec.square = 0.02;
    const std::vector<ObjectPoint> points = ObjectPoints(spec);
    const cv::Mat image = DrawDiscs(points, render, 6.0, cv::Size(400, 400));
    std::vector<cv::Point2f> centres;
    ASSERT_TRUE(cv::findCirclesGrid(image, cv::Size(g.cols, g.rows), centres, g.flag))
        << TargetTypeName(g.type) << " " << g.cols << "x" << g.rows;
    ASSERT_EQ(centres.size(), points.size());
    // Neighbouring centres are 20 px or more apart.
    EXPECT_LT(LargestOrderError(centres, points, render), 0.05)
        << TargetTypeName(g.type) << " " << g.cols << "x" << g.rows;
  }
}

// Why CheckTarget rejects asymmetric grids with an even number of rows: the 3 × 6 grid maps onto
// itself by a half turn, and findCirclesGrid orders it neither as the calibration sample's object
// points nor in reverse (it returns the rows in pairs from the bottom, each right to left), so
// object points would be paired with the wrong circles.
TEST(TargetOpenCv, EvenRowAsymmetricGridIsMisordered) {
  TargetSpec spec;
  spec.type = TargetType::kAsymmetricCircles;
  spec.cols = 3;
  spec.rows = 6;
  spec.square = 0.02;
  ASSERT_TRUE(CheckTarget(spec).has_value());
  std::vector<ObjectPoint> points;  // calcChessboardCorners' ASYMMETRIC_CIRCLES_GRID formula
  for (int r = 0; r < spec.rows; ++r) {
    for (int c = 0; c < spec.cols; ++c) {
      points.push_back({r * spec.cols + c, Eigen::Vector3d((2 * c + r % 2) * 0.02, r * 0.02, 0)});
    }
  }
  const Render render{1000.0, 40.0};
  std::vector<cv::Point2f> centres;
  ASSERT_TRUE(cv::findCirclesGrid(DrawDiscs(points, render, 6.0, cv::Size(400, 400)),
                                  cv::Size(3, 6), centres, cv::CALIB_CB_ASYMMETRIC_GRID));
  const std::vector<ObjectPoint> reversed(points.rbegin(), points.rend());
  EXPECT_GT(LargestOrderError(centres, points, render), 20.0);  // 20 px: one row or more off
  EXPECT_GT(LargestOrderError(centres, reversed, render), 20.0);
}

TEST(TargetOpenCv, ChessboardOrderMatchesFindChessboardCorners) {
  // Square edges at offset + k·s fall between pixel centres (pixel (u, v) covers u ± 0.5).
  const Render render{1000.0, 80.5};
  for (const auto& [cols, rows] : {std::pair{9, 6}, {6, 9}, {7, 5}, {8, 6}}) {
    TargetSpec spec;
    spec.type = TargetType::kChessboard;
    spec.cols = cols;
    spec.rows = rows;
    spec.square = 0.04;
    const std::vector<ObjectPoint> points = ObjectPoints(spec);
    // (cols + 1) × (rows + 1) squares around the inner corners; the one left of and above
    // corner 0 is black. Pixel centre u lies in square column ⌊(u − offset)/s⌋ + 1.
    cv::Mat image(cv::Size(560, 560), CV_8UC1, cv::Scalar(255));
    const double s = render.scale * spec.square;
    for (int v = 0; v < image.rows; ++v) {
      for (int u = 0; u < image.cols; ++u) {
        const int c = static_cast<int>(std::floor((u - render.offset) / s)) + 1;
        const int r = static_cast<int>(std::floor((v - render.offset) / s)) + 1;
        if (c >= 0 && c <= cols && r >= 0 && r <= rows && (c + r) % 2 == 0) {
          image.at<uchar>(v, u) = 0;
        }
      }
    }
    std::vector<cv::Point2f> corners;
    ASSERT_TRUE(cv::findChessboardCorners(image, cv::Size(cols, rows), corners)) << cols;
    ASSERT_EQ(corners.size(), points.size());
    // Neighbouring corners are 40 px apart: a wrong order would miss by 40 px or more.
    EXPECT_LT(LargestOrderError(corners, points, render), 0.5) << cols << "x" << rows;
  }
}

}  // namespace
}  // namespace hecal::pose
