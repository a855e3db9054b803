#include "hecal/io/target_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

using pose::TargetType;
using ::testing::HasSubstr;

pose::TargetSpec ParseTarget(const std::string& text) {
  return ParseTargetYaml(text, "target.yaml");
}

// The InputError a text raises.
InputError TargetErrorOf(const std::string& text) {
  SCOPED_TRACE(text);
  return testing::Thrown<InputError>([&] { ParseTarget(text); });
}

void ExpectTargetError(const std::string& text, int line, const std::string& problem) {
  testing::ExpectInputError(TargetErrorOf(text), "target.yaml", line, problem);
}

TEST(TargetFile, Chessboard) {
  const pose::TargetSpec spec = ParseTarget("type: chessboard\ncols: 9\nrows: 6\nsquare: 0.025\n");
  EXPECT_EQ(spec.type, TargetType::kChessboard);
  EXPECT_EQ(spec.cols, 9);
  EXPECT_EQ(spec.rows, 6);
  EXPECT_EQ(spec.square, 0.025);
  EXPECT_EQ(pose::ObjectPoints(spec).size(), 54u);
}

TEST(TargetFile, CharucoInMillimetres) {
  // The moveit board (data/moveit-calibration/SOURCE.md), written in millimetres.
  const pose::TargetSpec spec = ParseTarget(
      "# moveit_calibration test board\n"
      "type: charuco\ncols: 5\nrows: 7\nsquare: 28.157\nmarker: 17.6\n"
      "dictionary: DICT_5X5_250\nunits: mm\n");
  EXPECT_EQ(spec.type, TargetType::kCharuco);
  EXPECT_NEAR(spec.square, 0.028157, 1e-15);
  EXPECT_NEAR(spec.marker, 0.0176, 1e-15);
  EXPECT_EQ(spec.dictionary, "DICT_5X5_250");
  EXPECT_EQ(pose::ObjectPoints(spec).size(), 24u);
}

TEST(TargetFile, ArucoGrid) {
  const pose::TargetSpec spec = ParseTarget(
      "type: aruco_grid\ncols: 4\nrows: 3\nmarker: 0.0256\nspacing: 0.0066\n"
      "dictionary: DICT_4X4_250\n");
  EXPECT_EQ(spec.type, TargetType::kArucoGrid);
  EXPECT_EQ(spec.marker, 0.0256);
  EXPECT_EQ(spec.spacing, 0.0066);
  EXPECT_EQ(spec.first_id, 0);
  EXPECT_EQ(pose::ObjectPoints(spec).size(), 48u);
}

TEST(TargetFile, AprilTagGridWithFirstId) {
  const pose::TargetSpec spec = ParseTarget(
      "{type: apriltag_grid, cols: 6, rows: 6, marker: 0.088, spacing: 0.0264, family: tag36h11, "
      "first_id: 100}");
  EXPECT_EQ(spec.type, TargetType::kAprilTagGrid);
  EXPECT_EQ(spec.family, "tag36h11");
  EXPECT_EQ(spec.first_id, 100);
  EXPECT_EQ(spec.spacing, 0.0264);
}

TEST(TargetFile, SingleTags) {
  const pose::TargetSpec april =
      ParseTarget("type: apriltag\nfamily: tag36h11\nid: 12\nsize: 80\nunits: mm\n");
  EXPECT_EQ(april.type, TargetType::kAprilTag);
  EXPECT_EQ(april.family, "tag36h11");
  EXPECT_EQ(april.id, 12);
  EXPECT_NEAR(april.size, 0.08, 1e-15);
  EXPECT_EQ(pose::ObjectPoints(april).size(), 4u);
  const pose::TargetSpec aruco =
      ParseTarget("{type: aruco, dictionary: DICT_6X6_250, id: 0, size: 0.1}");
  EXPECT_EQ(aruco.type, TargetType::kAruco);
  EXPECT_EQ(aruco.dictionary, "DICT_6X6_250");
  EXPECT_EQ(aruco.id, 0);
  EXPECT_EQ(aruco.size, 0.1);
}

TEST(TargetFile, SingleTagErrors) {
  const std::string april = "type: apriltag\nfamily: tag36h11\n";
  ExpectTargetError(april + "size: 0.08\n", 1, "apriltag targets need 'id' (the id of the tag)");
  ExpectTargetError(april + "id: 3\n", 1, "apriltag targets need 'size'");
  ExpectTargetError(april + "id: 600\nsize: 0.08\n", 3,
                    "id 600 is not in tag36h11, whose ids are 0 to 586");
  ExpectTargetError(april + "id: -1\nsize: 0.08\n", 3, "not a whole number");
  ExpectTargetError("type: aruco\ndictionary: DICT_4X4_50\nid: 2\nsize: 0.05\ncols: 2\n", 5,
                    "'cols' does not apply to aruco targets");
  // The grid's names for the side and the id: the fix says what a single tag calls them.
  const InputError marker = TargetErrorOf(april + "id: 3\nmarker: 0.08\n");
  testing::ExpectInputError(marker, "target.yaml", 4,
                            "'marker' does not apply to apriltag targets");
  EXPECT_THAT(marker.fix(), HasSubstr("apriltag targets call it 'size'"));
  const InputError first_id = TargetErrorOf(april + "first_id: 3\nsize: 0.08\n");
  EXPECT_THAT(first_id.fix(), HasSubstr("call it 'id'"));
  const InputError size = TargetErrorOf(
      "type: apriltag_grid\ncols: 2\nrows: 2\nsize: 0.04\nspacing: 0.01\nfamily: tag36h11\n");
  EXPECT_THAT(size.problem(), HasSubstr("'size' does not apply to apriltag_grid targets"));
  EXPECT_THAT(size.fix(), HasSubstr("call it 'marker'"));
}

