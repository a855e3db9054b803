// The files an import writes read back through hecal's own readers (pose_table.h, camera_file.h)
// to the poses and intrinsics that went in, in the source's unit, with the '#' lines in the
// documented order.
#include "hecal/io/import_output.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>
#include <string>

#include "hecal/io/camera_file.h"
#include "hecal/io/pose_table.h"

namespace hecal::io {
namespace {

// A 90° turn about z at (1, 2, 3) m, in a table whose unit is millimetres, with one warning.
ImportedPoses Imported() {
  ImportedPoses imported;
  PoseRow row;
  row.pose.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).matrix();
  row.pose.translation() = Eigen::Vector3d(1.0, 2.0, 3.0);
  row.id = "0";
  imported.robot.rows = {row};
  imported.robot.unit = LengthUnit::kMillimetre;
  imported.robot.warnings = {"r.txt: 1 of 1 rotation matrices was projected"};
  imported.robot_notes = {"source: r.txt", "convention: robot inverted"};
  return imported;
}

std::vector<std::string> CommentLines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size() && text[start] == '#') {
    const size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

TEST(ImportOutput, PoseTableReadsBackInTheSourceUnit) {
  const ImportTexts texts = FormatImportedPoses(Imported(), "written by test");
  EXPECT_FALSE(texts.camera);
  EXPECT_FALSE(texts.intrinsics);
  const PoseTable table = ParsePoseTable(texts.robot, "robot.csv", {});
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.unit, LengthUnit::kMillimetre);  // x_mm: the unit named in the header
  EXPECT_TRUE(table.unit_named);
  EXPECT_EQ(*table.rows[0].id, "0");
  EXPECT_TRUE(table.rows[0].pose.isApprox(Imported().robot.rows[0].pose, 1e-12));
  EXPECT_EQ(CommentLines(texts.robot),
            (std::vector<std::string>{"# written by test", "# source: r.txt",
                                      "# convention: robot inverted",
                                      "# note: r.txt: 1 of 1 rotation matrices was projected"}));
}

TEST(ImportOutput, CameraTableAndIntrinsicsWhenImported) {
  ImportedPoses imported = Imported();
  imported.camera = imported.robot;
  imported.camera->warnings.clear();
  imported.camera_notes = {"camera notes"};
  imported.intrinsics =
      ImportedIntrinsics{1000.0, 1001.0, 320.5, 240.25, {0.1, -0.2, 0.001, 0.002, 0.3}, "cali.txt"};
  const ImportTexts texts = FormatImportedPoses(imported, "written by test");
  ASSERT_TRUE(texts.camera);
  EXPECT_EQ(CommentLines(*texts.camera),
            (std::vector<std::string>{"# written by test", "# camera notes"}));
  ASSERT_TRUE(texts.intrinsics);
  const pose::CameraModel camera = ParseCameraFile(*texts.intrinsics, "camera.yaml").camera;
  EXPECT_EQ(camera.fx, 1000.0);
  EXPECT_EQ(camera.fy, 1001.0);
  EXPECT_EQ(camera.cx, 320.5);
  EXPECT_EQ(camera.cy, 240.25);
  EXPECT_EQ(camera.distortion, (std::array<double, 5>{0.1, -0.2, 0.001, 0.002, 0.3}));
  const std::vector<std::string> comments = CommentLines(*texts.intrinsics);
  ASSERT_EQ(comments.size(), 3u);
  EXPECT_EQ(comments[0], "# written by test");
  EXPECT_EQ(comments[1].rfind("# source: cali.txt (", 0), 0u);
}

}  // namespace
}  // namespace hecal::io
