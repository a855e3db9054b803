#include "hecal/pose/target.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <stdexcept>

#include "hecal/core/error.h"
#include "testing/target_specs.h"

namespace hecal::pose {
namespace {

using hecal::testing::Chessboard;
using ::testing::HasSubstr;
using ::testing::Not;

TargetSpec Charuco(int cols, int rows, double square, double marker) {
  TargetSpec spec = Chessboard(cols, rows, square);
  spec.type = TargetType::kCharuco;
  spec.marker = marker;
  spec.dictionary = "DICT_5X5_250";
  return spec;
}

TargetSpec ArucoGrid(int cols, int rows, double marker, double spacing) {
  TargetSpec spec;
  spec.type = TargetType::kArucoGrid;
  spec.cols = cols;
  spec.rows = rows;
  spec.marker = marker;
  spec.spacing = spacing;
  spec.dictionary = "DICT_4X4_250";
  return spec;
}

TargetSpec Tag(TargetType type, int id, double size) {
  TargetSpec spec;
  spec.type = type;
  spec.id = id;
  spec.size = size;
  if (type == TargetType::kAruco) {
    spec.dictionary = "DICT_4X4_50";
  } else {
    spec.family = "tag36h11";
  }
  return spec;
}

// One valid spec of every type.
std::vector<TargetSpec> EveryType() {
  TargetSpec circles = Chessboard(4, 5, 0.02);
  circles.type = TargetType::kCircles;
  TargetSpec acircles = Chessboard(4, 11, 0.02);
  acircles.type = TargetType::kAsymmetricCircles;
  TargetSpec april = ArucoGrid(6, 6, 0.088, 0.0264);
  april.type = TargetType::kAprilTagGrid;
  april.dictionary.clear();
  april.family = "tag36h11";
  return {Chessboard(9, 6, 0.025),
          Charuco(5, 7, 0.028157, 0.0176),
          ArucoGrid(4, 3, 0.0256, 0.0066),
          april,
          circles,
          acircles,
          Tag(TargetType::kAruco, 7, 0.05),
          Tag(TargetType::kAprilTag, 0, 0.08)};
}

TEST(Target, NamesRoundTrip) {
  ASSERT_EQ(TargetTypes().size(), 8u);
  ASSERT_EQ(EveryType().size(), TargetTypes().size());
  for (const TargetType type : TargetTypes()) {
    EXPECT_EQ(ParseTargetType(TargetTypeName(type)), type);
  }
  EXPECT_EQ(TargetTypeName(TargetType::kAsymmetricCircles), "acircles");
  EXPECT_EQ(TargetTypeName(TargetType::kAruco), "aruco");
  EXPECT_EQ(TargetTypeName(TargetType::kAprilTag), "apriltag");
  for (const TargetField field : TargetFields()) {
    EXPECT_FALSE(TargetFieldName(field).empty());
  }
  EXPECT_EQ(TargetFieldName(TargetField::kId), "id");
  EXPECT_EQ(TargetFieldName(TargetField::kSize), "size");
  EXPECT_FALSE(ParseTargetType("Chessboard").has_value());
  EXPECT_FALSE(ParseTargetType("checkerboard").has_value());
}

TEST(Target, IdsAreConsecutiveAndCountMatches) {
  for (const TargetSpec& spec : EveryType()) {
    ASSERT_FALSE(CheckTarget(spec).has_value()) << TargetTypeName(spec.type);
    const std::vector<ObjectPoint> points = ObjectPoints(spec);
    ASSERT_EQ(static_cast<int>(points.size()), PointCount(spec)) << TargetTypeName(spec.type);
    std::set<std::pair<double, double>> distinct;
    for (size_t k = 0; k < points.size(); ++k) {
      EXPECT_EQ(points[k].id, static_cast<int>(k));
      EXPECT_EQ(points[k].position.z(), 0.0);
      if (!IsSingleTag(spec.type)) {  // origin at the top-left: x, y ≥ 0 (a tag's is its centre)
        EXPECT_GE(points[k].position.x(), 0.0);
        EXPECT_GE(points[k].position.y(), 0.0);
      }
      distinct.insert({points[k].position.x(), points[k].position.y()});
    }
    EXPECT_EQ(distinct.size(), points.size()) << TargetTypeName(spec.type);
  }
}

TEST(Target, ChessboardKnownPoints) {
  const std::vector<ObjectPoint> points = ObjectPoints(Chessboard(3, 2, 0.5));
  const double expected[6][2] = {{0, 0}, {0.5, 0}, {1, 0}, {0, 0.5}, {0.5, 0.5}, {1, 0.5}};
  ASSERT_EQ(points.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(points[k].position, Eigen::Vector3d(expected[k][0], expected[k][1], 0)) << k;
  }
}

TEST(Target, AsymmetricCirclesGeometry) {
  TargetSpec spec = Chessboard(4, 11, 0.02);
  spec.type = TargetType::kAsymmetricCircles;
  const std::vector<ObjectPoint> points = ObjectPoints(spec);
  // Every centre's nearest neighbour is √2·square away (the diagonal), neighbours within a row
  // 2·square, rows square apart; odd rows start square to the right.
  for (const ObjectPoint& a : points) {
    double nearest = INFINITY;
    for (const ObjectPoint& b : points) {
      if (a.id != b.id) nearest = std::min(nearest, (a.position - b.position).norm());
    }
    EXPECT_NEAR(nearest, std::sqrt(2.0) * 0.02, 1e-15) << a.id;
  }
  EXPECT_NEAR((points[1].position - points[0].position).norm(), 0.04, 1e-15);
  EXPECT_EQ(points[4].position, Eigen::Vector3d(0.02, 0.02, 0));   // row 1, column 0
  EXPECT_EQ(points[43].position, Eigen::Vector3d(0.12, 0.20, 0));  // row 10, column 3
}

TEST(Target, CharucoCornersAreInnerCornersOfTheSquares) {
  const TargetSpec spec = Charuco(5, 7, 0.03, 0.02);
  const std::vector<ObjectPoint> points = ObjectPoints(spec);
  ASSERT_EQ(points.size(), 24u);     // (5 − 1)·(7 − 1), as the moveit photo's 24 corners
  EXPECT_EQ(MarkerCount(spec), 17);  // 35 squares, 18 black (top-left black), 17 markers
  EXPECT_TRUE(points[0].position.isApprox(Eigen::Vector3d(0.03, 0.03, 0)));
  EXPECT_TRUE(points[3].position.isApprox(Eigen::Vector3d(0.12, 0.03, 0)));  // end of row 0
  EXPECT_TRUE(points[4].position.isApprox(Eigen::Vector3d(0.03, 0.06, 0)));  // start of row 1
  EXPECT_TRUE(points[23].position.isApprox(Eigen::Vector3d(0.12, 0.18, 0)));
}

TEST(Target, GridMarkersAreClockwiseSquares) {
  const TargetSpec spec = ArucoGrid(4, 3, 0.0256, 0.0066);
  const std::vector<ObjectPoint> points = ObjectPoints(spec);
  ASSERT_EQ(points.size(), 48u);
  for (int m = 0; m < 12; ++m) {
    const Eigen::Vector3d* p[4];
    for (int k = 0; k < 4; ++k) p[k] = &points[4 * m + k].position;
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR((*p[(k + 1) % 4] - *p[k]).norm(), 0.0256, 1e-15) << m;
    }
    // Top-left, top-right, bottom-right: x then y increase, and (p1 − p0) × (p2 − p1) is +z
    // (clockwise on the printed side, whose viewer looks along +z).
    EXPECT_GT((*p[1] - *p[0]).x(), 0.0);
    EXPECT_GT((*p[2] - *p[1]).y(), 0.0);
    EXPECT_GT((*p[1] - *p[0]).cross(*p[2] - *p[1]).z(), 0.0);
  }
  // Marker 5 is row 1, column 1: its top-left corner one pitch right and down.
  EXPECT_TRUE(points[20].position.isApprox(Eigen::Vector3d(0.0322, 0.0322, 0)));
  // The board is 4·0.0256 + 3·0.0066 wide and 3·0.0256 + 2·0.0066 = 0.0900 high (the height the
  // moveit SOURCE.md uses to convert to the legacy frame).
  EXPECT_NEAR(points[46].position.x(), 0.1222, 1e-15);
  EXPECT_NEAR(points[46].position.y(), 0.0900, 1e-15);
}

// A single tag: its centre is the origin, x right, y down (libapriltag's tag frame), corners
// clockwise from the top-left as seen on the print, the side `size` apart.
TEST(Target, SingleTagCornersAroundTheCentre) {
  for (const TargetType type : {TargetType::kAruco, TargetType::kAprilTag}) {
    const TargetSpec spec = Tag(type, 3, 0.08);
    EXPECT_TRUE(IsSingleTag(type));
    EXPECT_EQ(MarkerCount(spec), 1);
    EXPECT_EQ(PointCount(spec), 4);
    const std::vector<ObjectPoint> points = ObjectPoints(spec);
    ASSERT_EQ(points.size(), 4u);
    EXPECT_TRUE(points[0].position.isApprox(Eigen::Vector3d(-0.04, -0.04, 0.0)));  // top-left
    EXPECT_TRUE(points[1].position.isApprox(Eigen::Vector3d(0.04, -0.04, 0.0)));   // top-right
    EXPECT_TRUE(points[2].position.isApprox(Eigen::Vector3d(0.04, 0.04, 0.0)));    // bottom-right
    EXPECT_TRUE(points[3].position.isApprox(Eigen::Vector3d(-0.04, 0.04, 0.0)));   // bottom-left
  }
  EXPECT_FALSE(IsSingleTag(TargetType::kAprilTagGrid));
}

TEST(Target, DictionaryTables) {
  ASSERT_EQ(ArucoDictionaries().size(), 21u);
  EXPECT_EQ(ArucoDictionaries()[0].name, "DICT_4X4_50");
  EXPECT_EQ(ArucoDictionaries()[16].name, "DICT_ARUCO_ORIGINAL");
  EXPECT_EQ(ArucoDictionaries()[20].name, "DICT_APRILTAG_36h11");
  ASSERT_EQ(AprilTagFamilies().size(), 9u);
  std::set<std::string_view> families;
  for (const MarkerDictionary& family : AprilTagFamilies()) families.insert(family.name);
  for (const char* name : {"tag36h11", "tag25h9", "tag16h5", "tagCircle21h7", "tagCircle49h12",
                           "tagStandard41h12", "tagStandard52h13", "tagCustom48h12", "tag36h10"}) {
    EXPECT_EQ(families.count(name), 1u) << name;
  }
}

TEST(Target, FieldUse) {
  EXPECT_EQ(TargetFieldUse(TargetType::kChessboard, TargetField::kSquare), FieldUse::kRequired);
  EXPECT_EQ(TargetFieldUse(TargetType::kChessboard, TargetField::kMarker), FieldUse::kUnused);
  EXPECT_EQ(TargetFieldUse(TargetType::kCharuco, TargetField::kDictionary), FieldUse::kRequired);
  EXPECT_EQ(TargetFieldUse(TargetType::kCharuco, TargetField::kFirstId), FieldUse::kUnused);
  EXPECT_EQ(TargetFieldUse(TargetType::kArucoGrid, TargetField::kSquare), FieldUse::kUnused);
  EXPECT_EQ(TargetFieldUse(TargetType::kAprilTagGrid, TargetField::kFamily), FieldUse::kRequired);
  EXPECT_EQ(TargetFieldUse(TargetType::kAprilTagGrid, TargetField::kDictionary), FieldUse::kUnused);
  EXPECT_EQ(TargetFieldUse(TargetType::kAprilTagGrid, TargetField::kFirstId), FieldUse::kOptional);
  EXPECT_EQ(TargetFieldUse(TargetType::kAprilTagGrid, TargetField::kSize), FieldUse::kUnused);
  for (const TargetType tag : {TargetType::kAruco, TargetType::kAprilTag}) {
    EXPECT_EQ(TargetFieldUse(tag, TargetField::kId), FieldUse::kRequired);
    EXPECT_EQ(TargetFieldUse(tag, TargetField::kSize), FieldUse::kRequired);
    EXPECT_EQ(TargetFieldUse(tag, TargetField::kCols), FieldUse::kUnused);
    EXPECT_EQ(TargetFieldUse(tag, TargetField::kMarker), FieldUse::kUnused);
    EXPECT_EQ(TargetFieldUse(tag, TargetField::kFirstId), FieldUse::kUnused);
  }
  EXPECT_EQ(TargetFieldUse(TargetType::kAruco, TargetField::kDictionary), FieldUse::kRequired);
  EXPECT_EQ(TargetFieldUse(TargetType::kAprilTag, TargetField::kFamily), FieldUse::kRequired);
  EXPECT_EQ(TargetFieldUse(TargetType::kAprilTag, TargetField::kDictionary), FieldUse::kUnused);
}

// The field CheckTarget blames and a piece of its message.
void ExpectProblem(const TargetSpec& spec, TargetField field, const std::string& text) {
  const std::optional<TargetProblem> problem = CheckTarget(spec);
  ASSERT_TRUE(problem.has_value()) << text;
  EXPECT_EQ(problem->field, field) << problem->problem;
  EXPECT_THAT(problem->problem, HasSubstr(text));
  EXPECT_FALSE(problem->fix.empty());
  EXPECT_THROW(ObjectPoints(spec), InputError);
}

// A marker grid of one column or one row is one marker per line: the fix names the single-tag
// type of the same family (aruco for aruco_grid, apriltag for apriltag_grid); other counts and
// other types keep the plain "count the ..." fix.
TEST(Target, AGridOfOneMarkerPointsAtTheSingleTagType) {
  const auto fix = [](const TargetSpec& spec) {
    const std::optional<TargetProblem> problem = CheckTarget(spec);
    return problem ? problem->fix : std::string("(accepted)");
  };
  TargetSpec aruco = ArucoGrid(1, 3, 0.05, 0.01);
  EXPECT_THAT(fix(aruco), HasSubstr("for one marker use type: aruco with dictionary, id and size"));
  EXPECT_THAT(fix(aruco), HasSubstr("count the markers along x"));
  ExpectProblem(aruco, TargetField::kCols, "cols is 1");
  TargetSpec april = ArucoGrid(3, 1, 0.05, 0.01);
  april.type = TargetType::kAprilTagGrid;
  april.dictionary.clear();
  april.family = "tag36h11";
  EXPECT_THAT(fix(april), HasSubstr("for one marker use type: apriltag with family, id and size"));
  EXPECT_THAT(fix(april), HasSubstr("count the markers along y"));
  EXPECT_THAT(fix(ArucoGrid(0, 3, 0.05, 0.01)), Not(HasSubstr("for one marker")));
  EXPECT_THAT(fix(Chessboard(1, 6, 0.02)), Not(HasSubstr("for one marker")));
}

TEST(Target, CheckRejectsUnusableSpecs) {
  ExpectProblem(Chessboard(9, 1, 0.02), TargetField::kRows, "rows is 1");
  ExpectProblem(Chessboard(0, 6, 0.02), TargetField::kCols, "cols is 0");
  ExpectProblem(Chessboard(1001, 6, 0.02), TargetField::kCols, "2 to 1000");
  ExpectProblem(Chessboard(9, 6, -0.02), TargetField::kSquare, "positive length");
  ExpectProblem(Chessboard(9, 6, NAN), TargetField::kSquare, "positive length");
  ExpectProblem(Chessboard(9, 6, 0.0), TargetField::kSquare, "positive length");
  ExpectProblem(Charuco(2, 7, 0.03, 0.02), TargetField::kCols, "3 to 1000 squares");
  ExpectProblem(Charuco(5, 7, 0.03, 0.03), TargetField::kMarker, "smaller than the square");
  ExpectProblem(Charuco(5, 7, 0.03, 0.0), TargetField::kMarker, "positive length");

  TargetSpec marker_on_chessboard = Chessboard(9, 6, 0.02);
  marker_on_chessboard.marker = 0.01;
  ExpectProblem(marker_on_chessboard, TargetField::kMarker, "does not apply to chessboard targets");
  TargetSpec first_id_on_charuco = Charuco(5, 7, 0.03, 0.02);
  first_id_on_charuco.first_id = 3;
  ExpectProblem(first_id_on_charuco, TargetField::kFirstId, "does not apply to charuco targets");

  TargetSpec unknown = Charuco(5, 7, 0.03, 0.02);
  unknown.dictionary = "DICT_5X5_256";
  ExpectProblem(unknown, TargetField::kDictionary, "unknown ArUco dictionary 'DICT_5X5_256'");
  TargetSpec missing = Charuco(5, 7, 0.03, 0.02);
  missing.dictionary.clear();
  ExpectProblem(missing, TargetField::kDictionary, "unknown ArUco dictionary ''");

  // 10 × 10 squares carry 50 markers: DICT_4X4_50 has just enough, a 10 × 11 board does not.
  TargetSpec fits = Charuco(10, 10, 0.03, 0.02);
  fits.dictionary = "DICT_4X4_50";
  EXPECT_FALSE(CheckTarget(fits).has_value());
  TargetSpec too_many = Charuco(10, 11, 0.03, 0.02);
  too_many.dictionary = "DICT_4X4_50";
  ExpectProblem(too_many, TargetField::kDictionary, "ids 0 to 54 but DICT_4X4_50 has only 50");
  TargetSpec shifted = ArucoGrid(5, 5, 0.03, 0.01);
  shifted.dictionary = "DICT_4X4_50";
  shifted.first_id = 25;
  EXPECT_FALSE(CheckTarget(shifted).has_value());
  shifted.first_id = 26;
  ExpectProblem(shifted, TargetField::kFirstId, "ids 26 to 50");
  shifted.first_id = -1;
  ExpectProblem(shifted, TargetField::kFirstId, "first_id is -1");

  TargetSpec april = ArucoGrid(6, 6, 0.088, 0.0264);
  april.type = TargetType::kAprilTagGrid;
  april.family = "tag36h11";
  ExpectProblem(april, TargetField::kDictionary, "does not apply to apriltag_grid targets");
  april.dictionary.clear();
  april.family = "tag36H11";
  ExpectProblem(april, TargetField::kFamily, "unknown AprilTag family 'tag36H11'");
  april.family = "tag16h5";  // 36 markers, 30 codes
  ExpectProblem(april, TargetField::kFamily, "has only 30 ids");
  april.family = "tag36h11";
  april.spacing = 0.0;
  ExpectProblem(april, TargetField::kSpacing, "positive length");

  // Single tags: the id must exist in the dictionary / family (DICT_4X4_50: 0..49; tag16h5:
  // 0..29), be non-negative, and the size positive; grid keys do not apply.
  TargetSpec tag = Tag(TargetType::kAruco, 49, 0.05);
  EXPECT_FALSE(CheckTarget(tag).has_value());
  tag.id = 50;
  ExpectProblem(tag, TargetField::kId, "id 50 is not in DICT_4X4_50, whose ids are 0 to 49");
  tag.id = -2;
  ExpectProblem(tag, TargetField::kId, "id is -2");
  tag.id = 1;
  tag.size = 0.0;
  ExpectProblem(tag, TargetField::kSize, "size must be a positive length");
  tag.size = 0.05;
  tag.cols = 2;
  ExpectProblem(tag, TargetField::kCols, "does not apply to aruco targets");
  TargetSpec april_tag = Tag(TargetType::kAprilTag, 30, 0.05);
  april_tag.family = "tag16h5";
  ExpectProblem(april_tag, TargetField::kId, "id 30 is not in tag16h5");
  april_tag.marker = 0.05;
  ExpectProblem(april_tag, TargetField::kMarker, "does not apply to apriltag targets");

  TargetSpec even = Chessboard(4, 10, 0.02);
  even.type = TargetType::kAsymmetricCircles;
  ExpectProblem(even, TargetField::kRows, "even number of rows (10)");
}

}  // namespace
}  // namespace hecal::pose