// Lengths outside 1 mm ≤ length < 1 m are refused when the unit is the likely mistake: no unit
// and ≥ 1 (millimetres without `units: mm`), or `units: mm` and < 1 mm (metres marked as mm).
// An explicit `units: m` is taken at its word.
TEST(TargetFile, ImplausibleLengthsNameTheUnit) {
  const InputError mm = TargetErrorOf("type: chessboard\ncols: 9\nrows: 6\nsquare: 15\n");
  testing::ExpectInputError(mm, "target.yaml", 4, "square 15 m is not a plausible target square");
  EXPECT_THAT(mm.fix(), HasSubstr("if the lengths are in millimetres add `units: mm`"));
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6\nsquare: 1\n", 4, "square 1 m is not");
  ExpectTargetError("type: apriltag\nfamily: tag36h11\nid: 1\nsize: 80\n", 4,
                    "size 80 m is not a plausible tag size");
  ExpectTargetError(
      "type: aruco_grid\ncols: 4\nrows: 3\nmarker: 0.0256\nspacing: 6.6\n"
      "dictionary: DICT_4X4_250\n",
      5, "spacing 6.6 m is not a plausible target spacing");
  const InputError metres =
      TargetErrorOf("type: chessboard\ncols: 9\nrows: 6\nsquare: 0.015\nunits: mm\n");
  testing::ExpectInputError(metres, "target.yaml", 4,
                            "square 0.015 mm is not a plausible target square: it looks like "
                            "metres");
  EXPECT_THAT(metres.fix(), HasSubstr("remove `units: mm`"));
  // The edges of the range, and explicit units.
  EXPECT_NEAR(ParseTarget("type: chessboard\ncols: 9\nrows: 6\nsquare: 0.999\n").square, 0.999,
              1e-15);
  EXPECT_NEAR(ParseTarget("type: chessboard\ncols: 9\nrows: 6\nsquare: 1\nunits: mm\n").square,
              0.001, 1e-15);
  EXPECT_NEAR(ParseTarget("type: apriltag\nfamily: tag36h11\nid: 1\nsize: 1.2\nunits: m\n").size,
              1.2, 1e-15);
  EXPECT_NEAR(ParseTarget("type: apriltag\nfamily: tag36h11\nid: 1\nsize: 1200\nunits: mm\n").size,
              1.2, 1e-15);
  EXPECT_NEAR(ParseTarget("type: chessboard\ncols: 9\nrows: 6\nsquare: 0.0005\nunits: m\n").square,
              0.0005, 1e-15);
  // A negative length is a sign error, not a unit error, whatever the unit.
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6\nsquare: -15\nunits: mm\n", 4,
                    "positive length");
}

TEST(TargetFile, CircleGrids) {
  const pose::TargetSpec circles = ParseTarget("type: circles\ncols: 4\nrows: 5\nsquare: 0.02\n");
  EXPECT_EQ(circles.type, TargetType::kCircles);
  const pose::TargetSpec acircles =
      ParseTarget("type: acircles\ncols: 4\nrows: 11\nsquare: 20\nunits: mm\n");
  EXPECT_EQ(acircles.type, TargetType::kAsymmetricCircles);
  EXPECT_NEAR(acircles.square, 0.02, 1e-15);
  EXPECT_EQ(pose::ObjectPoints(acircles).size(), 44u);
}

TEST(TargetFile, ReadsAFile) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "hecal_target_file_test.yaml").string();
  WriteFileAtomically(path, "type: chessboard\ncols: 7\nrows: 5\nsquare: 0.03\n");
  EXPECT_EQ(ReadTargetFile(path).cols, 7);
  std::filesystem::remove(path);
  EXPECT_THROW(ReadTargetFile(path), InputError);
}

const std::string kChessboard = "type: chessboard\ncols: 9\nrows: 6\nsquare: 0.025\n";

