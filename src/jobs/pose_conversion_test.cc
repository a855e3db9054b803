// ConvertPoseTable against hand-computed truths: a 90° turn about z with a 1000 mm offset,
// inverted, is a −90° turn with the offset (0, 1000, 0) mm; the output keeps the input's unit
// unless one is asked for; the written text reads back to the same pose; and the options'
// IsValid names the field.
#include "hecal/jobs/pose_conversion.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "hecal/io/atomic_file.h"
#include "testing/options_validity.h"

namespace hecal::jobs {
namespace {

class PoseConversionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() /
             ("hecal_pose_conversion_" + std::to_string(::getpid()) + ".csv"))
                .string();
    // qw = qz = √½: 90° about z.
    io::WriteFileAtomically(path_,
                            "id,x_mm,y_mm,z_mm,qw,qx,qy,qz\n"
                            "a,1000,0,0,0.70710678118654752,0,0,0.70710678118654752\n");
  }
  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_;
};

TEST_F(PoseConversionTest, InvertsAndKeepsTheUnit) {
  PoseConversionOptions options;
  options.input = path_;
  options.read.invert = true;
  options.to = *io::ParseRotationFormat("euler:ZYX");
  options.degrees = true;
  const PoseConversion result = ConvertPoseTable(options);
  ASSERT_EQ(result.table.rows.size(), 1u);
  const Pose& T = result.table.rows[0].pose;
  EXPECT_NEAR(T.translation().x(), 0.0, 1e-12);
  EXPECT_NEAR(T.translation().y(), 1.0, 1e-12);  // metres inside the table
  EXPECT_NEAR(Eigen::AngleAxisd(T.linear()).angle(), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(T.linear()(1, 0), -1.0, 1e-12);                  // R_z(−90°): x ↦ −y
  EXPECT_EQ(result.write.units, io::LengthUnit::kMillimetre);  // the input's unit
  EXPECT_TRUE(result.write.degrees);
  EXPECT_EQ(result.write.rotation.ToString(), "euler:ZYX");

  // The text reads back to the same pose without any read option.
  const std::string text = FormatPoseTable(result.table, result.write);
  EXPECT_NE(text.find("x_mm"), std::string::npos) << text;
  const io::PoseTable back = io::ParsePoseTable(text, "converted", io::PoseReadOptions{});
  ASSERT_EQ(back.rows.size(), 1u);
  EXPECT_TRUE(back.rows[0].pose.isApprox(T, 1e-12));
}

TEST_F(PoseConversionTest, WritesTheUnitAskedFor) {
  PoseConversionOptions options;
  options.input = path_;
  options.units = io::LengthUnit::kMetre;
  EXPECT_EQ(ConvertPoseTable(options).write.units, io::LengthUnit::kMetre);
}

TEST(PoseConversionOptions, IsValidNamesTheField) {
  PoseConversionOptions options;
  options.input = "poses.csv";
  EXPECT_TRUE(testing::IsValidOptions(options));
  EXPECT_TRUE(testing::RefusesNaming(options, "PoseConversionOptions.input",
                                     [](auto& o) { o.input.clear(); }));
}

}  // namespace
}  // namespace hecal::jobs
