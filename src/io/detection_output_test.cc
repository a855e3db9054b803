// The detected-points file against its documented layout (header, quoting, numbers that
// round-trip) and the companion file names against hand-written ones.
#include "hecal/io/detection_output.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace hecal::io {
namespace {

TEST(DetectionOutput, PointsFileLayout) {
  const double u = 0.1 + 0.2;  // 0.30000000000000004: needs 17 digits to round-trip
  const std::string text =
      FormatDetectedPoints({{"im_01", 0, {u, 2.5}}, {"a,b", 47, {-1.0, 1e-7}}});
  const size_t header = text.find("\nid,point_id,u,v\n");
  ASSERT_NE(header, std::string::npos);
  EXPECT_EQ(text[0], '#');
  const std::string rows = text.substr(header + 17);
  const std::string first = rows.substr(0, rows.find('\n'));
  EXPECT_EQ(first.rfind("im_01,0,", 0), 0u) << first;
  const std::string number = first.substr(8, first.find(',', 8) - 8);
  EXPECT_EQ(std::strtod(number.c_str(), nullptr), u);
  EXPECT_EQ(rows.substr(rows.find('\n') + 1, 10), "\"a,b\",47,-") << rows;
}

TEST(DetectionOutput, NoPointsIsTheHeaderOnly) {
  const std::string text = FormatDetectedPoints({});
  EXPECT_EQ(text.substr(text.size() - 16), "id,point_id,u,v\n");
}

TEST(DetectionOutput, CompanionPathsDropTheExtension) {
  EXPECT_EQ(DetectionCompanionPaths("out/det.csv").points, "out/det.points.csv");
  EXPECT_EQ(DetectionCompanionPaths("out/det.csv").camera, "out/det.camera.yaml");
  EXPECT_EQ(DetectionCompanionPaths("det").points, "det.points.csv");
  EXPECT_EQ(DetectionCompanionPaths("a.b/poses").camera, "a.b/poses.camera.yaml");
}

}  // namespace
}  // namespace hecal::io