TEST(TargetFile, StructureErrors) {
  ExpectTargetError("", 0, "empty");
  ExpectTargetError("- chessboard\n- 9\n", 1, "not a map");
  ExpectTargetError("type: chessboard\ncols: [9\n", 3, "not valid YAML");
  ExpectTargetError(kChessboard + "sqaure: 0.02\n", 5,
                    "unknown key \"sqaure\" (did you mean 'square'?)");
  ExpectTargetError(kChessboard + "colour: red\n", 5, "unknown key \"colour\"");
  ExpectTargetError(kChessboard + "? [a, b]\n: 1\n", 5, "a key is not a plain name");
  ExpectTargetError(kChessboard + "rows: 7\n", 5, "key 'rows' is given twice (first on line 3)");
  ExpectTargetError("cols: 9\nrows: 6\nsquare: 0.025\n", 0, "has no 'type'");
  ExpectTargetError("type: checkerboard\ncols: 9\n", 1, "unknown target type \"checkerboard\"");
  ExpectTargetError("type: chesboard\ncols: 9\n", 1, "(did you mean 'chessboard'?)");
  ExpectTargetError("type: [chessboard]\n", 1, "type is not a single value");
  ExpectTargetError(kChessboard + "units: cm\n", 5, "units is \"cm\"");
}

TEST(TargetFile, KeysPerType) {
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6\n", 1, "chessboard targets need 'square'");
  ExpectTargetError("type: charuco\ncols: 5\nrows: 7\nsquare: 0.03\ndictionary: DICT_5X5_250\n", 1,
                    "charuco targets need 'marker'");
  ExpectTargetError("type: aruco_grid\ncols: 4\nrows: 3\nmarker: 0.03\nspacing: 0.01\n", 1,
                    "aruco_grid targets need 'dictionary'");
  ExpectTargetError("type: apriltag_grid\ncols: 4\nrows: 3\nmarker: 0.03\nfamily: tag36h11\n", 1,
                    "apriltag_grid targets need 'spacing'");
  ExpectTargetError(kChessboard + "marker: 0.01\n", 5,
                    "'marker' does not apply to chessboard targets");
  const InputError unused = TargetErrorOf(kChessboard + "dictionary: DICT_5X5_250\n");
  EXPECT_THAT(unused.fix(), HasSubstr("(charuco, aruco_grid, aruco)"));
  ExpectTargetError(
      "type: charuco\ncols: 5\nrows: 7\nsquare: 0.03\nmarker: 0.02\ndictionary: DICT_5X5_250\n"
      "first_id: 4\n",
      7, "'first_id' does not apply to charuco targets");
}

TEST(TargetFile, ValueErrors) {
  ExpectTargetError("type: chessboard\ncols: [9, 6]\nrows: 6\nsquare: 0.02\n", 2,
                    "cols is not a number (found a list)");
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6.5\nsquare: 0.02\n", 3,
                    "not a whole number");
  ExpectTargetError("type: chessboard\ncols: nine\nrows: 6\nsquare: 0.02\n", 2, "not a number");
  ExpectTargetError("type: chessboard\ncols: -9\nrows: 6\nsquare: 0.02\n", 2, "not a whole number");
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 1\nsquare: 0.02\n", 3, "rows is 1");
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 0\nsquare: 0.02\n", 3, "rows is 0");
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6\nsquare: -0.02\n", 4, "positive length");
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6\nsquare: .nan\n", 4, "positive length");
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6\nsquare: 0\n", 4, "positive length");
  ExpectTargetError("type: chessboard\ncols: 9\nrows: 6\nsquare: {a: 1}\n", 4, "found a map");
  ExpectTargetError(
      "type: charuco\ncols: 5\nrows: 7\nsquare: 20\nmarker: 20\ndictionary: DICT_5X5_250\n"
      "units: mm\n",
      5, "the ChArUco marker (0.02 m) must be smaller than the square (0.02 m)");
  ExpectTargetError(
      "type: charuco\ncols: 2\nrows: 7\nsquare: 0.03\nmarker: 0.02\n"
      "dictionary: DICT_5X5_250\n",
      2, "3 to 1000 squares");
  ExpectTargetError(
      "type: charuco\ncols: 5\nrows: 7\nsquare: 0.03\nmarker: 0.02\n"
      "dictionary: DICT_5x5_250\n",
      6, "unknown ArUco dictionary 'DICT_5x5_250' (did you mean 'DICT_5X5_250'?)");
  EXPECT_NO_THROW(
      ParseTarget("type: charuco\ncols: 5\nrows: 7\nsquare: 0.03\nmarker: 0.02\n"
                  "dictionary: DICT_4X4_50\n"));  // 17 markers, 50 ids
  ExpectTargetError(
      "type: apriltag_grid\ncols: 6\nrows: 6\nmarker: 0.088\nspacing: 0.0264\n"
      "family: tag36h12\n",
      6, "unknown AprilTag family 'tag36h12' (did you mean");
  ExpectTargetError(
      "type: apriltag_grid\ncols: 6\nrows: 6\nmarker: 0.088\nspacing: 0.0264\n"
      "family: tag36h11\nfirst_id: 560\n",
      7, "marker ids 560 to 595 but tag36h11 has only 587 ids");
  ExpectTargetError("type: acircles\ncols: 4\nrows: 10\nsquare: 0.02\n", 3, "even number of rows");
}

}  // namespace
}  // namespace hecal::io
